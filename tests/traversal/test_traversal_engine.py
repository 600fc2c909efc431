"""MOVEMODULE in synchronous rounds: every bank map is crossed with bridges,
narrow pockets break invariants without them, the paper's measurements."""

from __future__ import annotations

import pytest

from hexbot.planning.traversal.bank import MAPS
from hexbot.planning.traversal.bridges import find_bridge_cells
from hexbot.planning.traversal.cli import resolve_map
from hexbot.planning.traversal.engine import Engine, traverse
from hexbot.planning.traversal.experiments import pocket_sweep, single_effect
from hexbot.planning.traversal.motion import Rolled, rotation_to

BANK = sorted(p.stem for p in MAPS.glob("*.txt"))


@pytest.mark.parametrize("name", BANK)
def test_every_bank_map_is_crossed_with_bridges(name):
    surface = resolve_map(name)
    result = traverse(find_bridge_cells(surface))
    assert result.status == "reached", result.reason
    assert set(result.final.values()) == set(surface.goals)


def test_a_narrow_pocket_without_bridges_stops_with_round_modules_and_rule():
    result = traverse(find_bridge_cells(resolve_map("basic-5"), bridges=False))
    assert result.status == "violation"
    v = result.violation
    assert v.round == len(result.rounds) + 1 and len(v.modules) == 2
    assert v.invariant in ("moving modules never adjacent", "swept cells empty")
    assert v.rules == ["roll", "roll"]


def test_bridge_modules_wait_then_leave_last_and_goals_fill_from_the_far_end():
    bmap = find_bridge_cells(resolve_map("left-5"))
    result = traverse(bmap)
    rules = [m.rule for moves in result.rounds for m in moves]
    for rule in ("start", "roll", "leave-bridge", "leave-support"):
        assert rule in rules
    goal_order = [c for c in bmap.layer1.cells if c in bmap.surface.goals]
    arrivals = [m.dst for moves in result.rounds for m in moves if m.dst in goal_order]
    assert arrivals[-1] == goal_order[0]  # the last module stops in the nearest goal


def test_the_invariant_check_refuses_a_move_into_an_occupied_cell():
    engine = Engine(find_bridge_cells(resolve_map("flat")))
    first, second = engine.modules[0], engine.modules[1]
    rotation = rotation_to(3, "CW")
    sub, goal, _ = rotation.at(first.cell)
    bad = Rolled(first.cell, second.cell, sub, rotation)
    violation = engine.check(1, [(first, bad)])
    assert violation is not None and violation.invariant in ("one module per cell",
                                                             "swept cells empty")


def test_fig12_13_three_bridge_keeps_time_and_moves_constant():
    rows = pocket_sweep(depths=(2, 4, 6, 8))
    assert all(r["with"]["status"] == r["without"]["status"] == r["small"]["status"]
               == "reached" for r in rows)
    assert len({r["with"]["time_steps"] for r in rows}) == 1
    assert len({r["with"]["moves"] for r in rows}) == 1
    without_time = [r["without"]["time_steps"] for r in rows]
    without_moves = [r["without"]["moves"] for r in rows]
    assert without_time == sorted(without_time) and without_time[-1] > rows[-1]["with"][
        "time_steps"]
    assert without_moves == sorted(without_moves) and without_moves[0] > rows[0]["with"]["moves"]


def test_single_bridge_adds_two_time_steps_and_saves_n_minus_1_moves():
    for row in single_effect(ns=(3, 5, 7)):
        assert row["status"] == ["reached", "reached"]
        assert row["extra_time"] == 2
        assert row["saved_moves"] == row["n"] - 1


def test_same_map_same_rounds():
    a = traverse(find_bridge_cells(resolve_map("fig14")))
    b = traverse(find_bridge_cells(resolve_map("fig14")))
    assert [[m.as_json() for m in r] for r in a.rounds] == [[m.as_json() for m in r]
                                                          for r in b.rounds]


