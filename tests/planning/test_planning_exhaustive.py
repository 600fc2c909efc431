"""Proof by exhaustion for small clusters: every pair of connected
configurations of up to 5 modules is planned (docs/planning.md, *What is
covered*). The full runs at 5 and 6 modules are `hexbot bench planning
--exhaustive N`; here all pairs of 4 and every 25th pair of 5."""

import itertools

import pytest

from hexbot.planning.checker import check_plan
from hexbot.planning.configuration import Configuration, is_connected
from hexbot.planning.generate import hub, polyhexes
from hexbot.planning.robust import plan_robust


def test_the_shapes_are_every_polyhex_once():
    # the fixed polyhexes (hexagonal polyominoes up to translation): 1, 3, 11, 44, 186
    assert [len(polyhexes(n)) for n in range(1, 6)] == [1, 3, 11, 44, 186]
    for shape in polyhexes(4):
        assert min(shape) == (0, 0) and is_connected(shape)


def pairs(size: int, every: int = 1):
    shapes = polyhexes(size)
    ordered = [(a, b) for a, b in itertools.product(shapes, shapes) if a != b]
    return ordered[::every]


def unplanned(pairs, fixed):
    """The pairs the robust mode does not plan, or plans wrongly (the checker)."""
    failed = []
    for a, b in pairs:
        start = Configuration.from_cells(a)
        plan = plan_robust(start, b, fixed=fixed)
        report = check_plan(start, b, plan.steps, fixed=fixed) if plan.reached else None
        if report is None or not report.ok:
            failed.append((sorted(a), sorted(b), plan.reason or report.problem))
    return failed


@pytest.mark.parametrize("fixed", [None, (0, 0)], ids=["free", "fixed"])
@pytest.mark.parametrize("size, every", [(3, 1), (4, 1), (5, 25)])
def test_every_pair_of_small_clusters_is_planned(size, every, fixed):
    failed = unplanned(pairs(size, every), fixed)
    assert not failed, failed[:3]


@pytest.mark.parametrize("fixed", [None, (0, 0)], ids=["free", "fixed"])
def test_clusters_of_seven_reach_the_hub_and_back(fixed):
    """The thesis' cluster has seven modules: every 7-module shape reaches the
    compact one and comes back, so every pair is reachable through it (all
    3,652 shapes: `hexbot bench planning --hub 7`; here every 40th)."""
    middle = hub(7)
    trips = [p for shape in polyhexes(7)[::40] if shape != middle
             for p in ((shape, middle), (middle, shape))]
    failed = unplanned(trips, fixed)
    assert not failed, failed[:3]
