"""Dropping round trips from serial plans, checked by the independent checker."""

import random

import pytest
from test_planning_journey import INLET

from hexbot.bench.planning import make_pair
from hexbot.planning import tidy as tidy_module
from hexbot.planning.budget import Deadline
from hexbot.planning.canonical import replay
from hexbot.planning.checker import check_plan
from hexbot.planning.configuration import Configuration
from hexbot.planning.generate import random_blob
from hexbot.planning.journey import journey, journey_flow
from hexbot.planning.local import forward
from hexbot.planning.moves import Move
from hexbot.planning.robust import _moves_from, is_cut, pack_consecutive, plan_robust, reverse_move
from hexbot.planning.tidy import shorten
from hexbot.planning.tracker import Tracker
from tests.planning.tidy_reference import reference_pass, reference_shorten


def checked(initial: Configuration, goal, serial, fixed=None):
    report = check_plan(initial, goal, pack_consecutive(initial, serial), fixed=fixed)
    assert report.ok, report.problem


def test_a_pointless_trip_is_dropped_and_the_plan_still_reaches_the_goal():
    shape = INLET | {(2, -2)}
    start = Configuration.from_cells(shape)
    tracker = Tracker(start, 100)
    tracker.roll(journey(shape, (2, -2), (-2, 1)))
    plan = list(tracker.moves)
    goal = replay(start, plan).cells
    # another module steps off and back before the journey starts
    there = next(
        Move(start[c].id, c, dst, rule.joint, rule.direction, sub, start[sub].id)
        for c in sorted(shape) if c != (2, -2) and not is_cut(set(shape), c)
        for rule, sub, dst in _moves_from(c, set(shape), c))
    there, back = [there], [reverse_move(there)]
    padded = there + back + plan
    checked(start, goal, padded)
    tidy = shorten(start, padded)
    checked(start, goal, tidy)
    # the detour is gone (and the crossing's search, which accepts a state as
    # soon as it is generated, had left a trip of its own)
    assert len(tidy) <= len(plan) < len(padded)


def test_a_helper_stepping_aside_for_a_crossing_is_kept():
    # the mouth crossing needs the wall modules to step aside and come back:
    # those are round trips, and without them the traveller cannot pass
    shape = INLET | {(2, -2)}
    start = Configuration.from_cells(shape)
    tracker = Tracker(start, 100)
    tracker.roll(journey(shape, (2, -2), (-2, 1)))
    helpers = {m.module for m in tracker.moves} - {tracker.moves[0].module}
    assert helpers  # the crossing moved wall modules
    tidy = shorten(start, tracker.moves)
    checked(start, replay(start, tracker.moves).cells, tidy)
    assert helpers & {m.module for m in tidy}


@pytest.mark.parametrize("seed", range(3))
def test_journey_plans_of_100_lose_moves_and_stay_legal(seed):
    a, b = make_pair("scramble", 100, seed)
    start = Configuration.from_cells(a)
    serial = forward(start, b, journey_flow, 10**6, None, Deadline(None), "local")
    tidy = shorten(start, serial)
    checked(start, b, tidy)
    # measured: 2-20 % fewer on these pairs (docs/planning.md)
    assert len(tidy) < len(serial)


def test_the_fixed_module_stays_fixed_after_tidying():
    a, b = make_pair("scramble", 100, 1)
    start = Configuration.from_cells(a)
    serial = forward(start, b, journey_flow, 10**6, (0, 0), Deadline(None), "local")
    tidy = shorten(start, serial)
    assert all(m.src != (0, 0) for m in tidy)
    checked(start, b, tidy, fixed=(0, 0))


def test_plan_robust_tidies_its_plans(monkeypatch):
    a, b = make_pair("scramble", 100, 2)
    start = Configuration.from_cells(a)
    plan = plan_robust(start, b)
    assert plan.reached, plan.reason
    report = check_plan(start, b, plan.steps)
    assert report.ok, report.problem
    monkeypatch.setattr("hexbot.planning.tidy.shorten", lambda i, moves, d=None: moves)
    # regroup tidies between its passes: untidied means without it too
    monkeypatch.setattr("hexbot.planning.regroup.regroup", lambda i, moves, f=None, d=None: moves)
    untidy = plan_robust(start, b)
    assert plan.method == untidy.method == "local"
    assert plan.move_count < untidy.move_count


# The pass runs in C (planning/_tidy.c) since session 18; the Python pass it
# replaced is tests/planning/tidy_reference.py. They must make the same plans.

def _untidy_flow_plan(family: str, n: int, seed: int, fixed=None):
    a, b = make_pair(family, n, seed)
    start = Configuration.from_cells(a)
    return start, b, forward(start, b, journey_flow, 10**6, fixed, Deadline(None), "local")


