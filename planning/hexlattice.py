"""Geometry of the hexagonal lattice in the thesis' axial coordinates.

Table 4-1 of the thesis (defined once in :mod:`hexbot.protocol.lattice`): a
cell is ``(x, y)``; its six sides are numbered 1..6 clockwise starting at the
upper left, and side ``s`` touches the neighbour ``(x, y) + SIDE_OFFSETS[s]``.
Joint ``j`` (a vertex) sits between sides ``j-1`` and ``j``. The hexagons
are flat-topped: x grows to the right (and half a cell up), y grows straight
up (see :func:`cartesian`).

The rotation move set of Table 4-3 is :mod:`hexbot.protocol.rotation_geometry`
(re-exported here); ``LETTER_CELLS`` names the cells around a mobile module
with the letters of Fig. 4-30, as the thesis' figures and table do.

The MATLAB listings store a configuration as a 0/1 matrix, row 1 on top:
the cell in row ``r``, column ``c`` of an ``R``-row matrix is the axial cell
``(c - 1, R - r)`` (``HexActuate``'s "Conversion to Hex coordinates").
"""

from __future__ import annotations

import math
from collections.abc import Iterable

from hexbot.protocol.lattice import (  # noqa: F401 - the planner's public vocabulary
    SIDE_OFFSETS,
    SIDES,
    Cell,
    distance,
    neighbor,
    side_towards,
    wrap,
)
from hexbot.protocol.lattice import facing as facing_side  # noqa: F401
from hexbot.protocol.rotation_geometry import (  # noqa: F401 - Table 4-3
    ROTATION_BY_KEY,
    ROTATIONS,
    Direction,
    Rotation,
    rotations_to,
)

JOINTS = SIDES

#: Largest |x| or |y| a configuration file may give. The planner's distance
#: arrays are int32 (|dx + dy| reaches 4x this) and a connected cluster of
#: N modules spans fewer than N cells, so this is far beyond any real plan;
#: the link's localization range (protocol.wire.LOC_COORD_LIMIT, 99) is the
#: executor's business, not the file reader's.
COORD_LIMIT = 1_000_000


# The offsets unpacked once: the planners ask for neighbours millions of times.
(_X1, _Y1), (_X2, _Y2), (_X3, _Y3), (_X4, _Y4), (_X5, _Y5), (_X6, _Y6) = (
    SIDE_OFFSETS[s] for s in SIDES)


def neighbors(cell: Cell) -> tuple[Cell, ...]:
    """The six neighbours in side order 1..6 (``HexNe``)."""
    x, y = cell
    return ((x + _X1, y + _Y1), (x + _X2, y + _Y2), (x + _X3, y + _Y3),
            (x + _X4, y + _Y4), (x + _X5, y + _Y5), (x + _X6, y + _Y6))


def ring_cell(cell: Cell, side: int) -> Cell:
    """The second-ring cell between the neighbours on ``side`` and ``side + 1``.

    These are G..L of Fig. 4-30: G between A and B, ..., L between F and A.
    """
    return neighbor(neighbor(cell, side), side + 1)


def rotate_cell(cell: Cell, steps: int, center: Cell = (0, 0)) -> Cell:
    """Rotate a cell about ``center`` by ``steps`` sixth-turns clockwise."""
    dx, dy = cell[0] - center[0], cell[1] - center[1]
    for _ in range(steps % 6):
        # one sixth-turn clockwise maps side s to side s+1: (dx, dy) -> (dx + dy, -dx)
        dx, dy = dx + dy, -dx
    return (center[0] + dx, center[1] + dy)


# --- Cartesian geometry (MATLAB ``Hex``) -------------------------------------

_YSCALE = 1 / math.sin(math.pi / 3)
_XSHEAR = math.tan(math.pi / 6)
CIRCUMRADIUS = 2 / 3


def cartesian(cell: Cell) -> tuple[float, float]:
    """Centre of a cell in the plane, as ``Hex`` of Appendix C places it."""
    x, y = cell
    return (float(x), y * _YSCALE + x * _XSHEAR)


def vertices(cell: Cell) -> list[tuple[float, float]]:
    """The six corners, corner ``j`` being joint ``j`` (1 = left, then clockwise)."""
    cx, cy = cartesian(cell)
    a, b = 1 / 3, 1 / (3 * math.tan(math.pi / 6))
    return [
        (cx - 2 * a, cy),
        (cx - a, cy + b),
        (cx + a, cy + b),
        (cx + 2 * a, cy),
        (cx + a, cy - b),
        (cx - a, cy - b),
    ]


# --- MATLAB matrix form ------------------------------------------------------


def matrix_to_cells(rows: list[list[int]]) -> set[Cell]:
    """Cells of a 0/1 matrix given as rows, row 1 on top."""
    height = len(rows)
    return {
        (c, height - 1 - r) for r, row in enumerate(rows) for c, value in enumerate(row) if value
    }


def cells_to_matrix(
    cells: Iterable[Cell], origin: Cell = (0, 0), shape: tuple[int, int] | None = None
) -> list[list[int]]:
    """0/1 rows (row 1 on top) whose bottom-left cell is ``origin``.

    Without ``shape`` the matrix is the smallest that holds every cell.
    """
    cells = list(cells)
    ox, oy = origin
    if shape is None:
        width = max((x - ox for x, _ in cells), default=-1) + 1
        height = max((y - oy for _, y in cells), default=-1) + 1
    else:
        height, width = shape
    rows = [[0] * width for _ in range(height)]
    for x, y in cells:
        r, c = height - 1 - (y - oy), x - ox
        if not (0 <= r < height and 0 <= c < width):
            raise ValueError(f"cell {(x, y)} is outside a {height}x{width} matrix at {origin}")
        rows[r][c] = 1
    return rows


def column_major_key(cell: Cell) -> tuple[int, int]:
    """Sort key giving MATLAB's ``find`` order: by column, then row from the top."""
    return (cell[0], -cell[1])


# --- Fig. 4-30: the cells around a mobile module ---------------------------

#: Fig. 4-30 letters as positions around the mobile module at (0, 0):
#: A..F are the neighbours on sides 1..6, G..L the second-ring cells between
#: consecutive neighbours (``HexActuate`` lists the same offsets in MATLAB form).
LETTER_CELLS: dict[str, Cell] = {
    **{letter: SIDE_OFFSETS[s] for letter, s in zip("ABCDEF", SIDES, strict=True)},
    **{letter: ring_cell((0, 0), s) for letter, s in zip("GHIJKL", SIDES, strict=True)},
}
