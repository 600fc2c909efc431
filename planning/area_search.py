"""Searches over a small area, every module outside it fixed (``planning/_regroup.c``).

Two kinds, one A* in C over the area's states (a bit per cell, at most 128
cells; modules interchangeable, only a module with three free sides in a
row moves, never the bolted one):

* :func:`move_in_area` (the finish's legs, :mod:`hexbot.planning.finish`):
  the fewest rotations to a given set of occupied cells;
* :func:`improve_in_area` (the window fixes, :mod:`hexbot.planning.windows`):
  the fewest rotations, or one more, after which fewer of the area's cells
  are wrong (a module off the goal, or a goal cell empty).

This module builds the grid the C side reads (the area's bounding box and
``MARGIN`` cells around it, since a rotation looks two cells around its
start) and turns the (start, rotation) pairs it returns back into hops.
"""

from __future__ import annotations

import numpy as np

from hexbot.planning import _regroup
from hexbot.planning.hexlattice import ROTATIONS, Cell
from hexbot.planning.regroup import MARGIN
from hexbot.planning.tidy import offset_distances
from hexbot.planning.windows import Hop

#: Cells of an area at most (a state is two 64-bit words; the C side's limit).
AREA = _regroup.AREA


class Grid:
    """The occupancy around an area, as the C searches read it."""

    def __init__(self, occupied: set[Cell] | frozenset[Cell], area: set[Cell],
                 fixed: Cell | None):
        xs = [x for x, _ in area]
        ys = [y for _, y in area]
        self.xmin, self.ymin = min(xs) - MARGIN, min(ys) - MARGIN
        self.width = max(xs) - self.xmin + MARGIN + 1
        self.height = max(ys) - self.ymin + MARGIN + 1
        self.cells = bytearray(self.width * self.height)
        for y in range(self.height):
            for x in range(self.width):
                cell = (x + self.xmin, y + self.ymin)
                if cell in occupied:
                    self.cells[x + y * self.width] = 2 if cell == fixed else 1
        self.distances = offset_distances(self.width, self.height)

    def index(self, cell: Cell) -> int:
        return cell[0] - self.xmin + (cell[1] - self.ymin) * self.width

    def indices(self, cells) -> np.ndarray:
        return np.array([self.index(c) for c in cells], dtype=np.intc)

    def hops(self, found: list[tuple[int, int]]) -> list[Hop]:
        """The C search's (start, rotation) pairs as hops on the lattice."""
        out: list[Hop] = []
        for start, rot in found:
            rule = ROTATIONS[rot]
            x, y = self.xmin + start % self.width, self.ymin + start // self.width
            (gx, gy), (sx, sy) = rule.goal, rule.substrate
            out.append(((x, y), (x + gx, y + gy), rule, (x + sx, y + sy)))
        return out


def move_in_area(occupied: set[Cell], area: set[Cell], target: set[Cell],
                 fixed: Cell | None, states: int, limit: int,
                 outside: dict[Cell, int] | None = None) -> list[Hop] | None:
    """The fewest rotations, fewer than ``limit``, inside ``area`` after which
    exactly ``target`` of its cells are occupied, or None (none within
    ``states`` area states, or an area of more than ``AREA`` cells).
    ``outside``: the piece (0, 1, ...) of the modules outside the area that
    each module touching it belongs to; with it, a module whose neighbours
    form several arcs may move when the pieces stay joined."""
    if len(area) > AREA:
        return None
    grid = Grid(occupied, area, fixed)
    order = sorted(area)
    labels = None
    count = 0
    if outside is not None:
        labels = np.full(grid.width * grid.height, -1, dtype=np.intc)
        for cell, label in outside.items():
            labels[grid.index(cell)] = label
        count = max(outside.values(), default=-1) + 1
    found = _regroup.search_area(
        grid.width, grid.height, grid.cells, grid.distances, grid.indices(order),
        grid.indices([c for c in order if c in target]), labels, count, states, limit)
    return None if found is None else grid.hops(found)


#: Rotations of one window fix at most (the C search's limit).
IMPROVE_ROTATIONS = 100


def improve_in_area(occupied: set[Cell], goal: frozenset[Cell], area: set[Cell],
                    fixed: Cell | None, states: int) -> list[Hop] | None:
    """The fewest rotations (or one more: the A* tests a state when it reaches
    it) inside ``area`` after which fewer of its cells are wrong (a module off
    ``goal``, or a goal cell empty), or None (none within
    ``states`` area states, or an area of more than ``AREA`` cells). Only a
    module whose occupied neighbours form one arc moves."""
    if len(area) > AREA:
        return None
    grid = Grid(occupied, area, fixed)
    order = sorted(area)
    found = _regroup.improve_area(
        grid.width, grid.height, grid.cells, grid.distances, grid.indices(order),
        grid.indices([c for c in order if c in goal]), None, 0, states, IMPROVE_ROTATIONS)
    return None if found is None else grid.hops(found)
