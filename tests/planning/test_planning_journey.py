"""Journeys across surface segments and the journey flow, checked independently."""

from collections import Counter

import pytest

from hexbot.bench.planning import make_pair
from hexbot.planning import journey as journeys
from hexbot.planning.bounds import bottleneck_bound, move_lower_bound
from hexbot.planning.budget import Deadline, PlanningFailure
from hexbot.planning.canonical import replay
from hexbot.planning.checker import check_plan
from hexbot.planning.configuration import Configuration, is_connected
from hexbot.planning.generate import parallelogram
from hexbot.planning.journey import channels, journey, journey_flow
from hexbot.planning.local import forward
from hexbot.planning.robust import fillable, pack_consecutive, plan_robust
from hexbot.planning.schedule import schedule_parallel
from hexbot.planning.surface import rolling_distances
from hexbot.planning.tracker import Tracker

NO_LIMIT = Deadline(None)

#: The 7-module shape of test_planning_surface: a one-cell inlet at (0, -1)
#: cuts the border; (2, -1) and (-2, 1) are in different segments.
INLET = {(-1, -1), (-1, 0), (-1, 1), (0, 0), (0, 1), (1, -1), (1, 1)}


def legal(initial: Configuration, goal, serial, fixed=None):
    report = check_plan(initial, goal, pack_consecutive(initial, serial), fixed=fixed)
    assert report.ok, report.problem


def flow_moves_per_bound(family: str, n: int, seed: int) -> float:
    """The journey flow's plan of a bench pair, checked; its moves / the bound."""
    a, b = make_pair(family, n, seed)
    start = Configuration.from_cells(a)
    serial = forward(start, b, journey_flow, 10**6, None, NO_LIMIT, "local")
    legal(start, b, serial)
    return len(serial) / move_lower_bound(a, b).value


def test_a_journey_crosses_a_mouth_no_rolling_module_can_cross():
    shape = INLET | {(2, -2)}
    start, target = (2, -2), (-2, 1)
    # others fixed, the module cannot roll there: the border is cut
    assert target not in rolling_distances(shape - {start}, [start])
    hops = journey(shape, start, target)
    assert hops
    cells = set(shape)
    for src, dst, _, _ in hops:
        assert src in cells and dst not in cells
        cells.discard(src)
        cells.add(dst)
        assert is_connected(cells)
    # the cells end as before, one module moved from the start to the target
    assert cells == shape - {start} | {target}
    goal = frozenset(cells)
    tracker = Tracker(Configuration.from_cells(shape), 100)
    tracker.roll(hops)
    legal(Configuration.from_cells(shape), goal, tracker.moves)


def test_a_module_flush_in_a_flat_side_leaves_it():
    # the middle of a parallelogram's top row has two free sides: it cannot rotate
    # until a neighbour steps aside
    shape = parallelogram(7, 3)
    flush = (3, 2)
    assert fillable(shape, {flush}) == {flush}
    goal = frozenset(shape - {flush} | {(7, 0)})
    start = Configuration.from_cells(shape)
    serial = forward(start, goal, journey_flow, 10**6, None, NO_LIMIT, "local")
    assert replay(start, serial).cells == goal
    legal(start, goal, serial)


@pytest.mark.parametrize("seed", range(6))
def test_scrambles_of_100_are_planned_within_three_times_the_bound(seed):
    # the strip route took 112-166 times the bound on these pairs
    assert flow_moves_per_bound("scramble", 100, seed) <= 3


def test_the_fixed_module_never_moves():
    a, b = make_pair("scramble", 100, 1)
    start = Configuration.from_cells(a)
    serial = forward(start, b, journey_flow, 10**6, (0, 0), NO_LIMIT, "local")
    assert all(m.src != (0, 0) for m in serial)
    legal(start, b, serial, fixed=(0, 0))


def test_a_stuck_flow_says_why():
    a, b = make_pair("blob", 100, 3)
    with pytest.raises(PlanningFailure, match=r"journeys stuck with \d+ goal cells to fill"):
        forward(Configuration.from_cells(a), b, journey_flow, 10**6, None, NO_LIMIT, "local")


