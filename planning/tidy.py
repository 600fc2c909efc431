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
"""

from __future__ import annotations

from collections import deque

from hexbot.planning.budget import NO_DEADLINE, Deadline
from hexbot.planning.configuration import Configuration
from hexbot.planning.hexlattice import Cell, distance
from hexbot.planning.moves import Move
from hexbot.planning.robust import _moves_from, unwind
from hexbot.planning.schedule import cells_of, stays_connected

#: Above this many moves a plan is left as it is: each move looked at costs a
#: copy of the configuration and replays up to ``WINDOW`` moves (5,000 moves of
#: a strip plan of 100 modules took 12 s; the local plans of 1,000 modules have
#: 350-500 moves and take 0.15 s).
TIDY_MOVES = 3_000

#: Moves scanned after a module's move for a later one to shortcut to.
WINDOW = 1_000

#: Passes over the plan at most (a shortcut can open another one earlier on).
PASSES = 4

#: Moves between two looks at the deadline.
DEADLINE_EVERY = 64


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
        plan = _one_pass(initial, plan, deadline)
        if len(plan) == before:
            break
    return plan


def _one_pass(initial: Configuration, plan: list[Move], deadline: Deadline) -> list[Move]:
    where: dict[Cell, int] = {c: m.id for c, m in initial.items()}
    last = _last_moves(plan)
    i = 0
    while i < len(plan):
        if i % DEADLINE_EVERY == 0 and deadline.expired():
            break
        found = _best_shortcut(where, plan, i, last[plan[i].module])
        if found is None:
            _apply(where, plan[i])
            i += 1
            continue
        end, roll = found
        module = plan[i].module
        plan[i:end + 1] = [m for m in plan[i:end] if m.module != module] + roll
        last = _last_moves(plan)
    return plan


def _last_moves(plan: list[Move]) -> dict[int, int]:
    """Each module's last move (index): no shortcut of it reaches further."""
    return {m.module: k for k, m in enumerate(plan)}


def _best_shortcut(where: dict[Cell, int], plan: list[Move], start: int, last: int
                   ) -> tuple[int, list[Move]] | None:
    """(index of the module's last move replaced, the roll replacing its moves
    from ``start`` on) saving the most rotations, or None."""
    module = plan[start].module
    home = plan[start].src
    after = dict(where)
    made = 0
    best: tuple[int, int, list[Move]] | None = None  # (saving, end, roll)
    for k in range(start, min(last + 1, start + WINDOW)):
        move = plan[k]
        if move.module == module:
            made += 1
            saving = best[0] if best else 0
            # a rotation moves a module to a neighbouring cell: no roll is shorter
            # than the distance, so most moves of a journey need no search
            if distance(home, move.dst) < made - saving:
                roll = _roll(after, home, move.dst, made - saving - 1)
                if roll is not None:
                    best = (made - len(roll), k, roll)
            continue
        if not _legal(after, move):
            break
        _apply(after, move)
    return (best[1], best[2]) if best else None


def _roll(where: dict[Cell, int], src: Cell, dst: Cell, limit: int) -> list[Move] | None:
    """The fewest rotations (at most ``limit``) taking the module at ``src`` to
    ``dst`` with the others fixed, or None (also when it would split the rest)."""
    if src == dst:
        return []
    if limit < 1 or not stays_connected(where.keys(), src):
        return None
    parent: dict[Cell, tuple | None] = {src: None}
    depth = {src: 0}
    queue = deque([src])
    while queue:
        cell = queue.popleft()
        if depth[cell] == limit:
            continue
        for rule, sub, goal in _moves_from(cell, where, src):
            if goal in parent:
                continue
            parent[goal] = (cell, rule, sub)
            depth[goal] = depth[cell] + 1
            if goal == dst:
                module = where[src]
                return [Move(module, a, b, r.joint, r.direction, s, where[s])
                        for a, b, r, s in unwind(parent, dst)]
            queue.append(goal)
    return None


def _legal(where: dict[Cell, int], move: Move) -> bool:
    if where.get(move.src) != move.module:
        return False
    if where.get(move.substrate) != move.substrate_module:
        return False
    if any(c in where for c in cells_of(move)[1:]):
        return False
    return stays_connected(where.keys(), move.src)


def _apply(where: dict[Cell, int], move: Move) -> None:
    where[move.dst] = where.pop(move.src)
