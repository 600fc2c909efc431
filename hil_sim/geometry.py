"""Hex-lattice geometry the simulator needs, in the thesis' axial coordinates.

Cells, sides, orientations and the IR selector are defined once in
:mod:`hexbot.protocol.lattice` (Tables 4-1 and 3-5) and re-exported here;
this module adds what only the plant needs: joints and the rotation pivots
of Table 4-3.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

from hexbot.protocol.lattice import (  # noqa: F401 - re-exported for the simulator
    CENTRE,
    CHANNEL_SIDE,
    SIDE_CHANNEL,
    SIDE_OFFSETS,
    SIDES,
    Cell,
    distance,
    facing,
    neighbor,
    side_towards,
    to_body,
    to_global,
    wrap,
)

Direction = Literal["CW", "CCW"]


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