@pytest.mark.parametrize("window", [1_000, 40, 3])
@pytest.mark.parametrize("pair", [("blob", 100, 0), ("blob", 100, 1), ("scramble", 100, 1)])
def test_the_c_pass_makes_the_python_passs_plan(pair, window, monkeypatch):
    monkeypatch.setattr(tidy_module, "WINDOW", window)
    start, goal, serial = _untidy_flow_plan(*pair)
    ours, theirs = serial, serial
    for _ in range(tidy_module.PASSES):
        ours = tidy_module.one_pass(start, ours)
        theirs = reference_pass(start, list(theirs), Deadline(None))
        assert ours == theirs
    if window > 3:  # the comparison saw shortcuts taken (3 moves ahead may find none)
        assert len(ours) < len(serial)
    checked(start, goal, ours)


def test_the_c_pass_makes_the_python_passs_plan_with_the_fixed_module():
    start, goal, serial = _untidy_flow_plan("scramble", 100, 1, fixed=(0, 0))
    ours = shorten(start, serial)
    assert ours == reference_shorten(start, serial)
    assert all(m.src != (0, 0) for m in ours)
    checked(start, goal, ours, fixed=(0, 0))


class _Countdown:
    """A deadline that expires after ``looks`` looks (a test double: the pass
    asks ``expired()`` every ``DEADLINE_EVERY`` moves)."""

    def __init__(self, looks: int) -> None:
        self.looks = looks

    def expired(self) -> bool:
        self.looks -= 1
        return self.looks < 0


@pytest.mark.parametrize("looks", [0, 3])
def test_the_c_pass_stops_where_the_python_pass_stops_at_the_deadline(looks):
    start, goal, serial = _untidy_flow_plan("blob", 100, 0)
    ours = tidy_module.one_pass(start, serial, _Countdown(looks))
    theirs = reference_pass(start, list(serial), _Countdown(looks))
    assert ours == theirs
    if looks == 0:
        assert ours == serial  # stopped before the first move: nothing changed
    else:
        assert ours != serial and ours != tidy_module.one_pass(start, serial)


def test_the_c_pass_refuses_a_move_that_no_rotation_makes():
    start, goal, serial = _untidy_flow_plan("blob", 100, 0)
    bad = serial[0]
    wrong_joint = Move(bad.module, bad.src, bad.dst, 9, bad.direction, bad.substrate,
                       bad.substrate_module)
    with pytest.raises(ValueError, match="no rotation about joint 9"):
        shorten(start, [wrong_joint, *serial[1:]])
    x, y = bad.substrate
    elsewhere = Move(bad.module, bad.src, bad.dst, bad.joint, bad.direction, (x + 1, y),
                     bad.substrate_module)
    with pytest.raises(ValueError, match="substrate is not its rotation's"):
        shorten(start, [elsewhere, *serial[1:]])
    stranger = Move(10**6, bad.src, bad.dst, bad.joint, bad.direction, bad.substrate,
                    bad.substrate_module)
    with pytest.raises(ValueError, match="a module the initial configuration does not have"):
        shorten(start, [stranger, *serial[1:]])


def test_plans_of_more_than_3000_moves_are_tidied(monkeypatch):
    # until session 18 the Python pass left plans of more than 3,000 moves
    # untidied: the blobs of 1,000 (measured: 4,483 -> 3,418 moves on this pair)
    a, b = make_pair("blob", 1000, 2)
    start = Configuration.from_cells(a)
    plan = plan_robust(start, b)
    assert plan.reached and plan.method == "local", plan.reason
    report = check_plan(start, b, plan.steps)
    assert report.ok, report.problem
    monkeypatch.setattr("hexbot.planning.tidy.shorten", lambda i, moves, d=None: moves)
    # regroup tidies between its passes: untidied means without it too
    monkeypatch.setattr("hexbot.planning.regroup.regroup", lambda i, moves, f=None, d=None: moves)
    untidy = plan_robust(start, b)
    assert untidy.move_count > 3_000
    assert plan.move_count < 0.9 * untidy.move_count
    assert len(plan.steps) < len(untidy.steps)


def _random_walk(size: int, moves: int, seed: int) -> tuple[Configuration, list[Move]]:
    """``moves`` random legal rotations of random modules that are no cut
    vertex (any, not only those whose neighbours form one arc): a plan full
    of detours, whose replays meet cut vertices the journeys' plans avoid."""
    rng = random.Random(seed)
    start = Configuration.from_cells(random_blob(size, seed))
    where = {c: m.id for c, m in start.items()}
    plan: list[Move] = []
    while len(plan) < moves:
        cell = rng.choice(sorted(where))
        options = _moves_from(cell, set(where), cell)
        if not options or is_cut(set(where), cell):
            continue
        rule, sub, dst = rng.choice(options)
        plan.append(Move(where[cell], cell, dst, rule.joint, rule.direction, sub, where[sub]))
        where[dst] = where.pop(cell)
    return start, plan


@pytest.mark.parametrize("seed", range(6))
def test_the_c_pass_makes_the_python_passs_plan_on_random_walks(seed):
    start, plan = _random_walk(8 + seed, 400, seed)
    goal = replay(start, plan).cells
    ours = shorten(start, plan)
    assert ours == reference_shorten(start, plan)
    assert len(ours) < len(plan) // 2
    checked(start, goal, ours)
