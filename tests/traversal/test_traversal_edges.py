"""Each invariant of a traversal round must be reported by its own name when
a move breaks it (the run stops with the round, the modules and the rule)."""

from __future__ import annotations

from hexbot.planning.traversal.bridges import find_bridge_cells
from hexbot.planning.traversal.cli import resolve_map
from hexbot.planning.traversal.engine import Engine, traverse
from hexbot.planning.traversal.motion import Rolled, rotation_to
from hexbot.planning.traversal.surface import parse_map


def roll(module, goal_side: int, direction: str) -> Rolled:
    """The rotation of ``module`` that ends on ``goal_side`` (Table 4-3)."""
    rotation = rotation_to(goal_side, direction)
    substrate, goal, _swept = rotation.at(module.cell)
    return Rolled(module.cell, goal, substrate, rotation)


def flat_engine():
    # the chain lies on the flat surface at (1, 11) .. (4, 11)
    engine = Engine(find_bridge_cells(resolve_map("flat")))
    assert [m.cell for m in engine.modules] == [(1, 11), (2, 11), (3, 11), (4, 11)]
    return engine


def test_a_roll_about_an_empty_cell_has_no_substrate():
    engine = flat_engine()
    first = engine.modules[0]
    move = roll(first, 1, "CW")  # about (1, 12), above the chain: empty
    assert move.substrate == (1, 12) and not engine.occupied(move.substrate)
    violation = engine.check(1, [(first, move)])
    assert violation is not None
    assert violation.invariant == "no move without a substrate" and violation.modules == [1]


def test_a_module_that_rolls_on_a_moving_one_is_named_for_it():
    engine = flat_engine()
    _, second, third, fourth = engine.modules
    over_third = roll(fourth, 1, "CCW")  # (4, 11) -> (3, 12) about the third module
    assert over_third.substrate == third.cell
    away = roll(third, 1, "CCW")  # the third rolls on, about the second, in the same round
    assert away.substrate == second.cell
    violation = engine.check(1, [(fourth, over_third), (third, away)])
    assert violation is not None
    assert violation.invariant == "a mover never rolls on a moving module"
    assert violation.modules == [4, 3]


def test_two_movers_that_end_side_by_side_break_the_spacing():
    # the second and the fourth start two cells apart and land next to each
    # other, (2, 12) and (3, 12): moving modules are never adjacent
    engine = flat_engine()
    _, second, _, fourth = engine.modules
    a, b = roll(second, 2, "CW"), roll(fourth, 1, "CCW")
    assert (a.dst, b.dst) == ((2, 12), (3, 12))
    violation = engine.check(1, [(second, a), (fourth, b)])
    assert violation is not None
    assert violation.invariant == "moving modules never adjacent"
    assert violation.modules == [2, 4]


NOTCH = """\
. . . . . . . . . . . . . .
. . . . S M M M . . G G G .
S S S S S . S S S S S S S S
S S S S S S S S S S S S S S
"""


def test_a_roll_into_a_notch_sweeps_its_far_wall():
    # The tail module (5, 2) stands between the bump (4, 2) and the chain. Its
    # roll about the bump into the notch (5, 1) would sweep (6, 1), the far
    # wall: the deformable model needs the goal and that side free.
    engine = Engine(find_bridge_cells(parse_map(NOTCH, "notch.txt")))
    tail = engine.modules[0]
    assert tail.cell == (5, 2)
    move = roll(tail, 5, "CW")
    assert (move.substrate, move.dst) == ((4, 2), (5, 1))
    violation = engine.check(1, [(tail, move)])
    assert violation is not None
    assert violation.invariant == "swept cells empty" and "[6, 1] is occupied" in violation.detail


def test_a_module_holding_back_its_start_is_not_a_deadlock():
    # The fourth module defers its start 30 rounds; after the first three are
    # done nothing moves while it waits, yet the run must wait for it (a hold
    # counts as activity), not stop after stall_rounds quiet rounds.
    bmap = find_bridge_cells(resolve_map("flat"))
    plain = Engine(bmap).run()
    held = Engine(bmap, holds=(0, 0, 0, 30), stall_rounds=8).run()
    assert held.status == "reached", held.reason
    assert held.time_steps == plain.time_steps + 30


def test_a_deadlock_is_declared_after_exactly_stall_rounds_quiet_rounds():
    # random:40 with 8 modules: module 8, held 12 rounds, stops on a Bridge
    # cell with nobody behind it to pass (test_traversal_holds): a deadlock
    from hexbot.planning.traversal.bank import random_surface

    bmap = find_bridge_cells(random_surface(40, n=8, width=48, pockets=8), "hexbot")
    result = Engine(bmap, holds=(0, 0, 1, 1, 1, 1, 1, 12), stall_rounds=5).run()
    assert result.status == "deadlock"
    assert result.reason.startswith("no module moved for 5 rounds; waiting: 8:bridge@")


def test_a_module_moving_between_two_pass_cells_counts_as_one_pass():
    # random:82 with 8 modules: next to a neighbouring bridge a Bridge module
    # has two pass cells; a module rolling from one into the other is the same
    # pass. Counted twice, the Bridge module leaves before the last module has
    # passed, and they break an invariant (round 40).
    from hexbot.planning.traversal.bank import random_surface

    bmap = find_bridge_cells(random_surface(82, n=8, width=48, pockets=8))
    result = traverse(bmap)
    assert result.status == "reached", result.reason
    assert set(result.final.values()) == set(bmap.surface.goals)