def test_channels_open_the_wall_of_a_goal_cell_no_order_fills():
    # blob pair 1 of 100: one goal cell is walled in by the goal itself (the flow
    # used to stop there with that one cell to fill)
    a, b = make_pair("blob", 100, 1)
    voids = set(b - a)
    assert fillable(b, voids)
    walls = channels(b, voids, None)
    assert walls and walls <= b - voids and len(walls) <= 3
    assert not fillable(b, voids | walls)
    assert channels(b, set(), None) == set()


@pytest.mark.parametrize("seed", [1, 2])
def test_blobs_with_walled_goal_cells_are_planned_by_journeys(seed):
    # the walls step aside first and are refilled like any goal cell; before,
    # the robust planner took the middle ball (seed 1, 3.1 times the bound) and
    # the strip route (seed 2, 26.6 times the bound)
    assert flow_moves_per_bound("blob", 100, seed) <= 4


def test_an_end_stuck_in_a_bay_hands_over_to_a_goal_module():
    # scramble 300, seed 0: the last end rolls in a bay whose two mouths no
    # crossing passes; a goal module beside the bay takes its journey to the
    # void, the end its cell. Before, the strip route: 309 times the bound.
    assert flow_moves_per_bound("scramble", 300, 0) <= 3


def test_taking_moves_back_restores_the_configuration():
    a, b = make_pair("scramble", 30, 2)
    start = Configuration.from_cells(a)
    tracker = Tracker(start, 10**6)
    journey_flow(tracker, b, None, NO_LIMIT)
    assert tracker.occupied == set(b)
    tracker.undo_to(0)
    assert tracker.occupied == set(a) and not tracker.moves and not tracker.rolls
    assert tracker.ids == {c: m.id for c, m in start.items()}


def _flow_and_schedule(start, goal):
    tracker = Tracker(start, 10**6)
    journey_flow(tracker, goal, None, NO_LIMIT)
    steps = schedule_parallel(start, tracker.moves)
    report = check_plan(start, goal, steps)
    assert report.ok, report.problem
    return tracker, steps


def test_a_long_journey_runs_as_a_relay(monkeypatch):
    # a module crossing a bumpy row to its far end: alone it rolls 20 times in a
    # row; as a relay the bumps pass it on, each rolling a short leg at once
    bumps = {(x, 2) for x in range(1, 15, 3)}
    shape = set(parallelogram(16, 2)) | bumps
    start = Configuration.from_cells(shape | {(0, 2)})
    goal = frozenset(shape | {(15, 2)})
    relayed, steps = _flow_and_schedule(start, goal)
    monkeypatch.setattr(journeys, "RELAY_LONG", 10**6)
    single, single_steps = _flow_and_schedule(start, goal)
    assert len(single.rolls) == 1 and len(single_steps) == len(single.moves) == 20
    assert len(relayed.rolls) > 1 and len(relayed.moves) <= len(single.moves)
    assert len(steps) <= 8
    assert max(Counter(m.module for m in relayed.moves).values()) <= 8


def test_relays_shorten_the_makespan_of_a_scramble(monkeypatch):
    # scramble 300, seed 2: 32 time steps without relays, 27 with them (36
    # and 27 until session 15, when the schedule let reads of a cell run in
    # any order)
    a, b = make_pair("scramble", 300, 2)
    start = Configuration.from_cells(a)
    relayed, steps = _flow_and_schedule(start, b)
    monkeypatch.setattr(journeys, "RELAY_LONG", 10**6)
    single, single_steps = _flow_and_schedule(start, b)
    assert len(steps) <= 0.85 * len(single_steps)
    assert len(relayed.moves) <= len(single.moves)


