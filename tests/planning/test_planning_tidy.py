"""Dropping round trips from serial plans, checked by the independent checker."""

import pytest
from test_planning_journey import INLET

from hexbot.bench.planning import make_pair
from hexbot.planning.budget import Deadline
from hexbot.planning.canonical import replay
from hexbot.planning.checker import check_plan
from hexbot.planning.configuration import Configuration
from hexbot.planning.journey import journey, journey_flow
from hexbot.planning.local import forward
from hexbot.planning.moves import Move
from hexbot.planning.robust import _moves_from, is_cut, pack_consecutive, plan_robust, reverse_move
from hexbot.planning.tidy import shorten
from hexbot.planning.tracker import Tracker


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
    untidy = plan_robust(start, b)
    assert plan.method == untidy.method == "local"
    assert plan.move_count < untidy.move_count
