"""The real firmware images on the simulated cluster, through the hexbot_sim fixture.

Needs the C extension (``pip install -e .``) and the images (``make -C firmware``).
"""

from pathlib import Path

import pytest

from hexbot.protocol.frames import encode_pc, make, select

THESIS_TIMES = (8, 4, 9)  # Table 3-1: t1 = 80 ms, t2 = 40-45 ms, t3 = 90-95 ms, in 10 ms ticks


def boot(sim, modules=1):
    for _ in sim.modules:  # one per module, each in its boot slot (docs/firmware.md)
        sim.expect(b"COMM. LISTENING", timeout=10)
    sim.run(1.0)
    sim.pc_read()


def send(sim, command, *replies, timeout=10.0):
    """Send a frame and wait for each reply text in turn; return everything up to the last."""
    sim.pc_write(encode_pc(command))
    return b"".join(sim.expect(reply, timeout) for reply in replies)


def setup_pair(sim):
    """Module 1 becomes the substrate (Ref), then both modules are addressed."""
    boot(sim)
    send(sim, select([1]), b"M01: ACKE")
    send(sim, make("Ref"), b"S01: ACKA")
    send(sim, select([1, 2]), b"S01: ACKE", b"M02: ACKE")


def rotate(sim, code, si, mi, times=THESIS_TIMES):
    ack = bytes([ord(code == "CW" and "C" or "D")])
    send(sim, make(code, si, *times, mi, *times), b"S01: ACK" + ack, b"M02: ACK" + ack)
    sim.run(1.0)
    return [e for e in sim.events if e["event"] in ("moved", "refused")]


@pytest.mark.hexbot_scenario("single")
def test_boot_texts_then_ack_for_a_function_code(hexbot_sim):
    text = hexbot_sim.expect(b"COMM. LISTENING", timeout=10)
    assert b"COMM. BOARD READY" in text and b"CTR. BOARD READY ID=01" in text
    hexbot_sim.run(1.0)
    hexbot_sim.pc_read()
    reply = send(hexbot_sim, make("JxOpen", 3), b"ACK\x01\n\r")
    assert b"M: ACK\x01" in reply
    hexbot_sim.run(0.5)
    assert hexbot_sim.actuators(1)["joints"] == [False, False, True, False, False, False]
    assert hexbot_sim.modules[1].control_ports["A"] == 1 << 5  # J3 = PA5
    assert b"MSG\x01\x03NNN" in hexbot_sim.debug_read(1)


@pytest.mark.hexbot_scenario("flower7")
def test_localization_of_flower7(hexbot_sim):
    boot(hexbot_sim)
    send(hexbot_sim, select([1]), b"M01: ACKE")
    send(hexbot_sim, make("Ref"), b"S01: ACKA")
    send(hexbot_sim, select([0]), b"M07: ACKE")
    reports = send(hexbot_sim, make("Localize"), b"M07: ACKB", timeout=60)
    positions = {m.id: m.position for m in hexbot_sim.modules.values()}
    for module_id in range(2, 8):
        x, y = positions[module_id]
        assert f"Pos: {x:+03d}{y:+03d}".encode() in reports, module_id
    # Every module knows where it is: STATUS carries x, y, yref as bytes.
    for module_id in range(1, 8):
        send(hexbot_sim, select([module_id]), f"{module_id:02d}: ACKE".encode())
        send(hexbot_sim, make("Status"), b"STA")
        hexbot_sim.run(0.5)
        body = hexbot_sim.pc_read()
        x, y = positions[module_id]
        assert body[0] == module_id and body[2] == 1  # id, localized
        assert (int.from_bytes(body[3:4], signed=True), int.from_bytes(body[4:5], signed=True),
                body[5]) == (x, y, 0)


@pytest.mark.hexbot_scenario("pair")
def test_thesis_timed_cw_rotation_moves_the_mobile(hexbot_sim):
    setup_pair(hexbot_sim)
    events = rotate(hexbot_sim, "CW", 4, 4)
    assert [e["event"] for e in events] == ["moved"]
    assert events[0]["module"] == 2 and events[0]["to"] == [0, 1]
    assert hexbot_sim.modules[2].position == (0, 1)
    assert hexbot_sim.modules[2].orientation == 2


@pytest.mark.hexbot_scenario("pair")
def test_ccw_rotation_goes_the_other_way(hexbot_sim):
    setup_pair(hexbot_sim)
    events = rotate(hexbot_sim, "CCW", 5, 5)
    assert [(e["event"], e.get("to")) for e in events] == [("moved", [-1, 0])]
    assert hexbot_sim.modules[2].orientation == 4


