"""Hex-lattice geometry the simulator needs, in the thesis' axial coordinates.

Table 4-1: a cell is ``(x, y)``; sides are numbered 1..6 clockwise and side
``s`` touches the neighbour at ``(x, y) + SIDE_OFFSETS[s]``; the neighbour
touches back with its side ``s + 3``. Joint ``j`` is the vertex between sides
``j - 1`` and ``j``.

Orientation convention (shared with the firmware's Yref): a module with
orientation ``o`` (0..5) has its body side ``b`` on global side
``((b - 1 + o) mod 6) + 1``. A module that hears MSG1 on body side ``j``
through global side ``S`` therefore has ``o = (S - j) mod 6``.

The planner keeps its own copy of this geometry in ``planning/``; the
simulator does not import the planner, so the two stay independent checks of
each other.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

Cell = tuple[int, int]
Direction = Literal["CW", "CCW"]

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
    """Any integer onto 1..6 (side or joint numbers wrap around)."""
    return (side - 1) % 6 + 1


def facing(side: int) -> int:
    """The side of the neighbour that touches ``side``."""
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


def joint_between(side_a: int, side_b: int) -> int:
    """The joint (vertex) shared by two adjacent sides of one module."""
    a, b = wrap(side_a), wrap(side_b)
    if wrap(a + 1) == b:
        return b
    if wrap(b + 1) == a:
        return a
    raise ValueError(f"sides {side_a} and {side_b} are not adjacent")


@dataclass(frozen=True)
class Pivot:
    """A rotation of a mobile module about one of its joints (Table 4-3).

    All sides are global. CW about joint ``j``: substrate on side ``j``, goal
    on side ``j - 1``, swept cells on sides ``j - 2``, ``j - 3`` and the
    second-ring cell beyond the goal and side ``j - 2``. CCW mirrors it:
    substrate on ``j - 1``, goal on ``j``, swept ``j + 1``, ``j + 2`` and the
    ring cell beyond them. A CW rotation turns the module 120 degrees
    clockwise: its orientation grows by 2.
    """

    joint: int  # global joint index of the mobile module's pivot vertex
    direction: Direction

    @property
    def substrate_side(self) -> int:
        return wrap(self.joint) if self.direction == "CW" else wrap(self.joint - 1)

    @property
    def goal_side(self) -> int:
        return wrap(self.joint - 1) if self.direction == "CW" else wrap(self.joint)

    @property
    def turn(self) -> int:
        """Orientation change in sixth-turns clockwise."""
        return 2 if self.direction == "CW" else -2

    def swept(self, cell: Cell) -> tuple[Cell, Cell, Cell]:
        """Cells the module passes through on its way to the goal (goal excluded)."""
        if self.direction == "CW":
            near, far = wrap(self.joint - 2), wrap(self.joint - 3)
        else:
            near, far = wrap(self.joint + 1), wrap(self.joint + 2)
        ring = neighbor(neighbor(cell, self.goal_side), near)
        return (neighbor(cell, near), neighbor(cell, far), ring)

    def goal(self, cell: Cell) -> Cell:
        return neighbor(cell, self.goal_side)

    def substrate(self, cell: Cell) -> Cell:
        return neighbor(cell, self.substrate_side)


def distance(a: Cell, b: Cell) -> int:
    dx, dy = b[0] - a[0], b[1] - a[1]
    return (abs(dx) + abs(dy) + abs(dx + dy)) // 2
