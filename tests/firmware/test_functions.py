"""Every function code of Table 3-7 (and our extensions) through the PC's IR
link: the acknowledgement the protocol documents, and what it actually did
to the pins (joints, magnets, LEDs)."""

from __future__ import annotations

import pytest
from fwsim import QUIET_S, Bench, pc_frame, single_ack

from hexbot.hil_sim.module import LED_PINS, decode_actuators
from hexbot.hil_sim.plant import NEG, OFF, POS
from hexbot.protocol import codes, frames, parser
from hexbot.protocol.codes import Board, ErrorCode
from hexbot.protocol.header import SCHEMA_HASH, schema_mismatch


def sample_args(fn: codes.FunctionCode) -> list[int]:
    """Small valid arguments: one repetition, 10 ms delays, joint/side 2."""
    if fn.code == 69:
        return [1]
    values = []
    for arg in fn.args:
        if arg.name.startswith(("t", "st", "mt")):
            values.append(1)
        elif arg.hi == 6 and arg.lo == 1:
            values.append(2)
        else:
            values.append(arg.lo if arg.lo > 0 else max(arg.lo, 0))
    return values


EXECUTABLE = [fn for fn in codes.executable_codes()]
UNUSED = [c for c, fn in codes.CODES.items() if not fn.executable] + [0, 76, 127, 200, 255]


@pytest.mark.parametrize("fn", EXECUTABLE, ids=lambda fn: f"{fn.code}-{fn.name}")
def test_every_function_code_is_acknowledged(single: Bench, fn: codes.FunctionCode):
    args = sample_args(fn)
    replies = single.command(fn.code, *args, timeout=30.0, settle=QUIET_S)
    if fn.code == 66:
        # Alone and not the reference: nobody to hear, the documented error.
        (err,) = replies
        assert isinstance(err, parser.ErrorReply)
        assert (err.code, err.reason) == (66, ErrorCode.NOT_HEARD)
        return
    if fn.code == 70:
        (sta,) = replies
        assert isinstance(sta, parser.StatusReport)
        assert (sta.module_id, sta.role, sta.localized) == (1, "M", False)
        assert sta.schema == SCHEMA_HASH  # built from this protocol
        assert schema_mismatch(sta.schema) is None
        return
    ack = single_ack(replies, fn.code)
    if fn.code == 69:
        assert (ack.role, ack.module) == ("M", 1)  # addressed mode from now on
    elif fn.code == 65:
        assert (ack.role, ack.module) == ("S", None)  # the reference is a substrate
    else:
        assert (ack.role, ack.module) == ("M", None)  # thesis prefix "M: "
    if fn.board is Board.CONTROL:
        # The control board logged what it received on its debug port.
        debug = single.debug_read(1)
        msg = bytes([fn.code, *args, *[78] * (4 - len(args))])
        assert b"ACK" + bytes([fn.code]) + b"\n\rMSG" + msg + b"\n\r" in debug


@pytest.mark.parametrize("code", UNUSED)
def test_unused_codes_answer_ack_n(single: Bench, code: int):
    single_ack(single.frame(pc_frame(code)), ord("N"))


@pytest.mark.parametrize(
    "code,args",
    [(1, [0]), (2, [7]), (11, [0]), (13, [200]), (5, [0, 3]), (21, [7, 1, 1, 1]),
     (25, [7]), (28, [0]), (38, [9]), (50, [3]), (67, [0, 1, 1, 1, 2, 1, 1, 1]),
     (68, [2, 1, 1, 1, 7, 1, 1, 1]), (71, [0]), (71, [3])],
)
def test_out_of_range_arguments_get_err_not_wraparound(single: Bench, code, args):
    (err,) = single.frame(pc_frame(code, *args))
    assert isinstance(err, parser.ErrorReply)
    assert (err.code, err.reason) == (code, ErrorCode.ARG_RANGE)
    assert single.debug_read(1) == b""  # nothing reached the control board
    (sta,) = single.command("Status")
    assert sta.error == ErrorCode.ARG_RANGE
    single_ack(single.command("ClearError"), 72)
    (sta,) = single.command("Status")
    assert sta.error == ErrorCode.NONE




