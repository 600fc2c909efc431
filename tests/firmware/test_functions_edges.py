"""Function edges that no test reached (firmware mutation audit, session 32):
IrSel's hold counts from the move, a corrupted board frame switches every
actuator off, rotation sequences wrap around the hexagon."""

from __future__ import annotations

import pytest
from fwsim import Bench, pc_frame

from hexbot.hil_sim.plant import OFF
from hexbot.protocol import frames, parser


def test_ir_select_holds_the_side_ten_seconds_after_its_late_ack(single: Bench):
    # Module 1 seventh in the Select list: its ACK of IrSel waits six slots
    # (3.6 s), and only then does the selector move. The 10 s of silence
    # that bring it back to the centre count from there (docs/firmware.md).
    single.drain()
    single.send(pc_frame(69, 2, 3, 4, 5, 6, 7, 1))
    single.run(5.0)
    assert [(r.code, r.module) for r in single.replies()] == [(69, 1)]
    single.drain()
    mark = single.send(frames.encode_pc(frames.make("IrSel", 3)))
    acked = single.session.wait_for(
        lambda o: isinstance(o.event, parser.Ack) and o.event.code == 25, mark, 6.0)
    assert acked is not None
    single.run(0.1)
    assert single.sim.modules[1].channel == 3
    single.run(9.0)  # 9.1 s after the move: still listening on side 3
    assert single.sim.modules[1].channel == 3
    single.run(1.5)
    assert single.sim.modules[1].channel == 0


def test_a_corrupted_board_frame_switches_every_actuator_off(single: Bench):
    # docs: every error path of the control board switches everything off;
    # a frame whose seventh byte is not '#' is one (not only a half frame
    # that times out).
    single.debug_write(1, b"*\x0b\x02NNN#*\x01\x04NNN#")  # SxP(2), JxOpen(4)
    single.run(0.1)
    joints, magnets = single.actuators()
    assert joints[3] and magnets[1] != OFF
    single.debug_write(1, b"*\x01\x05NNNX")  # seven bytes, no '#' at the end
    single.run(0.1)
    joints, magnets = single.actuators()
    assert not any(joints) and all(m == OFF for m in magnets), (joints, magnets)


# Table 3-1 about joint 6, where the offsets wrap past joint 6 to joint 1
# (i + 1 = 7 is joint 1); t1 = 80 ms, t2 = 40 ms, t3 = 90 ms.
def _rotations_about_6():
    from test_functions import J, M

    from hexbot.hil_sim.plant import NEG, POS
    return {
        "MCW": [J(6, 1), M(s6=NEG, s5=NEG), J(), M()],
        "MCCW": [J(1), M(s6=NEG, s5=NEG), J(1, 6), M()],
        "SCW": [J(5), M(s3=NEG, s4=POS), J(5, 4), M()],
        "SCCW": [J(3, 2), M(s2=NEG, s1=POS), J(), M()],
    }


@pytest.mark.parametrize("name", ["MCW", "MCCW", "SCW", "SCCW"])
def test_rotation_sequences_wrap_around_the_hexagon(single: Bench, name: str):
    from test_functions import J, M, record_actuators

    j1, m1, j2, _ = _rotations_about_6()[name]
    want = [(j1, M()), (j1, m1), (j2, m1), (J(), M())]
    got = record_actuators(single, name, 6, 8, 4, 9)
    assert [(j, m) for _t, j, m in got] == want, got
