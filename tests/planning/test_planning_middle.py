"""The middle-ball detour: initial -> compact ball -> goal, legal or a clear failure."""

import random

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from hexbot.planning.canonical import replay
from hexbot.planning.configuration import Configuration, is_connected
from hexbot.planning.generate import random_blob
from hexbot.planning.hexlattice import distance
from hexbot.planning.middle import _via, ball, middles, ring, via_middle
from hexbot.planning.plan import Step, check_step
from hexbot.planning.robust import (
    PlanningFailure,
    direct_budget,
    fillable,
    is_immobile,
    plan_robust,
)
from tests.planning.test_planning_robust import assert_legal


def apart_pair(size: int, seed: int) -> tuple[frozenset, frozenset]:
    a, b = random_blob(size, 2 * seed, 0.8), random_blob(size, 2 * seed + 1, 0.8)
    dx = max(x for x, _ in a) - min(x for x, _ in b) + 2
    return a, frozenset((x + dx, y) for x, y in b)


@pytest.mark.parametrize("count", [1, 2, 7, 8, 19, 20, 30, 61])
def test_ball_is_full_rings_then_one_arc(count):
    cells = ball((3, -2), count)
    assert len(cells) == count and (3, -2) in cells and is_connected(cells)
    radius = max(distance(c, (3, -2)) for c in cells)
    # every inner ring is complete: no notch for the direct method to wall in
    assert all(c in cells for r in range(radius) for c in ring((3, -2), r))
    # and every cell of it can be entered in some order (peeled from outside in)
    assert not fillable(cells, set(cells) - {(3, -2)})
    if count > 2:
        assert not is_immobile(cells)


def test_ring_is_a_closed_walk_of_neighbours():
    cells = ring((0, 0), 3)
    assert len(cells) == len(set(cells)) == 18
    assert all(distance(cells[i], cells[i - 1]) == 1 for i in range(18))


@pytest.mark.parametrize("seed", range(5))
def test_pairs_apart_stay_short_through_the_local_method_or_the_middle_ball(seed):
    a, b = apart_pair(10, seed)
    plan = plan_robust(Configuration.from_cells(a), b)
    assert plan.reached, plan.reason
    assert plan.method in ("local", "middle ball")
    assert_legal(plan)
    assert plan.final.cells == b
    # the strip route took 4.4-5.7x the distance bound on these pairs
    assert plan.move_count < 2.5 * plan.lower_bound
    # the middle ball alone plans them short too (the local method comes first now)
    start = Configuration.from_cells(a)
    serial = via_middle(start, b, 10**6)
    assert replay(start, serial).cells == b
    assert len(serial) < 2.5 * plan.lower_bound


def test_middle_ball_lies_between_both_configurations():
    a, b = apart_pair(30, 0)
    first = middles(a, b)[0]
    cx = sum(x for x, _ in first) / len(first)
    assert max(x for x, _ in a) - 10 < cx < min(x for x, _ in b) + 10


def test_fixed_module_outside_every_ball_is_a_planning_failure():
    a = frozenset((x, 0) for x in range(10))
    b = frozenset([(0, 0)] + [(x, 1) for x in range(9)])
    assert all((0, 0) not in shape for shape in middles(a, b))  # a ball would move it
    with pytest.raises(PlanningFailure, match=r"fixed module at \(0, 0\)"):
        via_middle(Configuration.from_cells(a), b, 10**6, fixed=(0, 0))


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(size=st.integers(3, 16), seed_a=st.integers(0, 10**6), seed_b=st.integers(0, 10**6))
def test_middle_route_is_legal_move_by_move_or_fails_cleanly(size, seed_a, seed_b):
    a = random_blob(size, seed_a, compact=random.Random(seed_a).random())
    b = random_blob(size, seed_b, compact=0.6)
    config = Configuration.from_cells(a)
    try:
        moves = via_middle(config, b, 10**5, budget=20)
    except PlanningFailure:
        return
    for move in moves:  # Table 4-3, swept cells empty, substrate still, connected
        assert check_step(config, Step([move])) == []
        config = replay(config, [move])
        assert is_connected(config.cells)
    assert config.cells == b


def test_small_pair_the_centred_ball_misses_goes_through_a_nudged_ball():
    # scan pair 24 of `hexbot bench planning --scan` (25 modules)
    a = random_blob(25, 401458, compact=random.Random(401458).random())
    b = random_blob(25, 880593, compact=0.6)
    with pytest.raises(PlanningFailure):
        _via(Configuration.from_cells(a), b, middles(a, b)[0], 10**6, None, direct_budget(25))
    start = Configuration.from_cells(a)
    assert replay(start, via_middle(start, b, 10**6, budget=direct_budget(25))).cells == b
    plan = plan_robust(start, b)  # the local method now plans it before the middle ball
    assert plan.reached and plan.method in ("local", "middle ball")
    assert_legal(plan)
    assert plan.final.cells == b
