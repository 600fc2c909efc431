"""Seeded random configurations for tests and benchmarks.

``random_blob`` grows a connected set cell by cell from (0, 0): each new
cell is a random empty neighbour of the set, drawn with ``random.Random(seed)``,
so the same (size, seed) always gives the same configuration.
``holey_blob`` is such a blob with holes: empty pockets that the shape
encloses, which a module can enter or leave only once a side of the pocket
is opened (the bench's "holes" family).
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


#: Sizes a hole is drawn from (cells): mostly single cells, as a lost module
#: leaves, some larger pockets. At most 7: a hole that size cannot enclose
#: more than one cell, so :func:`holey_blob`'s local check keeps it one piece.
HOLE_SIZES = (1, 1, 1, 2, 2, 3, 4, 5, 7)


def holey_blob(size: int, seed: int, compact: float = 0.8,
               hole_share: float = 0.04) -> frozenset[Cell]:
    """A connected set of ``size`` cells (at least 7) with holes: about
    ``hole_share`` x ``size`` cells (at least one) are empty pockets that the
    set encloses, each of 1-7 cells, two or more cells apart.

    A random blob of ``size`` cells is grown from (0, 0); holes are carved out
    of its interior (cells whose six neighbours are occupied; never (0, 0)),
    and the set grows back to ``size`` round its border, never into a hole.
    A blob too small to have an interior cell is grown round a single hole
    next to (0, 0) instead."""
    if size < 7:
        raise ValueError(f"a shape with a hole has at least 7 cells, got {size}")
    rng = random.Random(seed)
    cells = set(random_blob(size, seed, compact))
    inner = sorted(c for c in cells if c != (0, 0) and all(n in cells for n in neighbors(c)))
    want = max(1, round(hole_share * size))
    holes: set[Cell] = set()
    near: set[Cell] = set()  # within two cells of a hole: no other hole there
    tries = 0
    while len(holes) < want and inner and tries < 20 * want:
        tries += 1
        first = inner[rng.randrange(len(inner))]
        if first in near:
            continue
        hole = [first]
        for _ in range(min(rng.choice(HOLE_SIZES), want - len(holes)) - 1):
            grow = sorted({n for h in hole for n in neighbors(h)}
                          .difference(hole, near).intersection(inner))
            if not grow:
                break
            hole.append(rng.choice(grow))
        if any(all(n in hole for n in neighbors(c)) for h in hole for c in neighbors(h)
               if c not in hole):
            continue  # a ring round a cell would cut it off
        cells.difference_update(hole)
        holes.update(hole)
        near.update(m for h in hole for n in neighbors(h) for m in neighbors(n))
    if not holes:  # too small for an interior cell: a ring round a neighbour of (0, 0)
        hole_cell = neighbors((0, 0))[rng.randrange(6)]
        cells, holes = set(neighbors(hole_cell)), {hole_cell}
    # grow back as random_blob grows, never into a hole
    frontier: dict[Cell, int] = {}
    for c in cells:
        for n in neighbors(c):
            if n not in cells and n not in holes:
                frontier[n] = frontier.get(n, 0) + 1
    while len(cells) < size:
        options = sorted(frontier)
        cell = rng.choices(options, [1.0 + compact * 4 * (frontier[c] - 1) for c in options])[0]
        del frontier[cell]
        cells.add(cell)
        for n in neighbors(cell):
            if n not in cells and n not in holes:
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


def holes_pair(size: int, seed: int,
               compact: float = 0.8) -> tuple[frozenset[Cell], frozenset[Cell]]:
    """The benchmark's "holes" family: two independent :func:`holey_blob` of
    ``size`` cells sharing (0, 0), as :func:`blob_pair`."""
    return holey_blob(size, 2 * seed, compact), holey_blob(size, 2 * seed + 1, compact)


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
