"""What a rotation needs, under the two motion models, and the wall-following rule.

Both models move a module by one row of Table 4-3
(:mod:`hexbot.protocol.rotation_geometry`): about a joint it shares with an
occupied substrate, clockwise or counterclockwise, into the goal cell next
to both. They differ in the cells that must be empty:

- ``deformable`` (the paper's, after Chirikjian): "a minimum of two
  contiguous sides adjacent to unoccupied cells": the goal and the first
  swept cell (the side next to the goal, away from the substrate).
- ``hexbot`` (our rigid modules): the goal and all three swept cells of
  Table 4-3, the third of which lies in the second ring.

The wall-following rule (:func:`next_rotation`) is the probing module's and
every moving module's: keep rotating about the last substrate while the
next cell is free, otherwise take the next occupied cell as the substrate.
A free cell that cannot be entered (a one-cell dent under the deformable
model, more under the HexBot model) is passed over as if it were occupied.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

from hexbot.protocol.lattice import Cell, side_towards, wrap
from hexbot.protocol.rotation_geometry import ROTATION_BY_KEY, ROTATIONS, Direction, Rotation

MODELS = ("deformable", "hexbot")


def opposite(direction: Direction) -> Direction:
    return "CCW" if direction == "CW" else "CW"


#: each rotation's (substrate, goal, swept) cells for a module at (0, 0)
_AT_ORIGIN = {rotation: rotation.at((0, 0)) for rotation in ROTATIONS}


def cells_at(rotation: Rotation, cell: Cell) -> tuple[Cell, Cell, tuple[Cell, Cell, Cell]]:
    """``rotation.at(cell)``: the cells at the origin moved to ``cell`` (the
    round engine asks for them some ten thousand times a run)."""
    (sx, sy), (gx, gy), ((ax, ay), (bx, by), (rx, ry)) = _AT_ORIGIN[rotation]
    x, y = cell
    return ((x + sx, y + sy), (x + gx, y + gy),
            ((x + ax, y + ay), (x + bx, y + by), (x + rx, y + ry)))


def required_empty(rotation: Rotation, cell: Cell, model: str) -> tuple[Cell, ...]:
    """Cells that must be empty for the module at ``cell`` to do ``rotation``."""
    _sub, goal, swept = cells_at(rotation, cell)
    return (goal, swept[0]) if model == "deformable" else (goal, *swept)


def body_cells(rotation: Rotation, cell: Cell, model: str) -> tuple[Cell, ...]:
    """Cells the module's body passes through, which no other move of the round
    may pass through or need empty. A rigid module sweeps all of Table 4-3's
    cells: its start, goal and three swept cells, the cells a move needs in the
    plan checker and the schedule (``planning.schedule.cells_of``, checked
    equal by a test). The paper's deformable module holds only its start and
    goal: two of them may share a free side (its Figs. 12-13 cross a channel
    that way)."""
    _sub, goal, swept = cells_at(rotation, cell)
    return (cell, goal) if model == "deformable" else (cell, goal, *swept)


@dataclass(frozen=True)
class Rolled:
    """One rotation chosen by the rule: from ``src`` to ``dst`` over ``substrate``."""

    src: Cell
    dst: Cell
    substrate: Cell
    rotation: Rotation


def rotation_to(goal_side: int, direction: Direction) -> Rotation:
    """The rotation of ``direction`` that ends on ``goal_side`` (Table 4-3 row)."""
    joint = wrap(goal_side + 1) if direction == "CW" else wrap(goal_side)
    return ROTATION_BY_KEY[(joint, direction)]


def next_rotation(cell: Cell, pivot: Cell | None, direction: Direction,
                  occupied: Callable[[Cell], bool], model: str,
                  avoid: Callable[[Cell], bool] = lambda _c: False) -> Rolled | None:
    """The wall-following move of a module at ``cell`` whose last substrate was
    ``pivot``: scanning away from the pivot (counterclockwise around the
    module for a CW roll, clockwise for CCW), the first goal that is free,
    not avoided and has what the model needs empty, with an occupied
    substrate behind it. None when there is none (the module is stuck)."""
    start = side_towards(cell, pivot) if pivot is not None else None
    if start is None:
        start = 1
    step = -1 if direction == "CW" else 1
    for k in range(1, 7):
        goal_side = wrap(start + step * k)
        rotation = rotation_to(goal_side, direction)
        substrate, goal, _swept = cells_at(rotation, cell)
        if not occupied(substrate) or avoid(goal):
            continue
        if any(occupied(c) for c in required_empty(rotation, cell, model)):
            continue
        return Rolled(cell, goal, substrate, rotation)
    return None
