"""The RF12 radio: the wireless board's real image on simulated RF12 parts,
bytes through the simulated air (hil_sim/radio.py), in virtual time.

The image's transmit test sends bytes 1..9 (rest 0) every ~0.6 s; its
receive test (mode jumper closed) prints "START", the 16 bytes and 1 (sum
matched) or 0 on its debug port."""

from __future__ import annotations

import subprocess
from pathlib import Path

import pytest
from cluster_double import RadiosDouble

from hexbot.hil_sim import Simulator, load_scenario
from hexbot.hil_sim.radio import RadioMedium
from hexbot.protocol import wire
from hexbot.protocol.pins import RF12_MODE_PIN

ROOT = Path(__file__).resolve().parents[2]
RF12_ELF = ROOT / "firmware" / "build" / "rf12.elf"
PAYLOAD = bytes([1, 2, 3, 4, 5, 6, 7, 8, 9] + [0] * 7)
GOOD_PACKET = wire.TEXT_RF12_RX_START.encode() + PAYLOAD + b"\x01" + wire.EOL


@pytest.fixture(scope="module")
def rf12_image():
    subprocess.run(["make", "-s", "-C", str(ROOT / "firmware"), "all"], check=True,
                   capture_output=True)  # incremental, as tests/firmware do
    return RF12_ELF


def radio_sim(tmp_path: Path, cells: dict[int, tuple[int, int]], receivers: set[int],
              radio_range: int | None = None, seed: int = 1) -> Simulator:
    lines = ['name = "radio"', f"seed = {seed}", f"base = {min(cells)}",
             *([f"radio_range = {radio_range}"] if radio_range is not None else []),
             "[firmware]", f'rf12 = "{RF12_ELF}"']
    for ident, (x, y) in cells.items():
        lines += ["[[module]]", f"id = {ident}", f"position = [{x}, {y}]"]
    path = tmp_path / "radio.toml"
    path.write_text("\n".join(lines) + "\n")
    sim = Simulator(load_scenario(path))
    port, bit = RF12_MODE_PIN
    for ident in receivers:  # jumper closed: receive test
        sim.cluster.set_input(sim.modules[ident].rf12.index, port, 1 << bit, 0)
    return sim


def test_two_modules_exchange_a_packet_end_to_end(rf12_image, tmp_path):
    sim = radio_sim(tmp_path, {1: (0, 0), 2: (1, 0)}, receivers={2})
    sim.run(3.0)
    assert sim.debug_read(1, "rf12").endswith(b"MODE=TX FW=0.1.0\n\r")
    heard = sim.debug_read(2, "rf12")
    assert b"MODE=RX" in heard
    assert heard.count(GOOD_PACKET) >= 2, heard
    assert b"START" not in heard.replace(GOOD_PACKET, b"")  # no bad packet either
    # the wireless board's debug port is its own, not the control board's
    assert b"RF12" not in sim.debug_read(2)


def test_overlapping_transmitters_garble_the_packet(rf12_image, tmp_path):
    # modules 1 and 3 run the same image from the same start: their packets
    # overlap byte for byte at module 2, which hears both
    sim = radio_sim(tmp_path, {1: (-1, 0), 2: (0, 0), 3: (1, 0)}, receivers={2})
    sim.run(3.0)
    heard = sim.debug_read(2, "rf12")
    assert GOOD_PACKET not in heard, heard
    collisions = [e for e in sim.events if e["event"] == "radio-collision"]
    assert collisions and collisions[0]["module"] == 2
    assert sorted(collisions[0]["senders"]) == [1, 3]
    assert sim.radio.garbled > 0


def test_a_transmitter_out_of_range_is_not_heard(rf12_image, tmp_path):
    # range 2 cells: module 3 (3 cells from module 2) cannot jam it, so
    # module 2 hears module 1 clean; module 4 is beyond both
    sim = radio_sim(tmp_path, {1: (-1, 0), 2: (0, 0), 3: (3, 0), 4: (6, 0)},
                    receivers={2, 4}, radio_range=2)
    sim.run(3.0)
    assert sim.debug_read(2, "rf12").count(GOOD_PACKET) >= 2
    assert b"START" not in sim.debug_read(4, "rf12")
    assert not [e for e in sim.events if e["event"] == "radio-collision"]


def test_same_seed_same_trace(rf12_image, tmp_path):
    runs = []
    for _ in range(2):
        sim = radio_sim(tmp_path, {1: (-1, 0), 2: (0, 0), 3: (1, 0)}, receivers={2}, seed=7)
        sim.run(2.0)
        runs.append((sim.debug_read(2, "rf12"), sim.trace()))
    assert runs[0] == runs[1]


# --- the medium's rules, on a double of the core's radio interface -----------


CH = (1, 1600, 71)


def medium(cells: dict[int, tuple[int, int]], range_cells: int = 5):
    radios = RadiosDouble()
    for ident in cells:
        radios.state[ident] = {"receiving": True, "channel": CH}
    events: list = []
    med = RadioMedium(radios, {i: i for i in cells}, cells.__getitem__, range_cells, 1,
                      lambda cycle, e: events.append(e))
    return radios, med, events


def test_receivers_hear_only_their_channel_and_never_a_cut_byte():
    radios, med, _ = medium({1: (0, 0), 2: (1, 0), 3: (2, 0)})
    radios.state[3]["channel"] = (1, 1601, 71)  # 2.5 kHz off: another channel
    radios.logs[1] = [(0, 1670, 0x2D, False, CH), (1670, 2000, 0xD4, True, CH)]
    med.step(2000)
    assert radios.delivered == [(2, 1670, 0x2D)]


@pytest.mark.parametrize(("jammer", "garbled"), [((3, 0), True), ((4, 0), False)])
def test_overlap_garbles_only_if_both_transmitters_reach_the_receiver(jammer, garbled):
    # receiver 2 at (1, 0), range 2: a jammer at (3, 0) reaches it, at (4, 0) not
    radios, med, events = medium({1: (0, 0), 2: (1, 0), 3: jammer}, range_cells=2)
    radios.state[3]["receiving"] = False
    radios.logs[1] = [(0, 1670, 0x55, False, CH)]
    radios.carrier[3] = (1000, 2670, 0x66, False, CH)  # still on the air
    med.step(1670)
    (to, due, value), = radios.delivered
    assert (to, due) == (2, 1670)
    assert (med.garbled == 1) is garbled
    if garbled:
        assert events == [{"event": "radio-collision", "module": 2, "senders": [1, 3]}]
    else:
        assert value == 0x55 and events == []
