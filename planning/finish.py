"""Finishing a stalled flow: ends carried to far voids in legs along the surface.

When the journey flow is stuck, what is left is a few ends and voids far
apart on a rough surface: the journeys' crossings (radius 3 around one
mover) find no way past the notches between them. Here each end is taken
to its void along the shortest path over the empty cells that touch the
configuration (:func:`surface_path`), one *leg* of at most ``LEG`` cells at
a time. A leg is an A* search over an area (the leg's cells and the end's,
grown by ``PADS`` rings, at most 128 cells) for the fewest rotations that
leave the area as it is but for one module taken off the end's cell and
one standing on the leg's last cell, every module outside the area fixed
and modules interchangeable (:func:`hexbot.planning.area_search.move_in_area`): a
wall module may step aside and come back, or pass the end on, where the
end cannot roll itself. The last leg fills the void. A module moves only
with three free sides in a row, and when its occupied neighbours form one
arc or stay joined without it (through the area's modules and the pieces
of the outside they touch, :func:`outside_components`); never the bolted
one. So every rotation keeps the configuration in one piece.

Measured on the bench scramble of 10,000 modules (docs/planning.md,
*Finishing a stalled flow*).
"""

from __future__ import annotations

from collections import deque

from hexbot.planning import area_search
from hexbot.planning.budget import Deadline
from hexbot.planning.hexlattice import Cell, distance, neighbors
from hexbot.planning.schedule import meeting_searches
from hexbot.planning.windows import Hop, assigned_pairs, corridor

#: Cells of the surface path one leg covers at most (shorter legs are tried
#: when it finds nothing).
LEG = 8
#: Rings grown around a leg's cells, tried in turn.
PADS = (1, 2)
#: Area states one leg's search stores at most.
STATES = 30_000
#: A leg takes fewer rotations than this.
LEG_ROTATIONS = 60
#: Pairs at most this far apart are first tried on the hex line between them.
ACROSS = 12
#: Radii of the hex-line areas tried for the last leg.
CORRIDORS = (1, 2)
#: Other ends of an area tried in turn as the one that leaves.
OTHERS = 3
#: Legs one finish may take in all.
LEGS = 400


def surface_path(occupied: set[Cell], end: Cell, void: Cell) -> list[Cell] | None:
    """The shortest path from a free neighbour of ``end`` to ``void`` over empty
    cells that touch a module other than the end's; when the void is walled in,
    the path to the cell of that surface nearest to it (the last leg then goes
    through the wall); None when the end has no free neighbour."""
    starts = [n for n in neighbors(end) if n not in occupied]
    parent: dict[Cell, Cell | None] = dict.fromkeys(starts)
    queue = deque(starts)
    nearest = min(starts, key=lambda c: distance(c, void), default=None)
    while queue:
        cell = queue.popleft()
        if distance(cell, void) < distance(nearest, void):
            nearest = cell
        if cell == void:
            break
        for n in neighbors(cell):
            if n in parent or n in occupied:
                continue
            if n == void or any(m in occupied and m != end for m in neighbors(n)):
                parent[n] = cell
                queue.append(n)
    if nearest is None:
        return None
    path = []
    while nearest is not None:
        path.append(nearest)
        nearest = parent[nearest]
    return path[::-1]


def _grown(cells: list[Cell], rings: int) -> set[Cell]:
    area = set(cells)
    for _ in range(rings):
        area |= {n for c in area for n in neighbors(c)}
    return area


def outside_components(occupied: set[Cell], area: set[Cell]) -> dict[Cell, int]:
    """For the modules outside ``area`` that touch it: which piece of the
    modules outside the area each belongs to (0, 1, ...), by
    :func:`~hexbot.planning.schedule.meeting_searches` (never the whole
    configuration walked when it stays one piece)."""
    touching = sorted({n for c in area for n in neighbors(c) if n in occupied and n not in area})
    pieces = meeting_searches(occupied, touching, area) or []
    labels: dict[int, int] = {}
    return {cell: labels.setdefault(piece, len(labels))
            for cell, piece in zip(touching, pieces, strict=True)}


