"""The local method: window searches and the kernel flow, checked independently."""

import time

import pytest

from hexbot.bench.planning import make_pair
from hexbot.planning.bounds import move_lower_bound
from hexbot.planning.budget import BudgetExhausted, Deadline
from hexbot.planning.canonical import replay
from hexbot.planning.checker import check_plan
from hexbot.planning.configuration import Configuration
from hexbot.planning.flow import kernel, kernel_flow
from hexbot.planning.local import backward, forward, via_local
from hexbot.planning.robust import fillable, pack_consecutive, plan_robust, schedule_parallel
from hexbot.planning.windows import corridor, fix_in_window, window_flow

NO_LIMIT = Deadline(None)


def checked(initial, goal, serial, fixed=None):
    steps = schedule_parallel(initial, serial) or pack_consecutive(initial, serial)
    report = check_plan(initial, goal, steps, fixed=fixed)
    assert report.ok, report.problem
    return steps


@pytest.mark.parametrize("family", ["blob", "scramble"])
@pytest.mark.parametrize("seed", range(4))
def test_bench_pairs_of_30_are_planned_within_three_times_the_bound(family, seed):
    a, b = make_pair(family, 30, seed)
    start = Configuration.from_cells(a)
    serial = via_local(start, b, 10**6)
    checked(start, b, serial)
    # the strip route took up to 55 times the bound on these families
    assert len(serial) <= 3 * move_lower_bound(a, b).value


@pytest.mark.parametrize("flow", [window_flow, kernel_flow])
def test_each_flow_alone_plans_a_pair_both_ways(flow):
    a, b = make_pair("scramble", 30, 2)
    start = Configuration.from_cells(a)
    for direction in (forward, backward):
        serial = direction(start, b, flow, 10**6, None, NO_LIMIT, "local")
        assert replay(start, serial).cells == b
        checked(start, b, serial)


def test_the_fixed_module_never_moves():
    a, b = make_pair("scramble", 30, 1)
    start = Configuration.from_cells(a)
    serial = via_local(start, b, 10**6, fixed=(0, 0))
    assert all(m.src != (0, 0) for m in serial)
    checked(start, b, serial, fixed=(0, 0))


def test_kernel_lets_the_start_and_the_goal_peel_down_to_it():
    a, b = make_pair("blob", 100, 0)
    core, must = kernel(a, b, None)
    assert core and core <= a & b and not core & must
    assert not fillable(a, set(a) - core)  # every other start cell can be left
    assert not fillable(b, set(b) - core)  # every other goal cell can be entered


def test_a_window_fix_moves_a_module_off_the_goal_onto_it():
    bar = {(x, 0) for x in range(6)}
    goal = frozenset(bar - {(5, 0)} | {(4, 1)})
    hops = fix_in_window(set(bar), goal, corridor((5, 0), (4, 1), 1))
    assert [(src, dst) for src, dst, _, _ in hops] == [((5, 0), (4, 1))]
    # a window that holds no goal cell to fill has nothing to fix
    assert fix_in_window(set(bar), goal, corridor((5, 0), (5, 0), 0)) is None


def test_the_same_pair_gives_the_same_plan():
    a, b = make_pair("scramble", 30, 4)
    start = Configuration.from_cells(a)
    assert via_local(start, b, 10**6) == via_local(start, b, 10**6)


def test_the_time_cap_stops_it_with_a_reason():
    a, b = make_pair("scramble", 30, 8)
    with pytest.raises(BudgetExhausted, match="local: gave up"):
        via_local(Configuration.from_cells(a), b, 10**6, deadline=Deadline(0.0))


def test_a_methods_cap_counts_cpu_time_so_waiting_does_not_use_it_up():
    # a machine busy with other jobs must not cut a method short: the cap is
    # the planner's own CPU time, the overall budget stays wall time
    cap = Deadline(None).capped(0.05)
    time.sleep(0.1)
    assert not cap.expired()
    spins = 0
    while not cap.expired():  # work: the cap runs out
        spins += 1
    assert spins > 0
    assert Deadline(0.0).capped(10.0).expired()


def test_robust_mode_takes_the_local_method_where_direct_stalls():
    a, b = make_pair("scramble", 30, 0)
    plan = plan_robust(Configuration.from_cells(a), b)
    assert plan.reached and plan.method == "local", (plan.method, plan.reason)
    assert plan.move_count <= 3 * move_lower_bound(a, b).value


