"""The detour-cutting pass in Python: the reference the C pass
(``planning/_tidy.c``) is compared with, move for move.

It is tidy.shorten as it ran in Python until session 18 (without its
``TIDY_MOVES`` limit), over tidy.py's constants (read when called, so a test can change them).
"""

from __future__ import annotations

from collections import deque

from hexbot.planning import tidy
from hexbot.planning.budget import NO_DEADLINE, Deadline
from hexbot.planning.configuration import Configuration
from hexbot.planning.hexlattice import Cell, distance
from hexbot.planning.moves import Move
from hexbot.planning.robust import _moves_from, unwind
from hexbot.planning.schedule import cells_of, stays_connected


def reference_shorten(initial: Configuration, moves: list[Move],
                      deadline: Deadline = NO_DEADLINE) -> list[Move]:
    """tidy.shorten, every pass in Python."""
    plan = list(moves)
    for _ in range(tidy.PASSES):
        before = len(plan)
        plan = reference_pass(initial, plan, deadline)
        if len(plan) == before:
            break
    return plan


def reference_pass(initial: Configuration, plan: list[Move], deadline: Deadline) -> list[Move]:
    """One pass of the plan, as tidy.one_pass makes it in C."""
    where: dict[Cell, int] = {c: m.id for c, m in initial.items()}
    last = _last_moves(plan)
    i = 0
    while i < len(plan):
        if i % tidy.DEADLINE_EVERY == 0 and deadline.expired():
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
    for k in range(start, min(last + 1, start + tidy.WINDOW)):
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
