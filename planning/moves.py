"""Single-module rotations on the lattice: which are legal, what they actuate.

A rotation of the module at ``cell`` follows one row of Table 4-3: an
occupied substrate cell, an empty goal cell and three empty swept cells.
Layer 5 of the thesis adds the magnet polarities (``HexActuate``'s ``Fs``,
Table 3-1): the mobile module drives both sides next to the pivot joint
negative; the substrate drives the side facing the mobile negative and the
next one (towards the goal) positive.
"""

from __future__ import annotations

from dataclasses import dataclass, fields

from hexbot.planning import _strip
from hexbot.planning.hexlattice import ROTATION_BY_KEY, Cell, Direction, Rotation, wrap


@dataclass(frozen=True, slots=True)
class Move:
    """One rotation of one module. ``joint`` is the pivot, numbered in the global
    frame as a joint of the mobile module (Table 4-3).

    Slots, no ``__dict__``: a strip plan of 10,000 modules holds about five
    million of them (88 bytes each instead of about 250)."""

    module: int
    src: Cell
    dst: Cell
    joint: int
    direction: Direction
    substrate: Cell
    substrate_module: int

    def swept(self) -> tuple[Cell, ...]:
        rule = rule_of(self)
        return rule.at(self.src)[2]

    def footprint(self) -> set[Cell]:
        """Cells the rotation needs: where it starts and ends and what it sweeps."""
        return {self.src, self.dst, *self.swept()}


_strip.set_move_type(Move, [f.name for f in fields(Move)])
#: ``Move(...)`` without the frozen dataclass's ``__init__`` (``planning/_strip.c``):
#: 0.4 us a move instead of 2.5, for the planners that make millions (strip
#: routes, their reversal, the direct method).
new_move = _strip.new_move


def rule_of(move: Move) -> Rotation:
    rule = ROTATION_BY_KEY.get((move.joint, move.direction))
    if rule is not None:
        return rule
    raise ValueError(f"no rotation about joint {move.joint} {move.direction}")


@dataclass(frozen=True)
class Magnets:
    """Layer 5 polarities in the global frame: side numbers of each module."""

    mobile_negative: tuple[int, int]
    substrate_negative: int
    substrate_positive: int


def magnets(joint: int, direction: Direction) -> Magnets:
    """``HexActuate``'s ``Fs`` for a rotation about ``joint`` (Table 3-1)."""
    mobile = (wrap(joint), wrap(joint - 1))
    if direction == "CW":
        return Magnets(mobile, wrap(joint - 3), wrap(joint - 2))
    return Magnets(mobile, wrap(joint + 2), wrap(joint + 1))


#: Per direction, how a rotation turns the mobile module's body, in sixth-turns
#: clockwise (``Rotation.turn``: the same for every joint).
TURN: dict[str, int] = {r.direction: r.turn for r in ROTATION_BY_KEY.values()}


def orientation_after(orientation: int, direction: Direction) -> int:
    """A 120-degree rotation turns the mobile module's body by two sides
    (clockwise adds two to Yref)."""
    return (orientation + TURN[direction]) % 6