@pytest.mark.parametrize("joint", range(1, 7))
def test_joint_open_close(single: Bench, joint: int):
    single.command("JxOpen", joint)
    joints, _ = single.actuators()
    assert joints == tuple(j == joint for j in range(1, 7))
    single.command("JxClose", joint)
    assert single.actuators()[0] == (False,) * 6


@pytest.mark.parametrize("side", range(1, 7))
def test_magnet_poles_never_both_lines(single: Bench, side: int):
    single.command("SxP", side)
    assert single.actuators()[1] == tuple(POS if s == side else OFF for s in range(1, 7))
    single.command("SxN", side)
    assert single.actuators()[1] == tuple(NEG if s == side else OFF for s in range(1, 7))
    single.command("SxOff", side)
    assert single.actuators()[1] == (OFF,) * 6


def test_turn_off_all(single: Bench):
    single.command("JxOpenAll")
    for side in (1, 4):
        single.command("SxN", side)
    assert any(single.actuators()[0]) and any(single.actuators()[1])
    single_ack(single.command("TurnOffAll"), 20)
    assert single.actuators() == ((False,) * 6, (OFF,) * 6)


def led_on(bench: Bench, name: str) -> bool:
    port, bit = LED_PINS[name]
    return not bench.sim.modules[1].comm.port(port)[1] >> bit & 1  # active low


@pytest.mark.parametrize("side", range(1, 7))
def test_side_and_joint_leds(single: Bench, side: int):
    single.command("SideOnP", side)
    single.command("SideOnN", side)
    single.command("JointOn", side)
    lit = {n for n in LED_PINS if led_on(single, n)}
    assert lit == {f"led_s{side}a", f"led_s{side}b", f"led_j{side}"}
    single.command("LOff")
    assert not any(led_on(single, n) for n in LED_PINS)
    single.command("LOn")
    assert all(led_on(single, n) for n in LED_PINS)


def test_the_simulators_actuator_view_reports_the_leds(single: Bench):
    """What the console's Boards tab shows: SimulatorAccess.actuators() reads
    the LEDs from the pins (active low, outputs only)."""
    single.command("LOff")
    single.command("SideOnN", 4)
    single.command("JointOn", 2)
    out = single.sim.actuators(1)
    assert out["led_neg"] == [0, 0, 0, 1, 0, 0]
    assert out["led_pos"] == [0] * 6
    assert out["led_joints"] == [0, 1, 0, 0, 0, 0]


def record_actuators(bench: Bench, key: str, *args: int) -> list[tuple[float, tuple, tuple]]:
    """Send one command; return (seconds after the first change, joints, magnets)
    for every distinct actuator state the control board went through."""
    changes: list = []
    bench.sim.pin_sinks.append(changes.extend)
    bench.command(key, *args)
    bench.sim.pin_sinks.remove(changes.extend)
    states: list = []
    ports = {"A": 0, "B": 0, "D": 0}
    for cycle, _mod, board, port, value in changes:
        if board != "control" or port not in ports:
            continue
        ports[port] = value
        state = decode_actuators(ports)
        # Port writes a few microseconds apart are one step of the sequence.
        if states and cycle - states[-1][0] < 2000:
            states[-1] = (states[-1][0], *state)
        else:
            states.append((cycle, *state))
    merged = [s for i, s in enumerate(states) if i == 0 or s[1:] != states[i - 1][1:]]
    t0 = merged[0][0]
    return [(round((c - t0) / 1e6, 2), j, m) for c, j, m in merged]


def J(*open_joints: int) -> tuple:
    return tuple(j in open_joints for j in range(1, 7))


def M(**poles: int) -> tuple:
    return tuple(poles.get(f"s{s}", OFF) for s in range(1, 7))


# Table 3-1 / the listing, i = 2, t1 = 80 ms, t2 = 40 ms, t3 = 90 ms.
ROTATIONS = {
    "MCW": [(0.0, J(2, 3), M()), (0.08, J(2, 3), M(s2=NEG, s1=NEG)),
            (0.12, J(), M(s2=NEG, s1=NEG)), (0.21, J(), M())],
    "MCCW": [(0.0, J(3), M()), (0.08, J(3), M(s2=NEG, s1=NEG)),
             (0.12, J(2, 3), M(s2=NEG, s1=NEG)), (0.21, J(), M())],
    "SCW": [(0.0, J(1), M()), (0.08, J(1), M(s5=NEG, s6=POS)),
            (0.12, J(1, 6), M(s5=NEG, s6=POS)), (0.21, J(), M())],
    # The listing drove S(i-5) negative against its own comment and Table 3-1.
    "SCCW": [(0.0, J(5, 4), M()), (0.08, J(5, 4), M(s4=NEG, s3=POS)),
             (0.12, J(), M(s4=NEG, s3=POS)), (0.21, J(), M())],
}


