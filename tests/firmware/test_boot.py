"""Boot: status texts on the IR port and the debug port, the handshake that
passes the DIP-switch id, joint self-test, and every actuator off."""

from __future__ import annotations

from fwsim import BUILD, QUIET_S, Bench, boot_seconds, build_firmware, scenario_file

from hexbot.protocol import parser

IR_BOOT = [
    ("COMM. BOARD READY", "FW=0.1.0"),
    ("CTR. BOARD READY", "ID=01"),
    ("CTR. LISTENING", ""),
    ("COMM. LISTENING", "ID=01 FW=0.1.0"),
]
DEBUG_BOOT = [
    ("CTR. BOARD READY", "ID=01 FW=0.1.0"),
    ("COMM. BOARD READY", ""),
    ("CTR. LISTENING", ""),
]


def texts(data: bytes) -> list[tuple[str, str]]:
    events = parser.parse_all(data)
    assert not [e for e in events if isinstance(e, parser.Garbage)], events
    return [(e.phrase, e.tail) for e in events if isinstance(e, parser.Text)]


def test_boot_texts_on_ir_and_debug_port(images):
    bench = Bench.boot("single")
    assert bench.drain().startswith(b"\n\r\n\rCOMM. BOARD READY")
    bench = Bench.boot("single")
    assert texts(bench.drain()) == IR_BOOT
    assert texts(bench.debug_read(1)) == DEBUG_BOOT


def test_module_id_comes_from_the_dip_switches(images, tmp_path):
    bench = Bench.boot(scenario_file(tmp_path, [(37, (0, 0), 0)]))
    assert ("COMM. LISTENING", "ID=37 FW=0.1.0") in texts(bench.drain())
    bench.sim.run(0.1)
    assert ("CTR. BOARD READY", "ID=37 FW=0.1.0") in texts(bench.debug_read(37))


def test_version_string_from_make(tmp_path):
    build = build_firmware(tmp_path / "build", version="9.8.7-rc1")
    scenario = scenario_file(tmp_path, [(2, (0, 0), 0)], comm=build / "comm.elf",
                             control=build / "control.elf")
    bench = Bench.boot(scenario, version="9.8.7-rc1")
    found = texts(bench.drain())
    assert ("COMM. BOARD READY", "FW=9.8.7-rc1") in found
    assert ("COMM. LISTENING", "ID=02 FW=9.8.7-rc1") in found


def test_a_booting_cluster_reports_every_id_and_version(images):
    # Seven modules boot at once on one IR medium: each sends the texts that
    # carry its id in its own boot slot, in id order, and none collide.
    bench = Bench.boot("flower7")
    events = parser.parse_all(bench.drain())
    assert not [e for e in events if isinstance(e, parser.Garbage)], events
    found = [(e.phrase, e.tail) for e in events if isinstance(e, parser.Text)]
    assert found[0] == ("COMM. BOARD READY", "FW=0.1.0")  # all at once, identical
    slots = [found[1 + 3 * k: 4 + 3 * k] for k in range(7)]
    assert slots == [[("CTR. BOARD READY", f"ID={i:02d}"), ("CTR. LISTENING", ""),
                      ("COMM. LISTENING", f"ID={i:02d} FW=0.1.0")] for i in range(1, 8)]
    assert len(found) == 22
    # Bytes only overlapped while every module sent the same boot text.
    collided = [e for e in bench.sim.events if e["event"] == "ir-collision"]
    assert collided and max(e["t"] for e in collided) < 1.2, collided[-1]
    # And every module listens once its text is out.
    replies = bench.command("Select", 0, settle=QUIET_S)
    assert [(r.code, r.module) for r in replies] == [(69, i) for i in range(1, 8)]


def test_boot_slots_wrap_after_eight_ids(images, tmp_path):
    # Id 12 sends in slot (12 - 1) mod 8 = 3, from 2.0 + 3 x 2.64 = 9.9 s: a
    # high id does not keep its module silent for 11 slots.
    bench = Bench.boot(scenario_file(tmp_path, [(12, (0, 0), 0)]), boot_s=9.8)
    assert [phrase for phrase, _ in texts(bench.heard)] == ["COMM. BOARD READY"]
    bench.run(boot_seconds([12]) - 9.8)
    assert texts(bench.drain())[1:] == [("CTR. BOARD READY", "ID=12"), ("CTR. LISTENING", ""),
                                        ("COMM. LISTENING", "ID=12 FW=0.1.0")]


def test_joint_self_test_then_everything_off(images):
    from hexbot.hil_sim import Simulator, load_scenario

    sim = Simulator(load_scenario("single"))
    changes: list[tuple[int, int, str, str, int]] = []
    sim.pin_sinks.append(changes.extend)
    sim.run(3.0)
    porta = [(c, v) for c, _m, board, port, v in changes if board == "control" and port == "A"]
    # Each joint J1..J6 (PA2, PA3, PA5, PA4, PA0, PA1) opens alone, 50 ms, in turn.
    opened = [v for _c, v in porta if v]
    assert opened == [1 << 2, 1 << 3, 1 << 5, 1 << 4, 1 << 0, 1 << 1]
    widths = [(porta[i + 1][0] - porta[i][0]) / 1e6 for i in range(0, len(porta) - 1, 2)]
    assert all(0.04 <= w <= 0.06 for w in widths), widths
    sim.run(3.0)
    control = sim.modules[1].control
    assert control.port("A")[1] & 0x3F == 0  # joints closed
    assert control.port("B")[1] & 0xF3 == 0  # magnets off
    assert control.port("D")[1] & 0xFC == 0


def test_comm_board_without_control_board_still_answers(images, tmp_path):
    # The RF12 image never answers the handshake: the comm board gives up after
    # 3 s, reports no control board, and control functions answer '~'.
    scenario = scenario_file(tmp_path, [(1, (0, 0), 0)], control=BUILD / "rf12.elf")
    bench = Bench.boot(scenario, boot_s=9.0)
    found = texts(bench.drain())
    assert ("COMM. BOARD READY", "FW=0.1.0") in found
    assert ("COMM. LISTENING", "ID=00 FW=0.1.0") in found
    assert all(phrase != "CTR. LISTENING" for phrase, _ in found)
    (ack,) = bench.command("JxOpen", 2)
    assert ack.timed_out
    (sta,) = bench.command("Status")
    assert sta.error == 2  # CONTROL_TIMEOUT
    (ack,) = bench.command("LOn")
    assert ack.code == 44


def test_control_board_restart_is_picked_up_by_the_comm_board(single):
    sim = single.sim
    module = sim.modules[1]
    sim.cluster.reset(module.control.index)
    single.run(3.0)
    assert texts(single.debug_read(1)) == DEBUG_BOOT  # it found the comm board again
    (ack,) = single.command("JxOpen", 4)
    assert ack.code == 1
    assert module.control.port("A")[1] & 0x3F == 1 << 4
