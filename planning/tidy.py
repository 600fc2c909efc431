"""Shorter serial plans: detours that nothing needed are cut short.

The local flows leave detours behind: a wall module steps aside for a
crossing and comes back, a traveller backs out of a dead end, a module
fills a cell and leaves it again when the flow changes its mind. Take a
module's moves from its ``i``-th move (leaving cell X) to a later one
(arriving at cell Y), and the other modules' moves in between. If those
stay legal with the module still at X (Table 4-3's cells free, the
substrate in place, the rest one piece), and the module can then roll from
X to Y, with the others fixed, in fewer rotations than it made, the plan
with that roll instead is legal and shorter. After the roll both plans are
in the same configuration, so nothing later changes. X = Y is a round trip:
the roll is empty.

Measured on the bench's scrambles and blobs (docs/planning.md): 10-20 %
fewer moves on the local plans, and the makespan of the 1,000-module
scrambles from 26.8 and 17.7 to 16.0 and 11.3 times the bottleneck bound:
the detours were often on the plan's critical path. The strip's plans are
not tidied: their journeys are shortest rolls already (1-3 % came off, at
12 s for 5,000 moves of one).

Each pass runs in C (``planning/_tidy.c``) over a grid of module numbers:
in Python a pass over a blob of 1,000 (5,000-6,000 moves) took about 2 s,
so until session 18 plans of more than 3,000 moves were left as they were,
the blobs of 1,000 among them. tests/planning/tidy_reference.py keeps the
Python pass; the two make the same plans, move for move.
"""

from __future__ import annotations

from array import array

import numpy as np

from hexbot.planning import _tidy
from hexbot.planning.budget import NO_DEADLINE, Deadline
from hexbot.planning.configuration import Configuration
from hexbot.planning.hexlattice import ROTATIONS, distance
from hexbot.planning.moves import Move, new_move
from hexbot.planning.robust import _AROUND12, ROTATION_MASKS
from hexbot.planning.schedule import _AROUND, _ONE_ARC

#: Above this many moves a plan is left as it is. The local plans of 2,000
#: modules (``JOURNEY_LIMIT``) stay below it; a pass costs at most
#: ``WINDOW`` replayed moves per move.
TIDY_MOVES = 200_000

#: Moves scanned after a module's move for a later one to shortcut to.
WINDOW = 1_000

#: Passes over the plan at most (a shortcut can open another one earlier on).
PASSES = 4

#: Moves between two looks at the deadline.
DEADLINE_EVERY = 64

#: Cells between the plan's cells and the grid's edge: a roll stays next to
#: the modules, and a rotation looks two cells around its start.
MARGIN = 5

_INDEX = {(r.joint, r.direction): i for i, r in enumerate(ROTATIONS)}
_tidy.set_rules(_AROUND12, ROTATION_MASKS, _AROUND, _ONE_ARC)


def shorten(initial: Configuration, moves: list[Move],
            deadline: Deadline = NO_DEADLINE) -> list[Move]:
    """``moves`` with the detours nothing needed cut short (see the module
    docstring): at each move, the shortcut saving the most rotations is taken.
    Returns ``moves`` itself above ``TIDY_MOVES`` moves; stops early, with
    what it has shortened so far, when the deadline comes."""
    if len(moves) > TIDY_MOVES:
        return moves
    plan = list(moves)
    for _ in range(PASSES):
        before = len(plan)
        plan = one_pass(initial, plan, deadline)
        if len(plan) == before:
            break
    return plan


def one_pass(initial: Configuration, plan: list[Move],
             deadline: Deadline = NO_DEADLINE) -> list[Move]:
    """One walk over ``plan`` taking at each move the shortcut that saves the
    most rotations (``planning/_tidy.c``)."""
    if not plan:
        return []
    xmin, ymin, width, height = grid_frame(initial, plan, MARGIN)
    ids = [m.id for _, m in initial.items()]
    number = {module: k + 1 for k, module in enumerate(ids)}
    where = array("i", bytes(4 * width * height))
    for (x, y), m in initial.items():
        where[x - xmin + (y - ymin) * width] = number[m.id]
    encoded = array("i")
    for move in plan:
        rot = rotation_index(move)
        x, y = move.src
        if move.module not in number or move.substrate_module not in number:
            raise ValueError(f"{move}: a module the initial configuration does not have")
        encoded.extend((number[move.module], x - xmin + (y - ymin) * width, rot,
                        number[move.substrate_module]))
    tidied = _tidy.one_pass(width, height, where, encoded, len(ids),
                            offset_distances(width, height), WINDOW, deadline)
    return [plan[item] if isinstance(item, int) else _move(item, ids, xmin, ymin, width)
            for item in tidied]


def rotation_index(move: Move) -> int:
    """``move``'s index in ROTATIONS, the C passes' number for it (ValueError
    for a joint no rotation has or a substrate that is not the rotation's)."""
    rot = _INDEX.get((move.joint, move.direction))
    if rot is None:
        raise ValueError(f"no rotation about joint {move.joint} {move.direction}")
    (x, y), (sx, sy) = move.src, ROTATIONS[rot].substrate
    if move.substrate != (x + sx, y + sy):
        raise ValueError(f"{move}: its substrate is not its rotation's")
    return rot


def grid_frame(initial: Configuration, plan: list[Move],
               margin: int) -> tuple[int, int, int, int]:
    """(xmin, ymin, width, height) of a grid holding every cell of ``initial``
    and ``plan`` ``margin`` cells inside its edges (the C passes' grids)."""
    cells = set(initial.cells)
    cells.update(m.src for m in plan)
    cells.update(m.dst for m in plan)
    xmin = min(x for x, _ in cells) - margin
    ymin = min(y for _, y in cells) - margin
    width = max(x for x, _ in cells) - xmin + 1 + margin
    height = max(y for _, y in cells) - ymin + 1 + margin
    return xmin, ymin, width, height


def offset_distances(width: int, height: int) -> np.ndarray:
    """The lattice distance of every offset of a grid, (dx, dy) at [dy + height
    - 1, dx + width - 1] (C ints): protocol.lattice.distance over arrays."""
    offsets = np.meshgrid(np.arange(1 - width, width), np.arange(1 - height, height))
    return np.ascontiguousarray(distance((0, 0), offsets), dtype=np.intc)


def _move(item: tuple[int, int, int, int], ids: list[int], xmin: int, ymin: int,
          width: int) -> Move:
    """A move of a roll the C pass made: (module + 1, start, rotation, substrate + 1)."""
    module, start, rot, sub = item
    rule = ROTATIONS[rot]
    x, y = xmin + start % width, ymin + start // width
    (gx, gy), (sx, sy) = rule.goal, rule.substrate
    return new_move(ids[module - 1], (x, y), (x + gx, y + gy), rule.joint, rule.direction,
                    (x + sx, y + sy), ids[sub - 1])
