"""The configuration a local planner works on, and the moves it has made.

The local planners (:mod:`hexbot.planning.flow`, :mod:`hexbot.planning.windows`)
think in cells; the plan needs module ids. A :class:`Tracker` keeps both:
the occupied cells, which module stands on each, and the serial
:class:`~hexbot.planning.moves.Move` list, appended as rotations are applied.
"""

from __future__ import annotations

from hexbot.planning.budget import PlanningFailure
from hexbot.planning.configuration import Configuration
from hexbot.planning.hexlattice import ROTATIONS, Cell
from hexbot.planning.moves import Move, new_move

#: One rotation: (from, to, Table 4-3 row, substrate cell).
Hop = tuple[Cell, Cell, object, Cell]

_ROW = {(r.joint, r.direction): r for r in ROTATIONS}


class Tracker:
    def __init__(self, initial: Configuration, max_moves: int) -> None:
        self.occupied: set[Cell] = set(initial.cells)
        self.ids: dict[Cell, int] = {c: m.id for c, m in initial.items()}
        self.moves: list[Move] = []
        self.max_moves = max_moves
        #: where each roll's moves begin (a journey, or a planner's group of hops)
        self.rolls: list[int] = []

    def roll(self, hops: list[Hop]) -> None:
        """Apply rotations in order (one module's journey, or several modules' hops)."""
        if len(self.moves) + len(hops) > self.max_moves:
            raise PlanningFailure(f"more than {self.max_moves} moves needed")
        self.rolls.append(len(self.moves))
        for src, dst, rule, sub in hops:
            module = self.ids.pop(src)
            self.moves.append(new_move(module, src, dst, rule.joint, rule.direction, sub,
                                       self.ids[sub]))
            self.ids[dst] = module
            self.occupied.discard(src)
            self.occupied.add(dst)

    def undo_to(self, count: int) -> None:
        """Take back the moves after the first ``count`` (a planner backtracking)."""
        while self.rolls and self.rolls[-1] >= count:
            self.rolls.pop()
        while len(self.moves) > count:
            move = self.moves.pop()
            self.ids[move.src] = self.ids.pop(move.dst)
            self.occupied.discard(move.dst)
            self.occupied.add(move.src)

    def rolled(self) -> list[list[Hop]]:
        """The rotations of each roll so far, in order."""
        ends = self.rolls[1:] + [len(self.moves)] if self.rolls else []  # no roll yet: none
        return [[(m.src, m.dst, _ROW[m.joint, m.direction], m.substrate)
                 for m in self.moves[begin:end]]
                for begin, end in zip(self.rolls, ends, strict=True)]
