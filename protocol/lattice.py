"""The hex lattice as the protocol speaks of it: Table 4-1 and Table 3-5.

MSG1 carries axial coordinates and sides in these terms, the firmware's
localization and IR selector follow them, and the simulator and planner
build on them; this module is their one definition.

- A cell is ``(x, y)``; sides are numbered 1..6 clockwise and side ``s``
  touches the neighbour at ``(x, y) + SIDE_OFFSETS[s]``, which touches back
  with side ``s + 3`` (Table 4-1). Joint ``j`` is the vertex between sides
  ``j - 1`` and ``j``.
- Orientation (the firmware's Yref, 0..5): a module with orientation ``o``
  has its body side ``b`` on global side ``((b - 1 + o) mod 6) + 1``; one
  that hears MSG1 on body side ``j`` through global side ``S`` has
  ``o = (S - j) mod 6``.
- The IR channel selector (Table 3-5): index ``Y = 4C + 2B + A`` picks a
  transceiver; ``CENTRE`` is the one facing the PC.
"""

from __future__ import annotations

Cell = tuple[int, int]

SIDES = (1, 2, 3, 4, 5, 6)

#: Table 4-1: neighbour offset for each side.
SIDE_OFFSETS: dict[int, Cell] = {
    1: (-1, 1),
    2: (0, 1),
    3: (1, 0),
    4: (1, -1),
    5: (0, -1),
    6: (-1, 0),
}
_OFFSET_TO_SIDE = {offset: side for side, offset in SIDE_OFFSETS.items()}

#: Table 3-5: IR channel selector index Y (4C + 2B + A) -> side; 0 = centre (PC).
CENTRE = 0
CHANNEL_SIDE: dict[int, int | None] = {
    0: 1,
    1: 6,
    2: CENTRE,
    3: 2,
    4: 5,
    5: 3,
    6: 4,
    7: None,  # Y7 has no transceiver: deaf and mute
}
SIDE_CHANNEL: dict[int, int] = {side: y for y, side in CHANNEL_SIDE.items() if side is not None}


def wrap(side: int) -> int:
    """Any integer onto 1..6 (side and joint numbers wrap around)."""
    return (side - 1) % 6 + 1


def facing(side: int) -> int:
    """The side of the neighbour that touches ``side`` (s + 3)."""
    return wrap(side + 3)


def neighbor(cell: Cell, side: int) -> Cell:
    dx, dy = SIDE_OFFSETS[wrap(side)]
    return (cell[0] + dx, cell[1] + dy)


def side_towards(a: Cell, b: Cell) -> int | None:
    """The side of ``a`` touching ``b``; None when they are not adjacent."""
    return _OFFSET_TO_SIDE.get((b[0] - a[0], b[1] - a[1]))


def to_global(body_side: int, orientation: int) -> int:
    """Body side of a module with ``orientation`` -> global side."""
    return wrap(body_side + orientation)


def to_body(global_side: int, orientation: int) -> int:
    """Global side -> body side of a module with ``orientation``."""
    return wrap(global_side - orientation)


def turn(cell: Cell, sides: int) -> Cell:
    """``cell`` turned about the origin by ``sides`` sides clockwise (60
    degrees each; negative: anticlockwise): side ``s``'s offset becomes side
    ``s + sides``'s."""
    x, y = cell
    for _ in range(sides % 6):
        x, y = x + y, -x
    return (x, y)


def distance(a: Cell, b: Cell) -> int:
    """Lattice distance (number of side steps) between two cells."""
    dx, dy = b[0] - a[0], b[1] - a[1]
    return (abs(dx) + abs(dy) + abs(dx + dy)) // 2
