"""Bubbles: can an empty pocket walk through a solid block on its own?

A hole of a configuration is a pocket of empty cells that modules enclose.
Inside a solid block the only moves near it are rotations of the modules
round it into it: a rotation needs its goal cell and its three swept cells
free (Table 4-3), so the pocket must hold all four, and the mover's cell
joins the pocket as the goal cell leaves it. :func:`travelling_bubbles`
searches every pocket shape of ``size`` cells for a sequence of such moves
that brings the pocket back to its own shape somewhere else: a pocket that
can do that can walk, one that cannot stays within a few cells for ever.

Used in docs/planning.md (*Shapes with holes*): no pocket of up to 7 cells
can walk, so every hole of a shape moves only by a dig from its surface.
"""

from __future__ import annotations

from collections import deque
from collections.abc import Iterator

from hexbot.planning.hexlattice import Cell, neighbors
from hexbot.protocol.rotation_geometry import ROTATIONS

Pocket = frozenset[Cell]


def _placed(cells: set[Cell] | frozenset[Cell]) -> tuple[Pocket, Cell]:
    """The pocket moved so its smallest cell is (0, 0), and where that was."""
    x0, y0 = min(cells)
    return frozenset((x - x0, y - y0) for x, y in cells), (x0, y0)


def pocket_shapes(size: int) -> set[Pocket]:
    """Every connected pocket of ``size`` cells, up to translation."""
    shapes = {frozenset([(0, 0)])}
    for _ in range(size - 1):
        shapes = {_placed(shape | {n})[0] for shape in shapes for cell in shape
                  for n in neighbors(cell) if n not in shape}
    return shapes


def _moves(pocket: Pocket) -> Iterator[Pocket]:
    """The pockets one rotation of a module round ``pocket`` leaves (every
    cell outside the pocket holds a module)."""
    for mover in {n for c in pocket for n in neighbors(c)} - pocket:
        for rotation in ROTATIONS:
            substrate, goal, swept = rotation.at(mover)
            if substrate not in pocket and goal in pocket and all(c in pocket for c in swept):
                yield (pocket - {goal}) | {mover}


def travels(shape: Pocket) -> bool:
    """Can the pocket ``shape`` reach a translate of itself (and so walk)?"""
    seen: dict[Pocket, Cell] = {shape: (0, 0)}
    queue = deque([shape])
    while queue:
        pocket = queue.popleft()
        dx, dy = seen[pocket]
        for after in _moves(frozenset((x + dx, y + dy) for x, y in pocket)):
            placed, offset = _placed(after)
            if placed not in seen:
                seen[placed] = offset
                queue.append(placed)
            elif seen[placed] != offset:
                return True
    return False


def travelling_bubbles(size: int) -> list[Pocket]:
    """The pocket shapes of ``size`` cells that can walk through a solid block
    (none up to 7 cells: 1.8 s for the 814 shapes of 6, 12 s for the 3,652 of 7)."""
    return sorted((s for s in pocket_shapes(size) if travels(s)), key=sorted)
