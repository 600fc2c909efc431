"""Seeded random configurations for tests and benchmarks.

``random_blob`` grows a connected set cell by cell from (0, 0): each new
cell is a random empty neighbour of the set, drawn with ``random.Random(seed)``,
so the same (size, seed) always gives the same configuration.
"""

from __future__ import annotations

import random

from hexbot.planning.hexlattice import Cell, neighbors


def random_blob(size: int, seed: int, compact: float = 0.5) -> frozenset[Cell]:
    """A connected set of ``size`` cells. ``compact`` (0..1) favours frontier
    cells with many occupied neighbours, which gives rounder, hole-free shapes."""
    rng = random.Random(seed)
    cells: set[Cell] = {(0, 0)}
    frontier: dict[Cell, int] = {n: 1 for n in neighbors((0, 0))}
    while len(cells) < size:
        options = sorted(frontier)
        weights = [1.0 + compact * 4 * (frontier[c] - 1) for c in options]
        cell = rng.choices(options, weights)[0]
        del frontier[cell]
        cells.add(cell)
        for n in neighbors(cell):
            if n not in cells:
                frontier[n] = frontier.get(n, 0) + 1
    return frozenset(cells)


def parallelogram(width: int, height: int, origin: Cell = (0, 0)) -> frozenset[Cell]:
    """``width`` x ``height`` cells along the x and y axes."""
    ox, oy = origin
    return frozenset((ox + x, oy + y) for x in range(width) for y in range(height))
