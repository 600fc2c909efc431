"""The pivot step bound: never above the true fewest time steps (found here by
an exhaustive search over parallel steps the independent checker accepts),
and above the plain bottleneck where flat sides cannot shift at once."""

from collections import deque

import pytest

from hexbot.bench.planning import make_pair
from hexbot.planning import bounds
from hexbot.planning.bounds import NEVER, bottleneck_bound, leave_times, step_bound
from hexbot.planning.checker import _check_step
from hexbot.planning.generate import blob_pair
from hexbot.planning.moves import Move
from hexbot.planning.plan import Step
from hexbot.protocol.rotation_geometry import ROTATIONS


def _single_moves(cells: frozenset, ids: dict) -> list[tuple[Move, frozenset]]:
    """Every rotation open to one module, with the cells it needs."""
    out = []
    for cell in sorted(cells):
        for rule in ROTATIONS:
            substrate, end, swept = rule.at(cell)
            if substrate in cells and end not in cells and not any(c in cells for c in swept):
                move = Move(ids[cell], cell, end, rule.joint, rule.direction, substrate,
                            ids[substrate])
                out.append((move, frozenset((cell, end, *swept))))
    return out


def _steps_from(cells: frozenset, fixed):
    """Configurations one parallel step away: every set of moves with no shared
    cell that the checker accepts as one step."""
    ids = {c: i for i, c in enumerate(sorted(cells))}
    bolted = ids.get(fixed)
    singles = [m for m in _single_moves(cells, ids) if m[0].module != bolted]

    def grow(start, used, chosen):
        for k in range(start, len(singles)):
            move, need = singles[k]
            if need & used or move.substrate in {m.src for m in chosen} or \
                    any(m.substrate == move.src for m in chosen):
                continue
            picked = chosen + [move]
            where = {c: ids[c] for c in cells}
            if _check_step(where, Step(picked), bolted) == "":
                yield picked
            yield from grow(k + 1, used | need, picked)

    for picked in grow(0, frozenset(), []):
        yield (cells - {m.src for m in picked}) | {m.dst for m in picked}


def fewest_steps(initial: frozenset, goal: frozenset, fixed=None, limit: int = 12) -> int:
    """Breadth-first over whole configurations (modules are interchangeable)."""
    seen = {initial: 0}
    queue = deque([initial])
    while queue:
        cells = queue.popleft()
        if cells == goal:
            return seen[cells]
        if seen[cells] >= limit:
            continue
        for after in _steps_from(cells, fixed):
            if after not in seen:
                seen[after] = seen[cells] + 1
                queue.append(after)
    raise AssertionError("no plan within the limit")


@pytest.mark.parametrize("size,seed", [(3, s) for s in range(8)] + [(4, s) for s in range(8)]
                         + [(5, s) for s in range(6)])
def test_the_pivot_bound_never_exceeds_the_fewest_steps(size, seed):
    a, b = blob_pair(size, seed, 0.3)
    best = fewest_steps(a, b)
    assert bottleneck_bound(a, b).value <= step_bound(a, b).value <= best


def test_the_pivot_bound_is_reached_and_beats_the_plain_bottleneck():
    """A bent bar of three straightened: by distance alone one step, but the
    straight bar's middle cell has no three free sides in a row, so no module
    can arrive there in the last step: two steps, as the search finds."""
    a = frozenset({(-1, 0), (0, -1), (0, 0)})
    b = frozenset({(-1, 0), (0, 0), (1, 0)})
    best = fewest_steps(a, b)
    assert bottleneck_bound(a, b).value == 1
    assert step_bound(a, b).value == best == 2


def test_leave_times_grow_along_a_flat_side_and_the_bolted_module_never_leaves():
    bar = frozenset((x, 0) for x in range(5))
    times = leave_times(bar)
    # inside a bar the free sides are two and two: each waits for a neighbour
    assert [times[(x, 0)] for x in range(5)] == [1, 2, 3, 2, 1]
    ball = frozenset({(0, 0), (1, 0), (0, 1), (-1, 1), (-1, 0), (0, -1), (1, -1)})
    times = leave_times(ball)
    assert times[(0, 0)] == 2 and all(times[c] == 1 for c in ball - {(0, 0)})
    assert leave_times(ball, fixed=(1, 0))[(1, 0)] == NEVER


def test_the_fixed_module_stays_in_the_bound():
    a = frozenset({(0, 0), (1, 0)})
    b = frozenset({(1, 0), (2, 0)})  # free: one module rolls over the other
    assert step_bound(a, b).value <= fewest_steps(a, b) == 3
    assert step_bound(a, b, fixed=(0, 0)).value >= NEVER  # the bolted one would have to go


def test_the_nearest_fallback_is_weaker_and_valid():
    a, b = make_pair("blob", 300, 0)
    exact = step_bound(a, b)
    old = bounds.BOTTLENECK_LIMIT
    try:
        bounds.BOTTLENECK_LIMIT = 10
        weak = step_bound(a, b)
    finally:
        bounds.BOTTLENECK_LIMIT = old
    assert exact.kind == "pivot" and weak.kind == "nearest"
    assert bottleneck_bound(a, b).value < weak.value <= exact.value
