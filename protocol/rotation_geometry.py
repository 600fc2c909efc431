"""Table 4-3: which cells a rotation needs, for a mobile module about one of
its joints, clockwise or counterclockwise.

A mobile module pivots 120 degrees about a joint (vertex) it shares with its
substrate. All sides and joints here are global (lattice frame, Table 4-1):

- CW about joint ``j``: substrate on side ``j``, goal on side ``j - 1``;
  the module sweeps the cells on sides ``j - 2`` and ``j - 3`` and the
  second-ring cell beyond the goal and side ``j - 2``.
- CCW about joint ``j`` mirrors it: substrate on side ``j - 1``, goal on
  side ``j``; swept ``j + 1``, ``j + 2`` and the ring cell beyond the goal
  and side ``j + 1``.

The swept cells (the thesis' "empty locations") must be empty, the goal
too. A CW rotation turns the module clockwise: its orientation grows by 2.
The planner checks moves with these rows, the simulator's plant moves
modules by them; tests/protocol checks them against the printed table.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

from hexbot.protocol.lattice import SIDES, Cell, neighbor, wrap

Direction = Literal["CW", "CCW"]
DIRECTIONS: tuple[Direction, ...] = ("CW", "CCW")


@dataclass(frozen=True)
class Rotation:
    """One row of Table 4-3: a rotation about global ``joint``."""

    joint: int
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

    def substrate_cell(self, cell: Cell) -> Cell:
        return neighbor(cell, self.substrate_side)

    def goal_cell(self, cell: Cell) -> Cell:
        return neighbor(cell, self.goal_side)

    def swept_cells(self, cell: Cell) -> tuple[Cell, Cell, Cell]:
        """Cells the module passes through on its way to the goal (goal excluded)."""
        step = -1 if self.direction == "CW" else 1
        near, far = wrap(self.goal_side + step), wrap(self.goal_side + 2 * step)
        ring = neighbor(self.goal_cell(cell), near)
        return (neighbor(cell, near), neighbor(cell, far), ring)

    def at(self, cell: Cell) -> tuple[Cell, Cell, tuple[Cell, Cell, Cell]]:
        """(substrate cell, goal cell, swept cells) for a mobile module at ``cell``."""
        return self.substrate_cell(cell), self.goal_cell(cell), self.swept_cells(cell)

    # Offsets from the mobile module, the form the planner's move tables use.
    @property
    def substrate(self) -> Cell:
        return self.substrate_cell((0, 0))

    @property
    def goal(self) -> Cell:
        return self.goal_cell((0, 0))

    @property
    def swept(self) -> tuple[Cell, Cell, Cell]:
        return self.swept_cells((0, 0))


#: The twelve rotations in the order of Table 4-3 (and of ``HexActuate``):
#: CW about joints 1..6, then CCW about joints 1..6.
ROTATIONS: tuple[Rotation, ...] = tuple(Rotation(j, d) for d in DIRECTIONS for j in SIDES)
ROTATION_BY_KEY: dict[tuple[int, str], Rotation] = {(r.joint, r.direction): r for r in ROTATIONS}


def rotations_to(goal_side: int) -> list[Rotation]:
    """The two rotations that end on ``goal_side`` (CW about joint s+1, CCW about s)."""
    return [r for r in ROTATIONS if r.goal_side == wrap(goal_side)]


def joint_between(side_a: int, side_b: int) -> int:
    """The joint (vertex) shared by two adjacent sides of one module."""
    a, b = wrap(side_a), wrap(side_b)
    if wrap(a + 1) == b:
        return b
    if wrap(b + 1) == a:
        return a
    raise ValueError(f"sides {side_a} and {side_b} are not adjacent")
