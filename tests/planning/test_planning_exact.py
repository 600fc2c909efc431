"""Exact mode (A*), lower bounds, and the robust mode's gap on the small bank."""

import itertools

import pytest

from hexbot.planning.bank import small_cases
from hexbot.planning.bounds import bottleneck_bound, hex_distances, move_lower_bound
from hexbot.planning.checker import check_plan
from hexbot.planning.configuration import Configuration
from hexbot.planning.exact import EXACT_LIMIT, plan_exact
from hexbot.planning.generate import blob_pair, random_blob
from hexbot.planning.robust import plan_robust


def test_s02_optimum_is_17_moves_below_the_thesis_20(s02):
    initial, goal = s02
    plan = plan_exact(initial, goal, parallel=False)
    assert plan.reached and plan.move_count == 17
    assert check_plan(initial, goal, plan.steps).ok
    robust = plan_robust(initial, goal)
    assert robust.move_count >= 17  # nothing beats the optimum


def test_p02_swapped_optimum_is_8_moves(p02_swapped):
    initial, goal = p02_swapped
    plan = plan_exact(initial, goal)
    assert plan.reached and plan.move_count == 8
    assert check_plan(initial, goal, plan.steps).ok


def test_exact_refuses_large_configurations_and_stops_at_its_budget():
    a, b = blob_pair(EXACT_LIMIT + 1, 0)
    plan = plan_exact(Configuration.from_cells(a), b)
    assert not plan.reached and "takes at most" in plan.reason
    a, b = blob_pair(12, 3)
    plan = plan_exact(Configuration.from_cells(a), b, budget=1e-6)
    assert not plan.reached and "time budget" in plan.reason


def test_robust_never_beats_exact_and_both_are_legal_on_the_small_bank():
    cases = small_cases(random_pairs=1)
    assert any(c.name == "Test_All_S02" for c in cases)
    for case in cases:
        exact = plan_exact(case.initial, case.goal, case.fixed, budget=30)
        robust = plan_robust(case.initial, case.goal, fixed=case.fixed)
        assert exact.reached and robust.reached, case.name
        for plan in (exact, robust):
            report = check_plan(case.initial, case.goal, plan.steps, case.fixed)
            assert report.ok, (case.name, report.problem)
        assert exact.lower_bound <= exact.move_count <= robust.move_count, case.name


def brute_force(a, b, cost):
    """Every bijection a -> b: (min of the sum, min of the max)."""
    d = hex_distances(sorted(a), sorted(b))
    perms = list(itertools.permutations(range(len(b))))
    return (min(sum(d[i, p[i]] for i in range(len(a))) for p in perms),
            min(max(d[i, p[i]] for i in range(len(a))) for p in perms))


@pytest.mark.parametrize("seed", range(5))
def test_bounds_match_brute_force_on_small_sets(seed):
    a, b = random_blob(6, 2 * seed, 0.3), random_blob(6, 2 * seed + 1, 0.3)
    total, worst = brute_force(a, b, hex_distances)
    assert move_lower_bound(a, b).value == total
    assert bottleneck_bound(a, b).value == worst


@pytest.mark.parametrize("seed", range(3))
def test_the_bottleneck_bound_is_the_level_where_a_perfect_matching_appears(seed):
    """Checked with scipy's matching, which the bound used before (it took 44 s
    on one level of a blob of 1,000; fast at 300)."""
    from scipy.sparse import csr_matrix
    from scipy.sparse.csgraph import maximum_bipartite_matching

    from hexbot.bench.planning import make_pair

    a, b = make_pair("blob", 300, seed)
    level = bottleneck_bound(a, b).value
    d = hex_distances(sorted(a), sorted(b))

    def perfect(limit):
        return (maximum_bipartite_matching(csr_matrix(d <= limit), perm_type="column") >= 0).all()

    assert perfect(level) and not perfect(level - 1)


def test_bottleneck_counts_shifts_of_shared_cells():
    # a bar of three moving one cell right: each module moves once (bound 1), while
    # the only cell to leave is three cells from the only cell to fill
    a = frozenset({(0, 0), (1, 0), (2, 0)})
    b = frozenset({(1, 0), (2, 0), (3, 0)})
    assert move_lower_bound(a, b).value == 3 and bottleneck_bound(a, b).value == 1