@pytest.mark.parametrize(("name", "fills", "paper_kind"),
                         [("flat", 0, None), ("basic-2", 2, "BASIC"),
                          ("three-deep2", 3, "THREE"), ("three-deep4", 3, "THREE"),
                          ("three-deep8", 3, "THREE"), ("three-deep2-n5", 3, "THREE"),
                          ("three-curved-left", 3, "THREE"),
                          ("three-curved-right", 2, "THREE"),
                          ("three-curved-symmetric", 2, "THREE"),
                          ("fig14-n13", 12, None)])
def test_hexbot_motion_crosses_pockets_with_fill_cells(name, fills, paper_kind):
    bmap = find_bridge_cells(resolve_map(name), "hexbot")
    assert len(bmap.fills) == fills
    if paper_kind:  # the pocket the paper closes with a 2- or 3-bridge
        paper = find_bridge_cells(resolve_map(name))
        assert [g.kind for g in paper.groups] == [paper_kind]
    result = traverse(bmap)  # every invariant is checked each round
    assert result.status == "reached", result.reason
    # the first modules stay in Fill cells; the others end on the last goals
    held = [c for c in result.final.values() if c in bmap.fills]
    at_goal = [c for c in result.final.values() if c in bmap.surface.goals]
    assert len(held) + len(at_goal) == bmap.surface.n and len(at_goal) >= bmap.crossing
    goals = [c for c in bmap.layer1.cells if c in bmap.surface.goals]
    assert set(at_goal) == set(goals[len(goals) - len(at_goal):])


def test_hexbot_motion_refuses_a_step_rigid_modules_cannot_descend():
    from hexbot.errors import ScenarioError

    with pytest.raises(ScenarioError, match="cannot be crossed by rigid modules"):
        find_bridge_cells(resolve_map("steps"), "hexbot")


def test_hexbot_motion_refuses_fig14_whose_pockets_would_hold_12_of_11_modules():
    from hexbot.errors import ScenarioError

    with pytest.raises(ScenarioError, match="the Fill cells that let the walk on hold 12 "
                       "modules, more than the 10 of 11 that may stay"):
        find_bridge_cells(resolve_map("fig14"), "hexbot")


def test_fig12_time_crossover_lies_past_a_pocket_perimeter_of_10_as_in_the_paper():
    # "for pocket perimeter lengths greater than 10, the traversal time saved ...
    # outweighs the cost of detaining modules in the bridge cells"
    from hexbot.planning.traversal.experiments import crossover

    rows = pocket_sweep()
    for r in rows:
        if r["pocket"] < 9:
            assert r["with"]["time_steps"] > r["without"]["time_steps"], r
        if r["pocket"] > 10:
            assert r["with"]["time_steps"] < r["without"]["time_steps"], r
    assert 9 <= crossover(rows) <= 11


def test_the_foot_of_a_two_high_drop_cannot_be_entered_by_a_hexbot_rotation():
    # steps: the wall drops two rows onto a flat floor at x = 21; the foot cell
    # has four occupied neighbours in a row, and every Table 4-3 rotation into
    # it sweeps a surface cell (docs/traversal.md: why steps is refused)
    from hexbot.planning.traversal.motion import required_empty
    from hexbot.protocol.lattice import SIDES, neighbor
    from hexbot.protocol.rotation_geometry import ROTATIONS

    surface = resolve_map("steps").surface
    foot = (21, 11)
    assert foot not in surface and (21, 12) not in surface
    assert [neighbor(foot, s) in surface for s in SIDES] == [True, False, False, True, True,
                                                             True]
    for side in SIDES:
        src = neighbor(foot, side)
        if src in surface:
            continue
        for rotation in ROTATIONS:
            sub, goal, _ = rotation.at(src)
            if goal == foot and sub in surface:
                assert any(c in surface for c in required_empty(rotation, src, "hexbot"))
