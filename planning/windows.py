"""Window search: the shortest local fix, found by A* over a few cells.

A module off the goal (an *end*) and a goal cell still empty (a *void*)
are joined by the fewest rotations of the modules inside a window around
them, every other module fixed: best-first over the window's occupied
cells, each successor one Table 4-3 rotation of a module that is not a cut
vertex of the whole configuration, until the window's *badness* (modules
off the goal plus goal cells empty) goes down. Such a fix can shift goal
modules along the way (the void travels towards the end, the thesis' void
propagation) and open the inlets that cut the surface into segments
(:mod:`hexbot.planning.surface`), which a plain journey cannot.

The window is a corridor: the cells within ``radius`` of the hex line from
the end to the void. Its state space is bounded by ``max_states``, its size
by 128 cells (``AREA``: the search runs in C, ``planning/_regroup.c``; on
the bench's pairs of 30 and 100 modules the largest window searched had 121
cells, the largest that held a fix 72). A longer corridor is not built: for
a pair a million cells apart it took 16 s and 900 MB, to be refused.
"""

from __future__ import annotations

import numpy as np
from scipy.optimize import linear_sum_assignment

from hexbot.planning._regroup import AREA
from hexbot.planning.hexlattice import Cell, distance, neighbors

#: One rotation: (from, to, Table 4-3 row, substrate cell).
Hop = tuple[Cell, Cell, object, Cell]


_DISC_OFFSETS: dict[int, tuple[Cell, ...]] = {}  # radius -> offsets, worked out once


def disc(center: Cell, radius: int) -> set[Cell]:
    """The cells within ``radius`` of ``center``."""
    offsets = _DISC_OFFSETS.get(radius)
    if offsets is None:
        offsets = _DISC_OFFSETS[radius] = tuple(
            (dx, dy) for dx in range(-radius, radius + 1) for dy in range(-radius, radius + 1)
            if distance((dx, dy), (0, 0)) <= radius)
    x0, y0 = center
    return {(x0 + dx, y0 + dy) for dx, dy in offsets}


def corridor(a: Cell, b: Cell, radius: int) -> set[Cell] | None:
    """The cells within ``radius`` of the hex line from ``a`` to ``b``, or None
    when they are more than the ``AREA`` cells an area search takes (the
    line alone has one cell per step: a far pair's corridor is never built)."""
    steps = max(1, distance(a, b))
    if steps >= AREA:
        return None
    cells: set[Cell] = set()
    for k in range(steps + 1):
        point = (round(a[0] + (b[0] - a[0]) * k / steps), round(a[1] + (b[1] - a[1]) * k / steps))
        cells |= disc(point, radius)
        if len(cells) > AREA:
            return None
    return cells


def fix_in_window(occupied: set[Cell], goal: frozenset[Cell], window: set[Cell],
                  fixed: Cell | None = None, max_states: int = 3000) -> list[Hop] | None:
    """The fewest rotations (or one more) inside ``window`` that lower its badness, or None
    (none within ``max_states`` window states, or a window of more than 128
    cells). An A* in C (:func:`hexbot.planning.area_search.improve_in_area`)."""
    from hexbot.planning.area_search import improve_in_area  # it imports this module

    return improve_in_area(occupied, goal, window, fixed, max_states)


def _leavable(mask: int) -> bool:
    ring = [bool(mask >> i & 1) for i in range(6)]
    if not any(not ring[i] and not ring[i - 1] and not ring[i - 2] for i in range(6)):
        return False
    return sum(1 for i in range(6) if ring[i] and not ring[i - 1]) <= 1


#: Per ring mask (bit i = side i + 1 occupied): can a module with that ring leave?
_LEAVABLE = tuple(_leavable(mask) for mask in range(64))


def _can_leave(occupied: set[Cell] | frozenset[Cell], cell: Cell) -> bool:
    """Three consecutive sides free (a rotation needs them) and the occupied ones in
    one arc (so leaving cannot disconnect anything): six look-ups and a table,
    and most cells of a window fail here before their twelve rotations are tried."""
    a, b, c, d, e, f = neighbors(cell)
    return _LEAVABLE[(a in occupied) | (b in occupied) << 1 | (c in occupied) << 2
                     | (d in occupied) << 3 | (e in occupied) << 4 | (f in occupied) << 5]


def distance_matrix(rows: list[Cell], cols: list[Cell]) -> np.ndarray:
    """Lattice distances between every cell of ``rows`` and every cell of ``cols``."""
    a = np.array(rows, dtype=np.int64).reshape(-1, 2)
    b = np.array(cols, dtype=np.int64).reshape(-1, 2)
    dx = b[None, :, 0] - a[:, None, 0]
    dy = b[None, :, 1] - a[:, None, 1]
    return (np.abs(dx) + np.abs(dy) + np.abs(dx + dy)) // 2


def assigned_pairs(ends: set[Cell], voids: set[Cell],
                   cost: np.ndarray | None = None) -> list[tuple[int, Cell, Cell]]:
    """(distance, end, void) of the cheapest assignment of ends onto voids, nearest
    first. ``cost``: their :func:`distance_matrix` in sorted order, if known."""
    ends_, voids_ = sorted(ends), sorted(voids)
    if cost is None:
        cost = distance_matrix(ends_, voids_)
    rows, cols = linear_sum_assignment(cost)
    return sorted((int(cost[r, c]), ends_[r], voids_[c]) for r, c in zip(rows, cols, strict=True))


#: Corridor radii tried in turn, pairs tried per radius, window states per search.
RADII = (1, 2, 3)
PAIRS_TRIED = 6
MAX_STATES = 3000


def window_flow(tracker, goal: frozenset[Cell], fixed: Cell | None, deadline,
                method: str = "local") -> None:
    """Fix windows until every module is on the goal (raises PlanningFailure when
    no corridor of the nearest assigned pairs has a fix). Each fix lowers the
    number of modules off the goal, so the loop ends."""
    from hexbot.planning.budget import PlanningFailure

    while True:
        deadline.check(method)
        ends = tracker.occupied - goal
        if not ends:
            return
        pairs = assigned_pairs(ends, set(goal - tracker.occupied))
        hops = None
        for radius in RADII:
            for _, end, void in pairs[:PAIRS_TRIED]:
                window = corridor(end, void, radius)
                hops = window and fix_in_window(tracker.occupied, goal, window, fixed,
                                                MAX_STATES)
                if hops:
                    break
            if hops:
                break
        if not hops:
            raise PlanningFailure(f"{method}: window search stuck with {len(ends)} modules off "
                                  f"the goal (no fix in a corridor of radius {RADII[-1]} within "
                                  f"{MAX_STATES} states)")
        tracker.roll(hops)
