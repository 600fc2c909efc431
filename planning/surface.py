"""Where a module can roll: the surface of a configuration as Table 4-3 sees it.

A module travels over the others by rotations, each about a joint it shares
with a substrate, over a goal cell and three swept cells that must be empty.
With every other module fixed, the empty cells it can reach from one cell
form a *segment* of the surface. A smooth shape (a parallelogram, a compact
ball) has one segment all around it; a rough one is cut into many, because
a 120-degree rotation cannot cross the mouth of a one-cell inlet (the two
cells at the mouth share no module to turn about, and the inlet cell itself
has four occupied sides, so no rotation enters it).

This is what makes a "surface flow" planner non-local on random shapes: a
module can only reach the cells of its own segment, so a local plan must
first open the inlets between the cells to leave and the cells to fill
(docs/planning.md, "Why the surface flow is not local").
"""

from __future__ import annotations

from collections import deque
from collections.abc import Iterable

from hexbot.planning.hexlattice import SIDE_OFFSETS, SIDES, Cell, neighbors
from hexbot.planning.robust import _moves_from

_OFFSETS = tuple(SIDE_OFFSETS[s] for s in SIDES)


def rolling_distances(occupied: set[Cell] | frozenset[Cell],
                      sources: Iterable[Cell]) -> dict[Cell, int]:
    """Rotations needed to roll from the nearest of ``sources`` (empty cells) to
    every empty cell reachable from them, with every module in ``occupied`` fixed.

    Rotations are reversible over the same cells, so these are also the
    distances *towards* the sources.
    """
    start = sorted(set(sources))
    dist = dict.fromkeys(start, 0)
    queue = deque(start)
    while queue:
        cell = queue.popleft()
        for _, _, goal in _moves_from(cell, occupied, cell):
            if goal not in dist:
                dist[goal] = dist[cell] + 1
                queue.append(goal)
    return dist


def border(occupied: set[Cell] | frozenset[Cell]) -> set[Cell]:
    """Empty cells touching at least one module."""
    return {n for c in occupied for n in neighbors(c) if n not in occupied}


def border_steps(occupied: set[Cell] | frozenset[Cell], target: Cell,
                 stop: Cell | None = None) -> dict[Cell, int]:
    """Steps from ``target`` to the border cells, walking from border cell to
    adjacent border cell (around the configuration, not through it). A
    journey's measure of progress: rolling and crossing inlets both move along
    the border. With ``stop``, the walk ends with the level that reaches it
    (a journey from ``stop`` only goes nearer)."""
    (x1, y1), (x2, y2), (x3, y3), (x4, y4), (x5, y5), (x6, y6) = _OFFSETS
    dist = {target: 0}
    away: set[Cell] = set()  # empty cells touching no module (looked at once)
    level = [target]
    while level and (stop is None or stop not in dist):
        following = []
        for cell in level:
            here = dist[cell] + 1
            for n in neighbors(cell):
                if n in dist or n in occupied or n in away:
                    continue
                x, y = n
                if ((x + x1, y + y1) in occupied or (x + x2, y + y2) in occupied
                        or (x + x3, y + y3) in occupied or (x + x4, y + y4) in occupied
                        or (x + x5, y + y5) in occupied or (x + x6, y + y6) in occupied):
                    dist[n] = here
                    following.append(n)
                else:
                    away.add(n)
        level = following
    return dist


def surface_segments(occupied: set[Cell] | frozenset[Cell]) -> list[set[Cell]]:
    """The border cells grouped by where a module can roll between them (largest first).

    A border cell no rotation can leave (an inlet) is a segment of its own.
    Only border cells are returned; rolling never leaves the border anyway
    (the substrate touches the goal cell).
    """
    occupied = set(occupied)
    cells = border(occupied)
    seen: set[Cell] = set()
    segments: list[set[Cell]] = []
    for cell in sorted(cells):
        if cell in seen:
            continue
        segment = set(rolling_distances(occupied, [cell])) & cells
        seen |= segment
        segments.append(segment)
    segments.sort(key=lambda s: (-len(s), min(s)))
    return segments


def enclosed(occupied: set[Cell] | frozenset[Cell]) -> set[Cell]:
    """The empty cells the configuration walls in (its holes): those not joined
    to the outside through empty cells, side to side."""
    if not occupied:
        return set()
    xs = [x for x, _ in occupied]
    ys = [y for _, y in occupied]
    low, high = (min(xs) - 1, min(ys) - 1), (max(xs) + 1, max(ys) + 1)

    def inside(cell: Cell) -> bool:
        return low[0] <= cell[0] <= high[0] and low[1] <= cell[1] <= high[1]

    outside = {low}  # a corner of the bounding box grown by one is outside
    queue = deque(outside)
    while queue:
        for n in neighbors(queue.popleft()):
            if n not in outside and n not in occupied and inside(n):
                outside.add(n)
                queue.append(n)
    return {(x, y) for x in range(low[0], high[0] + 1) for y in range(low[1], high[1] + 1)
            if (x, y) not in occupied and (x, y) not in outside}
