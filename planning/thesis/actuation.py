"""Layer 5: from a recommended next location to a rotation (``HexActuate``).

The twelve rows of Table 4-3 are tried in the listing's order (CW joints
1..6, then CCW joints 1..6); the listing has no ``break``, so the *last*
row that fits wins. A row fits when its substrate cell is occupied, its
three swept cells are empty and its goal is the next location. Like the
listing, the goal cell itself is not checked, and any module can serve as
substrate (even one that moves in the same parallel step).
"""

from __future__ import annotations

from hexbot.planning.hexlattice import ROTATIONS, Cell, Rotation


def hex_actuate(
    src: Cell, dst: Cell, occupied: frozenset[Cell]
) -> tuple[Rotation, Cell] | None:
    """(rule, substrate cell) to go from ``src`` to ``dst``, or None."""
    chosen = None
    for rule in ROTATIONS:
        sub, goal, swept = rule.at(src)
        if goal != dst:
            continue
        if sub in occupied and not any(s in occupied for s in swept):
            chosen = (rule, sub)
    return chosen
