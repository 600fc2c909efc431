"""The host's second link: the PC's radio, a module's wireless board running
the ``rflink`` image, and its comm board behind it, all real images in the
simulator (docs/simulator.md, "The RF12 radio")."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest
import serial

from hexbot.hil_sim import Simulator, load_scenario
from hexbot.hil_sim.urlhandler import register
from hexbot.protocol import frames
from hexbot.protocol.header import schema_hash
from hexbot.protocol.parser import Ack, StatusReport, parse_all
from hexbot.protocol.timing import IRSEL_HOLD_TICKS, TICK_S

ROOT = Path(__file__).resolve().parents[2]
RFLINK = ROOT / "firmware" / "build" / "rflink.elf"
BOOTED_S = 9.0  # module 2's boot texts are over (boot slot 2)
RADIO_URL = "hexbot-sim://pair-radio?speed=0&radio=1"


@pytest.fixture(scope="module", autouse=True)
def images():
    subprocess.run(["make", "-s", "-C", str(ROOT / "firmware"), "all"], check=True,
                   capture_output=True)  # incremental, as tests/firmware do


def far_scenario(tmp_path: Path) -> Path:
    """pair-radio with the PC's radio 6 cells from module 2, range 3."""
    text = (ROOT / "hil_sim" / "scenarios" / "pair-radio.toml").read_text()
    text = text.replace("pc_radio = [0, 0]", "pc_radio = [5, 1]\nradio_range = 3")
    text = text.replace("../../firmware/build/rflink.elf", str(RFLINK))
    path = tmp_path / "far.toml"
    path.write_text(text)
    return path


def radio_exchange(scenario: str | Path, frame: bytes, seconds: float = 3.0
                   ) -> tuple[Simulator, bytes]:
    sim = Simulator(load_scenario(scenario))
    sim.pc_radio_read()  # the PC's radio on the air
    sim.run(BOOTED_S)
    sim.pc_radio_read()
    sim.pc_read()
    sim.pc_radio_write(frame)
    sim.run(seconds)
    return sim, sim.pc_radio_read()


def test_a_command_sent_by_radio_is_executed_and_acknowledged_by_radio():
    sim, heard = radio_exchange("pair-radio", frames.encode_pc(frames.make("JxOpen", 3)))
    assert parse_all(heard) == [Ack(b"", code=1, role="M")], heard
    assert sim.actuators(2)["joints"] == [0, 0, 1, 0, 0, 0]  # J3 open on the control board
    assert sim.actuators(1)["joints"] == [0] * 6  # module 1 has no radio
    assert sim.radio.pc.rx.bad == 0
    # the comm board answered on its centre channel: the PC's IR hears it too
    assert b"ACK\x01" in sim.pc_read()


def test_a_status_reply_longer_than_a_packet_comes_back_whole():
    sim, heard = radio_exchange("pair-radio", frames.encode_pc(frames.make("Status")))
    assert parse_all(heard) == [StatusReport(b"", module_id=2, role="M", prefix_role="M",
                                             schema=int(schema_hash(), 16))], heard
    assert len(heard) > 15 and sim.radio.pc.rx.good >= 2


def test_the_same_seed_gives_the_same_radio_exchange():
    frame = frames.encode_pc(frames.make("JxOpen", 2))
    (a, heard_a), (b, heard_b) = (radio_exchange("pair-radio", frame) for _ in range(2))
    assert heard_a == heard_b and a.trace() == b.trace()


def test_a_module_out_of_radio_range_hears_nothing(tmp_path):
    sim, heard = radio_exchange(far_scenario(tmp_path), frames.encode_pc(frames.make("JxOpen", 3)))
    assert heard == b""
    assert sim.actuators(2)["joints"] == [0] * 6


def hexbot(*argv: str) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "hexbot.cli", *argv, "--no-log"],
                          capture_output=True, text=True, timeout=120)


def test_hexbot_send_over_the_radio_port():
    proc = hexbot("send", "JxOpen", "3", "--module", "2", "--port", RADIO_URL)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    assert "M02 ACK 69 Select" in proc.stdout and "M02 ACK 1 JxOpen" in proc.stdout


def test_hexbot_send_to_a_module_out_of_radio_range_times_out(tmp_path):
    url = f"hexbot-sim://{far_scenario(tmp_path)}?speed=0&radio=1"
    proc = hexbot("send", "JxOpen", "3", "--module", "2", "--port", url)
    assert proc.returncode == 3, proc.stdout + proc.stderr
    assert "no reply from module 2" in proc.stderr.splitlines()[-1]


def test_a_radio_port_needs_a_module_with_a_wireless_board():
    register()
    with pytest.raises(serial.SerialException, match="no module of pair has a wireless board"):
        serial.serial_for_url("hexbot-sim://pair?speed=0&radio=1")
    with pytest.raises(serial.SerialException, match="radio must be 0"):
        serial.serial_for_url("hexbot-sim://pair-radio?speed=0&radio=2")


def ack_after(write, read, frame: bytes) -> float:
    """Simulated seconds from writing ``frame`` after boot to the end of its ACK."""
    sim = Simulator(load_scenario("pair-radio"))
    sim.pc_radio_read()
    sim.run(BOOTED_S)
    read(sim)
    write(sim, frame)
    got = b""
    while not (b"ACK" in got and got.endswith(b"\n\r")):
        sim.run(0.005)
        got += read(sim)
    return sim.time - BOOTED_S


def test_the_radio_adds_about_a_tenth_of_a_second_to_the_ir_round_trip():
    # two packets on the air (42 ms each) and the bridge's quiet time (70 ms)
    frame = frames.encode_pc(frames.make("JxOpen", 3))
    by_ir = ack_after(Simulator.pc_write, Simulator.pc_read, frame)
    by_radio = ack_after(Simulator.pc_radio_write, Simulator.pc_radio_read, frame)
    print(f"ACK by IR {by_ir:.3f} s, by radio {by_radio:.3f} s")
    assert 0.05 < by_radio - by_ir < 0.2


def test_the_radio_reaches_the_comm_board_only_while_its_selector_is_on_the_centre():
    sim, heard = radio_exchange("pair-radio", frames.encode_pc(frames.make("IrSel", 3)))
    assert parse_all(heard) == [Ack(b"", code=25, role="M")]  # answered on the centre
    sim.pc_radio_write(frames.encode_pc(frames.make("JxOpen", 3)))
    sim.run(3.0)  # the selector listens on side 3: the bridge's bytes go nowhere
    assert sim.pc_radio_read() == b""
    assert sim.actuators(2)["joints"] == [0] * 6
    sim.run(IRSEL_HOLD_TICKS * TICK_S)  # silence: back on the centre
    sim.pc_radio_write(frames.encode_pc(frames.make("JxOpen", 3)))
    sim.run(3.0)
    assert parse_all(sim.pc_radio_read()) == [Ack(b"", code=1, role="M")]
    assert sim.actuators(2)["joints"] == [0, 0, 1, 0, 0, 0]
