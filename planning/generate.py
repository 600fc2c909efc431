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


def polyhexes(size: int) -> list[frozenset[Cell]]:
    """Every connected configuration of ``size`` cells up to translation (the
    fixed polyhexes: 1, 3, 11, 44, 186, 814, ... for 1, 2, 3, ... cells), each
    placed with its smallest cell at (0, 0), in a fixed order."""
    shapes = {frozenset([(0, 0)])}
    for _ in range(size - 1):
        shapes = {_placed(shape | {n}) for shape in shapes for cell in shape
                  for n in neighbors(cell) if n not in shape}
    return sorted(shapes, key=sorted)


def _placed(cells: frozenset[Cell]) -> frozenset[Cell]:
    """``cells`` moved so that the smallest is at (0, 0)."""
    x0, y0 = min(cells)
    return frozenset((x - x0, y - y0) for x, y in cells)


def hub(size: int) -> frozenset[Cell]:
    """The compact configuration of ``size`` cells that every polyhex goes to
    and comes back from in ``hexbot bench planning --hub`` (the middle ball,
    placed like :func:`polyhexes` with its smallest cell at (0, 0))."""
    from hexbot.planning.middle import ball

    return _placed(ball((0, 0), size))


def blob_pair(size: int, seed: int,
              compact: float = 0.8) -> tuple[frozenset[Cell], frozenset[Cell]]:
    """The benchmark's "blob" family: two independent random blobs of ``size`` cells,
    both grown from (0, 0), the anchor they share (the fixed module with ``--fixed``)."""
    return random_blob(size, 2 * seed, compact), random_blob(size, 2 * seed + 1, compact)


def scramble(cells: frozenset[Cell], moves: int, seed: int,
             fixed: Cell | None = (0, 0)) -> frozenset[Cell]:
    """The benchmark's "scramble" family: the cells after ``moves`` random legal
    rotations (Table 4-3, never the ``fixed`` module), so the result is reachable
    from ``cells`` in at most ``moves`` moves. The movers are drawn among the
    surface modules whose neighbours form one arc (never cut vertices; a check
    needing no search keeps 10,000 modules fast)."""
    from hexbot.planning.robust import _moves_from, _single_arc

    rng = random.Random(seed)
    occupied = set(cells)
    surface: list[Cell] = []
    where: dict[Cell, int] = {}

    def update(cell: Cell) -> None:
        on = cell in occupied and cell != fixed and any(n not in occupied for n in neighbors(cell))
        if on and cell not in where:
            where[cell] = len(surface)
            surface.append(cell)
        elif not on and cell in where:
            last = surface.pop()
            slot = where.pop(cell)
            if last != cell:
                surface[slot] = last
                where[last] = slot

    for cell in sorted(occupied):
        update(cell)
    done = 0
    while done < moves:
        cell = surface[rng.randrange(len(surface))]
        options = [goal for _, _, goal in _moves_from(cell, occupied, cell)]
        if not options or not _single_arc(occupied, cell):
            continue
        goal = options[rng.randrange(len(options))]
        occupied.discard(cell)
        occupied.add(goal)
        for c in (cell, goal, *neighbors(cell), *neighbors(goal)):
            update(c)
        done += 1
    return frozenset(occupied)