@pytest.mark.hexbot_scenario("pair")
def test_wrong_joint_index_does_not_move(hexbot_sim):
    setup_pair(hexbot_sim)
    events = rotate(hexbot_sim, "CW", 4, 2)  # the mobile pivots where no substrate is
    assert {e["event"] for e in events} == {"refused"}
    # the mobile's pulse found nobody; the substrate's push found no matching mobile
    assert [(e["reason"], e.get("substrate")) for e in events] == [
        ("no substrate", None), ("wrong polarity", 1)]
    assert hexbot_sim.modules[2].position == (-1, 1)


def test_occupied_goal_cell_does_not_move(hexbot_sim_factory, tmp_path: Path):
    pair = Path(__file__).resolve().parents[2] / "hil_sim" / "scenarios" / "pair.toml"
    blocked = tmp_path / "blocked.toml"
    blocked.write_text(pair.read_text() + "\n[[module]]\nid = 3\nposition = [0, 1]\n")
    sim = hexbot_sim_factory(blocked)
    setup_pair(sim)
    events = rotate(sim, "CW", 4, 4)
    refused = [e for e in events if e.get("module") == 2]
    assert [(e["event"], e["reason"]) for e in refused] == [("refused", "occupied cell")]
    assert refused[0]["cells"] == [[0, 1]]
    assert sim.modules[2].position == (-1, 1)


FAULTY = """
name = "faulty-pair"
seed = 11
base = 1
[faults]
byte_loss = 0.05
bit_error_rate = 0.01
[[module]]
id = 1
position = [0, 0]
[[module]]
id = 2
position = [-1, 1]
"""


def scripted_run(factory, path, seed):
    sim = factory(path, seed)
    sim.run(5.0)
    received = sim.pc_read()
    for command in (select([1]), make("Ref"), select([1, 2]), make("CW", 4, *THESIS_TIMES,
                                                                      4, *THESIS_TIMES)):
        sim.pc_write(encode_pc(command))
        sim.run(3.0)
        received += sim.pc_read()
    return sim.trace(), received


def test_two_runs_give_the_same_trace(hexbot_sim_factory, tmp_path):
    path = tmp_path / "faulty.toml"
    path.write_text(FAULTY)
    first = scripted_run(hexbot_sim_factory, path, 11)
    assert first == scripted_run(hexbot_sim_factory, path, 11)
    assert any(e["event"] == "ir-lost" for e in first[0]["events"])
    assert first != scripted_run(hexbot_sim_factory, path, 12)


def test_a_byte_the_receiver_is_not_enabled_for_is_dropped_and_reported(
        hexbot_sim_factory, tmp_path):
    # The real control image enables UART1 within 2 ms of reset, before a
    # 4800-baud byte can arrive: a control board that never enables it
    # (a test program's spin loop) stands for a receiver that is off.
    import subprocess

    avr = Path(__file__).parent / "avr"
    subprocess.run(["make", "-s", "-C", str(avr), "build/cpuloop.atmega162.elf"], check=True)
    path = tmp_path / "deaf.toml"
    path.write_text('name = "deaf"\n[[module]]\nid = 1\nposition = [0, 0]\n'
                    f'firmware = {{ control = "{avr / "build/cpuloop.atmega162.elf"}" }}\n')
    sim = hexbot_sim_factory(path)
    sim.debug_write(1, b"x")
    sim.run(0.01)
    dropped = [e for e in sim.events if e["event"] == "debug-dropped"]
    assert [(e["module"], e["reason"]) for e in dropped] == [
        (1, "receiver off (RXEN) or overrun")]


@pytest.mark.hexbot_scenario("thesis-fig5-8")
def test_thesis_configuration_localizes_from_module_1(hexbot_sim):
    boot(hexbot_sim)
    send(hexbot_sim, select([1]), b"M01: ACKE")
    send(hexbot_sim, make("Ref"), b"S01: ACKA")
    send(hexbot_sim, select([0]), b"M06: ACKE")
    reports = send(hexbot_sim, make("Localize"), b"M06: ACKB", timeout=90)
    # module 5 at (4, 0) is four hops from the reference
    for module_id in range(2, 7):
        x, y = hexbot_sim.modules[module_id].position
        assert f"Pos: {x:+03d}{y:+03d}".encode() in reports, module_id
