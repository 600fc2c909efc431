"""The crossing search runs in C (planning/_crossing.c); it must give the hops
the Python search gave (tests/planning/crossing_reference.py), search for
search, since plans are compared across sessions and machines."""

import random

import pytest

from hexbot.bench.planning import make_pair
from hexbot.planning import _crossing
from hexbot.planning.hexlattice import neighbors
from hexbot.planning.journey import crossing
from hexbot.planning.surface import border_steps
from tests.planning.crossing_reference import reference_crossing


def _questions(seed: int, count: int):
    """Crossings a flow would ask for: a surface module of a random blob, the
    border distances to a random empty cell beside the blob."""
    rng = random.Random(seed)
    cells, _ = make_pair("blob", 60, seed)
    occupied = set(cells)
    surface = sorted(c for c in occupied if any(n not in occupied for n in neighbors(c)))
    empty = sorted({n for c in occupied for n in neighbors(c)} - occupied)
    for _ in range(count):
        traveller, target = rng.choice(surface), rng.choice(empty)
        steps = border_steps(occupied - {traveller}, target, stop=traveller)
        fixed = rng.choice(sorted(occupied)) if rng.random() < 0.3 else None
        yield occupied, traveller, steps, fixed


@pytest.mark.parametrize("seed", range(4))
def test_the_c_search_finds_what_the_python_search_found(seed):
    found = missed = 0
    for occupied, traveller, steps, fixed in _questions(seed, 25):
        for radius in (2, 3):
            for states in (300, 4000):
                ours = crossing(occupied, traveller, radius, steps, fixed, states)
                theirs = reference_crossing(occupied, traveller, radius, steps, fixed, states)
                assert ours == theirs, (traveller, radius, states, fixed)
                found += ours is not None
                missed += ours is None
    # Both outcomes were exercised, else the comparison proves little.
    assert found >= 20 and missed >= 5


def test_a_crossing_that_failed_is_not_searched_again():
    occupied, traveller, steps, fixed = next(
        q for q in _questions(7, 200)
        if reference_crossing(q[0], q[1], 2, q[2], q[3], 300) is None)
    failed: set = set()
    assert crossing(occupied, traveller, 2, steps, fixed, 300, failed) is None
    assert len(failed) == 1
    assert crossing(occupied, traveller, 2, steps, fixed, 300, failed) is None
    assert len(failed) == 1


def test_the_c_search_refuses_bad_arguments():
    with pytest.raises(ValueError, match="bad arguments"):
        _crossing.search(99, 1, 0, 0, 0, 0, 100)
    with pytest.raises(ValueError, match="bad arguments"):
        _crossing.search(0, 1, 0, 0, 0, 0, 0)