@pytest.mark.parametrize("name", ROTATIONS)
def test_rotation_sequences_and_timing(single: Bench, name: str):
    got = record_actuators(single, name, 2, 8, 4, 9)
    want = ROTATIONS[name]
    assert [(j, m) for _t, j, m in got] == [(j, m) for _t, j, m in want]
    for (t_got, *_), (t_want, *_) in zip(got, want, strict=True):
        assert abs(t_got - t_want) <= 0.011, (got, want)


def test_combined_rotation_runs_the_half_of_the_role(single: Bench):
    args = (3, 1, 1, 1, 5, 1, 1, 1)  # substrate half joint 3, mobile half joint 5
    single_ack(single.command("CW", *args), 67)
    assert b"MSG\x15\x05\x01\x01\x01" in single.debug_read(1)  # mobile: MCW(5, ...)
    single_ack(single.command("SetRole", 2), 71)
    ack = single_ack(single.command("CCW", *args), 68)
    assert ack.role == "S"
    assert b"MSG\x18\x03\x01\x01\x01" in single.debug_read(1)  # substrate: SCCW(3, ...)


def test_substrate_waits_one_second_before_acknowledging(single: Bench):
    def ack_delay() -> float:
        outcome = single.session.exchange(frames.make("LOn"), timeout=5.0)
        assert outcome.ok, outcome.reason
        return outcome.waited - 11 * 10 / 300  # from the end of the frame

    mobile = ack_delay()
    single.command("SetRole", 2)
    substrate = ack_delay()
    assert mobile < 0.5, mobile
    assert 0.98 <= substrate - mobile <= 1.05, (mobile, substrate)


def test_ir_select_acknowledges_on_centre_then_returns_after_silence(single: Bench):
    single_ack(single.command("IrSel", 3), 25)
    assert single.sim.modules[1].channel == 3
    single.drain()
    single.send(frames.encode_pc(frames.make("LOn")))  # unheard: the module listens on side 3
    single.run(2.0)
    assert single.replies() == []
    single.run(10.0)
    assert single.sim.modules[1].channel == 0
    single_ack(single.command("LOn"), 44)


def test_debug_port_drives_the_control_board_directly(single: Bench):
    # Thesis 3.4.5: UART1 of the control board takes commands without the comm board.
    single.debug_write(1, b"*\x01\x03NNN#")
    single.run(0.2)
    assert single.debug_read(1) == b"\n\r\n\rACK\x01\n\rMSG\x01\x03NNN\n\r"
    assert single.actuators()[0] == J(3)
    single.debug_write(1, b"*\x01\x09NNN#")  # joint 9: refused, everything off
    single.run(0.2)
    assert single.debug_read(1).startswith(b"\n\r\n\rACKN\n\r")
    assert single.actuators()[0] == J()
    single.debug_write(1, b"*\x0b\x02NNN#")  # SxP(2)
    single.run(0.05)
    assert single.actuators()[1] == M(s2=POS)
    single.debug_write(1, b"*\x01\x02NN")  # half a frame
    single.run(0.1)  # it times out (30 ms): error path, everything off
    assert single.actuators() == (J(), M())
    assert single.replies() == []  # nothing went to the PC


def test_ref_and_lyref(single: Bench):
    single_ack(single.command("Ref"), 65)
    (sta,) = single.command("Status")
    assert (sta.role, sta.localized, sta.x, sta.y, sta.yref) == ("S", True, 0, 0, 0)
    single.command("LYref", 1)  # the listing turns Yref one step CCW ...
    single.command("LYref", 1)
    single.command("LYref", 2)  # ... and back CW
    (sta,) = single.command("Status")
    assert sta.yref == 1
