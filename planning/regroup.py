"""Shorter serial plans: a few modules' moves in a small area re-planned together.

The local flows work one fill at a time, so an area often sees a module
step aside, another take its cell, the first come back a different way.
:mod:`hexbot.planning.tidy` cuts one module's detours; it cannot see that
two modules' moves would be one roll of a third. This pass looks at runs
of consecutive moves whose cells (start, goal, swept, substrate) lie within
``REACH`` of each other, at most ``MOST`` of them, and searches (A* with
the assignment bound, every module outside the area fixed, modules
interchangeable) the fewest rotations that take the area from the
configuration before the run to the one after it. Fewer rotations replace
the run; the configuration after it is the same, so nothing later
changes. Module ids are replayed afterwards: a module other than the
planned one may make a move.

A search only moves a module that can leave (three free sides in a row,
its occupied neighbours in one arc, :data:`hexbot.planning.windows._LEAVABLE`)
and never the module bolted to the base, so every plan it makes is legal
whatever lies outside the area.

Each pass runs forwards, then over the plan turned round (from its end
back to the start, every rotation undone by the opposite one): the runs
then start at other moves and find other shortcuts.

Measured on the blobs of 1,000 (docs/planning.md, *Moves re-planned
together*): the makespan of seed 0 went from 547 to 323 steps, its moves
from 4,247 to 3,356; the runs in one corner that chain the schedule are
the runs this pass finds shorter. The search runs in C
(``planning/_regroup.c``).
"""

from __future__ import annotations

import numpy as np

from hexbot.planning import _regroup
from hexbot.planning.budget import NO_DEADLINE, Deadline
from hexbot.planning.canonical import replay
from hexbot.planning.configuration import Configuration
from hexbot.planning.hexlattice import ROTATIONS, Cell
from hexbot.planning.moves import Move, new_move
from hexbot.planning.robust import _AROUND12, ROTATION_MASKS, reverse_move
from hexbot.planning.schedule import _AROUND
from hexbot.planning.tidy import grid_frame, offset_distances, rotation_index, shorten
from hexbot.planning.windows import _LEAVABLE

#: Largest lattice distance between two cells of a run.
REACH = 8
#: Moves in a run at most.
MOST = 30
#: Rings of neighbours around a run's cells that a search may use.
PAD = 1
#: Moves between two runs' starts (runs overlap: a run cut short at one
#: start is whole at the next).
STRIDE = 5
#: Area states a search stores at most.
STATES = 20_000
#: Passes at most, each followed by tidy's (a shorter area opens detours).
PASSES = 3
#: Above this many moves a plan is left as it is (the strip's plans).
REGROUP_MOVES = 200_000

#: Cells between the plan's cells and the grid's edge: a rotation looks two
#: cells around its start, and an area grows ``PAD`` beyond them.
MARGIN = 5 + PAD

_regroup.set_rules(_AROUND12, ROTATION_MASKS, _AROUND, _LEAVABLE)


def regroup(initial: Configuration, moves: list[Move], fixed: Cell | None = None,
            deadline: Deadline = NO_DEADLINE) -> list[Move]:
    """``moves`` with runs of moves re-planned in fewer rotations, each pass
    followed by tidy's (see the module docstring). Returns ``moves`` itself
    above ``REGROUP_MOVES`` moves; stops early, with what it has so far, when
    the deadline comes."""
    if len(moves) > REGROUP_MOVES:
        return moves
    plan = list(moves)
    for _ in range(PASSES):
        before = len(plan)
        plan = shorten(initial, one_pass(initial, plan, fixed, deadline), deadline)
        plan = backwards_pass(initial, plan, fixed, deadline)
        if len(plan) == before or deadline.expired():
            break
    return plan


def backwards_pass(initial: Configuration, plan: list[Move], fixed: Cell | None = None,
                   deadline: Deadline = NO_DEADLINE) -> list[Move]:
    """:func:`one_pass` over the plan run backwards, from its end to
    ``initial`` (every rotation undone by the opposite one), turned round
    again: the runs start at other moves, and find other shortcuts (5-10 %
    fewer moves and steps on the blobs of 300 and 1,000 after a forward
    pass, docs/planning.md)."""
    if not plan:
        return []
    end = replay(initial, plan)
    back = one_pass(end, [reverse_move(m) for m in reversed(plan)], fixed, deadline)
    # the backward pass may send other modules than the plan did, so the
    # modules ending where ``initial`` has them are not always the same ones
    return _relabel(initial, [reverse_move(m) for m in reversed(back)])


def one_pass(initial: Configuration, plan: list[Move], fixed: Cell | None = None,
             deadline: Deadline = NO_DEADLINE) -> list[Move]:
    """One walk over ``plan`` re-planning its runs (``planning/_regroup.c``)."""
    if not plan:
        return []
    xmin, ymin, width, height = grid_frame(initial, plan, MARGIN)
    grid = bytearray(width * height)
    for x, y in initial.cells:
        grid[x - xmin + (y - ymin) * width] = 2 if (x, y) == fixed else 1
    encoded = np.empty(2 * len(plan), dtype=np.intc)
    for k, move in enumerate(plan):
        rot = rotation_index(move)
        x, y = move.src
        encoded[2 * k], encoded[2 * k + 1] = x - xmin + (y - ymin) * width, rot
    hops = _regroup.one_pass(width, height, grid, encoded, offset_distances(width, height),
                             REACH, MOST, PAD, STRIDE, STATES, deadline)
    return _replay(initial, hops, xmin, ymin, width)


def _replay(initial: Configuration, hops: list[tuple[int, int]], xmin: int, ymin: int,
            width: int) -> list[Move]:
    """Moves with module ids from (start, rotation) pairs, replayed from ``initial``."""
    where = {cell: module.id for cell, module in initial.items()}
    moves = []
    for start, rot in hops:
        rule = ROTATIONS[rot]
        x, y = xmin + start % width, ymin + start // width
        (gx, gy), (sx, sy) = rule.goal, rule.substrate
        dst, sub = (x + gx, y + gy), (x + sx, y + sy)
        module = where.pop((x, y))
        moves.append(new_move(module, (x, y), dst, rule.joint, rule.direction, sub, where[sub]))
        where[dst] = module
    return moves


def _relabel(initial: Configuration, moves: list[Move]) -> list[Move]:
    """``moves`` with the module ids a replay from ``initial`` finds at their cells."""
    where = {cell: module.id for cell, module in initial.items()}
    out = []
    for m in moves:
        module = where.pop(m.src)
        out.append(new_move(module, m.src, m.dst, m.joint, m.direction, m.substrate,
                            where[m.substrate]))
        where[m.dst] = module
    return out