def test_relays_plan_a_count_of_journeys_so_a_pair_always_gets_the_same_plan(monkeypatch):
    # scramble 300, seed 2: its relays plan 129 journeys when nothing stops them;
    # cut short at 30 (a count, not CPU seconds) they stop at the same place in
    # every run
    a, b = make_pair("scramble", 300, 2)
    start = Configuration.from_cells(a)

    def plan():
        tracker, steps = _flow_and_schedule(start, b)
        return [(m.module, m.src, m.dst) for m in tracker.moves], len(steps)

    whole = plan()
    monkeypatch.setattr(journeys, "relay_journeys", lambda count: 30)
    first, second = plan(), plan()
    assert first == second
    assert first != whole  # the count did stop the relays


def test_runs_of_fills_on_the_critical_path_are_reversed(monkeypatch):
    # scramble 100, seed 0: 20 time steps with the relays alone, 15 when runs of
    # journeys on the critical path are planned again in reverse order
    a, b = make_pair("scramble", 100, 0)
    start = Configuration.from_cells(a)
    _, steps = _flow_and_schedule(start, b)
    monkeypatch.setattr(journeys, "REORDER_RUN", 1)
    _, in_order = _flow_and_schedule(start, b)
    assert len(steps) < len(in_order)


def test_a_local_change_of_1000_modules_is_planned_locally():
    # the goal is 3,000 random moves away; the strip route took 700-1,060 times the bound
    a, b = make_pair("scramble", 1000, 1)
    start = Configuration.from_cells(a)
    plan = plan_robust(start, b)
    assert plan.reached and plan.method == "local", (plan.method, plan.reason)
    bound = move_lower_bound(a, b).value
    assert plan.move_count <= 3 * bound
    # relays and reversed runs (session 11): 34 time steps -> 28, bottleneck 3
    assert len(plan.steps) <= 10 * bottleneck_bound(a, b).value
    report = check_plan(start, b, plan.steps)
    assert report.ok, report.problem


@pytest.mark.parametrize("seed", range(3))
def test_crossings_are_legal_and_leave_their_window_as_it_was_but_one_module_nearer(seed):
    from hexbot.planning.robust import _moves_from, is_cut
    from hexbot.planning.surface import border, border_steps
    from hexbot.planning.windows import disc

    occupied = set(make_pair("blob", 100, seed)[0])
    targets = sorted(border(occupied))[::9]
    found = 0
    for traveller in sorted(occupied)[::3]:
        if is_cut(occupied, traveller):
            continue
        for target in targets:
            steps = border_steps(occupied - {traveller}, target)
            for radius in journeys.CROSSING_RADII:
                result = journeys.crossing(occupied, traveller, radius, steps, None)
                if result is None:
                    continue
                hops, arrived = result
                after = set(occupied)
                for src, dst, rule, sub in hops:
                    assert src in after and dst not in after
                    assert (rule, sub, dst) in _moves_from(src, after, src)
                    after.discard(src)
                    after.add(dst)
                    assert is_connected(after)
                    assert {src, dst} <= disc(traveller, radius)
                assert after == (occupied - {traveller}) | {arrived}
                assert steps[arrived] < steps.get(traveller, float("inf"))
                found += 1
    assert found >= 20



@pytest.mark.parametrize("seed", range(3))
def test_a_peel_asked_after_a_change_agrees_with_peeling_again(seed):
    # the journey flow asks, per candidate fill, which voids and ends the fill
    # walls in; Peel re-peels only what the changed cells had freed
    import random

    from hexbot.planning.robust import Peel

    rng = random.Random(seed)
    a, b = make_pair("blob", 300, seed)
    occupied = set(a)
    for cell in rng.sample(sorted(b - a), len(b - a) // 3):
        occupied.add(cell)
    voids, ends = set(b - occupied), occupied - b
    peel = Peel(b, voids)
    assert peel.left == fillable(b, voids)
    for void in sorted(voids):
        assert peel.after(b, voids - {void}, (void,)) == fillable(b, voids - {void})
    shape = frozenset(occupied)
    peel = Peel(shape, ends)
    for mover in sorted(ends)[::4]:
        for void in sorted(voids)[::5]:
            after, rest = (shape - {mover}) | {void}, ends - {mover}
            assert peel.after(after, rest, (void, mover)) == fillable(after, rest)
