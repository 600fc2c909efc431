"""Firmware commands of a plan: body-frame joints, Table 3-1 timings, valid frames."""

from hexbot.planning.commands import (
    TIMINGS,
    body_index,
    global_index,
    move_commands,
    plan_to_commands,
)
from hexbot.planning.configuration import Configuration, Module
from hexbot.planning.moves import Move, magnets
from hexbot.planning.plan import Plan, Step, check_step
from hexbot.protocol.frames import decode_pc, encode_pc


def test_body_index_convention_and_inverse():
    assert [body_index(j, 0) for j in range(1, 7)] == [1, 2, 3, 4, 5, 6]
    assert [body_index(j, 1) for j in range(1, 7)] == [6, 1, 2, 3, 4, 5]
    assert body_index(1, 5) == 2
    for o in range(6):
        for j in range(1, 7):
            assert global_index(body_index(j, o), o) == j


def test_timings_are_table_3_1_in_ticks_and_last_220_ms():
    for (direction, role), (t1, t2, t3) in TIMINGS.items():
        assert t1 == 8
        assert (t1 + t2 + t3) * 10 == 220, (direction, role)
    assert TIMINGS[("CW", "mobile")] == TIMINGS[("CCW", "substrate")]


def test_magnets_of_layer_5_follow_hexactuate():
    # HexActuate: CW joint 1 -> mobile sides 1, 6 negative; substrate +5 -4
    cw = magnets(1, "CW")
    assert cw.mobile_negative == (1, 6)
    assert (cw.substrate_positive, cw.substrate_negative) == (5, 4)
    ccw = magnets(2, "CCW")  # '22': mobile 2 1, substrate a 3 4
    assert ccw.mobile_negative == (2, 1)
    assert (ccw.substrate_positive, ccw.substrate_negative) == (3, 4)


def test_combined_rotation_commands_in_each_module_frame():
    move = Move(7, (0, 0), (-1, 0), joint=1, direction="CW", substrate=(-1, 1), substrate_module=3)
    cmds = move_commands(move, mobile_orientation=2, substrate_orientation=5)
    assert [(c.code, c.args) for c in cmds] == [
        (69, (7,)), (71, (1,)),  # Select(7) SetRole(mobile)
        (69, (3,)), (71, (2,)),  # Select(3) SetRole(substrate)
        (69, (7, 3)),
        (67, (body_index(1, 5), 8, 4, 10, body_index(1, 2), 8, 5, 9)),
    ]
    for c in cmds:
        frame = encode_pc(c)
        assert len(frame) == 11 and frame[0] == ord("*") and frame[-1] == ord("#")
        assert decode_pc(frame) == c


def test_single_role_commands_use_codes_21_to_24():
    move = Move(2, (0, 0), (0, 1), joint=2, direction="CCW", substrate=(-1, 1), substrate_module=1)
    cmds = move_commands(move, 0, 0, style="single")
    assert [c.code for c in cmds] == [69, 24, 69, 22]  # SCCW for the substrate, MCCW for the mobile


def test_plan_to_commands_tracks_orientations_and_roles():
    config = Configuration({(0, 0): Module(1, 0), (1, 0): Module(2, 3)})
    # module 2 rolls clockwise twice around module 1; each CW turns its body by two sides
    first = Move(2, (1, 0), (1, -1), joint=6, direction="CW", substrate=(0, 0), substrate_module=1)
    second = Move(2, (1, -1), (0, -1), 1, "CW", substrate=(0, 0), substrate_module=1)
    plan = Plan("robust", config, frozenset({(0, 0), (0, -1)}), [Step([first]), Step([second])])
    steps = plan_to_commands(plan)
    rot1 = steps[0][0].commands[-1]
    rot2 = steps[1][0].commands[-1]
    assert rot1.args[4] == body_index(6, 3)
    assert rot2.args[4] == body_index(1, 5)  # orientation 3 + 2 after the first CW
    assert rot2.args[0] == 1  # the substrate never turned
    for config_before, step in zip(plan.configurations(), plan.steps, strict=False):
        assert check_step(config_before, step) == []
    assert [c.code for c in steps[1][0].commands] == [69, 67]  # roles already set
    assert plan.final.cells == {(0, 0), (0, -1)}