def move_in_area(occupied: set[Cell], area: set[Cell], target: set[Cell],
                 fixed: Cell | None, states: int = STATES,
                 limit: int = LEG_ROTATIONS) -> list[Hop] | None:
    """The fewest rotations, fewer than ``limit``, inside ``area`` after which
    exactly ``target`` of its cells are occupied (modules interchangeable, the
    rest fixed), or None. A module whose neighbours form several arcs may move
    when the rest stays one piece: :func:`outside_components` tells the search
    which modules outside the area are joined."""
    if len(area) > area_search.AREA:  # before the outside's pieces are looked for
        return None
    return area_search.move_in_area(occupied, area, target, fixed, states, limit,
                                    outside_components(occupied, area))


def _across(occupied: set[Cell], goal: frozenset[Cell], end: Cell, void: Cell,
            fixed: Cell | None) -> tuple[list[Hop], Cell] | None:
    """The last leg on the hex line from ``end`` to ``void`` (``corridor``)."""
    for radius in CORRIDORS:
        area = corridor(end, void, radius)
        found = area and _leave_for(occupied, goal, area, end, void, fixed)
        if found:
            return found
    return None


def _leave_for(occupied: set[Cell], goal: frozenset[Cell], area: set[Cell], end: Cell,
               reach: Cell, fixed: Cell | None) -> tuple[list[Hop], Cell] | None:
    """Rotations in ``area`` after which ``reach`` holds a module and one end of
    the area has left: ``end`` itself, else the others nearest ``reach`` first
    (``end`` is often walled in where a neighbouring end is free)."""
    kept = occupied & area
    others = sorted(((occupied - goal) & area) - {end}, key=lambda e: distance(e, reach))
    for leaving in [end, *others[:OTHERS]]:
        hops = move_in_area(occupied, area, kept - {leaving} | {reach}, fixed)
        if hops:
            return hops, leaving
    return None


def _leg(occupied: set[Cell], goal: frozenset[Cell], end: Cell, void: Cell,
         fixed: Cell | None) -> tuple[list[Hop], Cell, Cell] | None:
    """One leg from ``end`` towards ``void``: (rotations, the end that left, the
    cell reached), or None. Straight across when near, else along the surface
    path, the longest leg that a search finds."""
    if distance(end, void) <= ACROSS:  # through a wall if need be
        found = _across(occupied, goal, end, void, fixed)
        if found:
            return found[0], found[1], void
    path = surface_path(occupied, end, void)
    if path is None:
        return None
    for leg in range(min(LEG, len(path)), 2, -2):
        reach = path[leg - 1]
        for rings in PADS:
            found = _leave_for(occupied, goal, _grown(path[:leg] + [end], rings), end, reach,
                               fixed)
            if found:
                return found[0], found[1], reach
    return None


def _apply(occupied: set[Cell], hops: list[Hop]) -> None:
    for src, dst, _rule, _sub in hops:
        occupied.discard(src)
        occupied.add(dst)


def finish(occupied: set[Cell], goal: frozenset[Cell], fixed: Cell | None,
           deadline: Deadline) -> list[Hop]:
    """Carry ends to voids until every void is filled or no leg is found; the
    rotations (``occupied`` is left as it was: the caller's tracker rolls them).

    Each void keeps the end assigned to it (cheapest assignment, carried leg
    by leg, nearest pairs first); when a leg sends another end of its area,
    the two ends swap voids, so every end always heads for one void. A pass
    over the pairs that finds no leg ends the finish, and so do ``LEGS``."""
    work = set(occupied)
    heading = {void: end for _, end, void in assigned_pairs(work - goal, goal - work)}
    hops: list[Hop] = []
    legs = LEGS
    moved = True
    while heading and moved and legs > 0 and not deadline.expired():
        moved = False
        for void in sorted(heading, key=lambda v: distance(v, heading[v])):
            if void not in heading:
                continue
            end = heading[void]
            found = _leg(work, goal, end, void, fixed)
            if found is None:
                continue
            rotations, leaving, reach = found
            _apply(work, rotations)
            hops += rotations
            legs -= 1
            moved = True
            if leaving != end:  # the walled-in end takes the leaving one's void
                other = next(v for v, e in heading.items() if e == leaving)
                heading[other] = end
            if reach == void:
                del heading[void]
            else:
                heading[void] = reach
            if legs <= 0 or deadline.expired():
                break
    return hops