def test_a_goal_apart_from_the_start_is_a_global_change_with_a_short_local_cap():
    # a walk to a place one column away: no module keeps its cell; the local
    # flows spent their whole cap (16 s at 30 modules) failing before the
    # middle ball planned in a fraction of a second
    from hexbot.bench.planning import apart
    from hexbot.planning.generate import random_blob
    from hexbot.planning.local import GLOBAL_SECONDS, local_cap, local_seconds

    a = frozenset(random_blob(30, 0, 0.8))
    b = apart(a, frozenset(random_blob(30, 1, 0.8)))
    start = Configuration.from_cells(a)
    assert local_cap(start, b) == GLOBAL_SECONDS < local_seconds(30)
    plan = plan_robust(start, b)
    assert plan.reached and plan.method == "middle ball"
    assert check_plan(start, b, plan.steps).ok
    # the bench's pairs are local changes: they keep their cap
    for family, n, seed in [("blob", 10, 2), ("blob", 30, 3), ("scramble", 100, 0)]:
        initial, goal = make_pair(family, n, seed)
        assert local_cap(Configuration.from_cells(initial), goal) == local_seconds(n)


def _fewest_fix(occupied, goal, window, fixed=None, limit=20_000):
    """Reference for the C window search: breadth-first over the window's
    states (plain Python, the old search's move rule), the fewest rotations
    that lower the badness; None when the whole space has none; "limit" when
    it holds more than ``limit`` states."""
    from collections import deque

    from hexbot.planning.robust import _moves_from
    from hexbot.planning.windows import _can_leave

    outside = occupied - window
    holes = {c for c in window if c in goal}

    def badness(state):
        return len(state - goal) + len(holes - state)

    start = frozenset(occupied & window)
    before = badness(start)
    depth = {start: 0}
    queue = deque([start])
    while queue:
        state = queue.popleft()
        whole = outside | state
        for cell in state:
            if cell == fixed or not _can_leave(whole, cell):
                continue
            for _, _, dst in _moves_from(cell, whole, cell):
                after = (state - {cell}) | {dst}
                if dst not in window or after in depth:
                    continue
                if badness(after) < before:
                    return depth[state] + 1
                depth[after] = depth[state] + 1
                if len(depth) > limit:
                    return "limit"
                queue.append(after)
    return None


def _windows_of(family, n, seed, radius):
    from hexbot.planning.windows import assigned_pairs

    a, b = make_pair(family, n, seed)
    occupied, goal = set(a), frozenset(b)
    for _, end, void in assigned_pairs(occupied - goal, set(goal - occupied))[:4]:
        yield occupied, goal, corridor(end, void, radius)


def test_a_window_fix_takes_the_fewest_rotations_that_lower_the_badness_or_one_more():
    """The C search (A*, the goal tested when a state is reached) against a
    breadth-first search over the same window states (corridors of the
    nearest assigned pairs of bench pairs of 30 and 100 modules): the fewest
    rotations or one more, each one legal in turn (the window the only cells
    that change), and the badness lower at the end; no fix exactly when the
    breadth-first search exhausts the window's states."""
    from hexbot.planning.robust import _moves_from
    from hexbot.planning.windows import _can_leave

    compared = longer = longest = 0
    for family, n in (("blob", 30), ("blob", 100), ("scramble", 100)):
        for seed in range(4):
            for radius in (1, 2, 3):
                for occupied, goal, window in _windows_of(family, n, seed, radius):
                    fewest = _fewest_fix(occupied, goal, window)
                    if fewest == "limit":
                        continue
                    hops = fix_in_window(occupied, goal, window, max_states=200_000)
                    compared += 1
                    if fewest is None:
                        assert hops is None
                        continue
                    assert hops is not None and fewest <= len(hops) <= fewest + 1
                    longer += len(hops) > fewest
                    longest = max(longest, fewest)
                    state = set(occupied)
                    for src, dst, _, _ in hops:
                        assert dst in window and _can_leave(state, src)
                        assert dst in {d for _, _, d in _moves_from(src, state, src)}
                        state.remove(src)
                        state.add(dst)

                    def wrong(cells, window=window, goal=goal):
                        return sum(1 for c in window if (c in cells) != (c in goal))

                    assert wrong(state) < wrong(occupied)
    assert compared >= 100 and longest >= 7 and longer <= compared // 10


def test_a_window_of_more_than_128_cells_is_not_searched():
    from hexbot.planning.windows import disc

    bar = {(x, 0) for x in range(30)}
    goal = frozenset(bar - {(29, 0)} | {(28, 1)})
    assert len(disc((29, 0), 6)) == 127 and len(disc((29, 0), 7)) == 169
    hops = fix_in_window(set(bar), goal, disc((29, 0), 6))
    assert [(src, dst) for src, dst, _, _ in hops] == [((29, 0), (28, 1))]
    assert fix_in_window(set(bar), goal, disc((29, 0), 7)) is None
