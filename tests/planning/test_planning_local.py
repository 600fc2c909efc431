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
