"""The list schedule in Python: the reference the C schedule
(``planning/_schedule.c``) is compared with, step for step.

It is schedule.schedule_parallel as it ran in Python until session 17 (the
deadline left out), over schedule.py's own tables and connectivity test.
"""

from __future__ import annotations

import heapq

from hexbot.planning.hexlattice import Cell
from hexbot.planning.plan import Step
from hexbot.planning.schedule import _FLAT, FINE_MOVES, WINDOW, bottom_levels, stays_connected


def reference_schedule(initial, serial, window=WINDOW, fine=None):
    total = len(serial)
    occupied = set(initial.cells)
    steps: list[Step] = []
    # dependency graph of the admitted, unscheduled moves (indexed by move:
    # a few bytes a move, next to the hundred of the move itself)
    waiting: dict[int, int] = {}  # move -> dependencies not yet run
    after: list[list[int] | None] = [None] * total  # move -> moves that depend on it
    done = bytearray(total)  # 1 once scheduled in an earlier step
    last_change: dict[Cell, int] = {}  # cell -> last admitted move that changed it
    # cell -> moves reading it since it last changed (some may have run: each
    # is listed once and looked at once, when the cell changes)
    readers: dict[Cell, list[int]] = {}
    last_of: dict[int, int] = {}  # module -> its last admitted move
    # heap of the moves whose dependencies all ran, longest chain to the end
    # first (then serial order): -level * total + move
    ready: list[int] = []
    fine = total <= FINE_MOVES if fine is None else fine
    levels = bottom_levels(serial) if fine else None
    admitted = 0

    last_change_get, readers_pop, readers_get = last_change.get, readers.pop, readers.get
    last_of_get = last_of.get

    while admitted < total or ready or waiting:
        # admit moves into the graph (the hot loop: a list of dependencies, repeats
        # allowed, each counted and released once per listing)
        while admitted < total and len(waiting) + len(ready) < window:
            k = admitted
            admitted += 1
            move = serial[k]
            x, y = move.src
            gx, gy, ax, ay, bx, by, cx, cy = _FLAT[move.joint, move.direction]
            deps = []
            j = last_of_get(move.module)
            if j is not None and not done[j]:
                deps.append(j)
            a, b, c = (x + ax, y + ay), (x + bx, y + by), (x + cx, y + cy)
            if fine:
                reads = (move.substrate, a, b, c)
                changes = ((x, y), (x + gx, y + gy))
            else:
                reads = (move.substrate,)
                changes = ((x, y), (x + gx, y + gy), a, b, c)
            for cell in reads:
                j = last_change_get(cell)
                if j is not None and not done[j]:
                    deps.append(j)
                seen = readers_get(cell)
                if seen is None:
                    readers[cell] = [k]
                else:
                    seen.append(k)
            for cell in changes:
                j = last_change_get(cell)
                if j is not None and not done[j]:
                    deps.append(j)
                seen = readers_pop(cell, None)
                if seen:
                    for j in seen:
                        if not done[j]:
                            deps.append(j)
                last_change[cell] = k
            last_of[move.module] = k
            if deps:
                for j in deps:
                    later = after[j]
                    if later is None:
                        after[j] = [k]
                    else:
                        later.append(k)
                waiting[k] = len(deps)
            else:
                heapq.heappush(ready, k - levels[k] * total if fine else k)
        chosen: list[int] = []
        held: list[int] = []
        busy: set[Cell] = set()  # cells the step's moves need (reads share no order)
        while ready:
            key = heapq.heappop(ready)
            k = key % total
            src = serial[k].src
            cells = ()
            if fine:  # reads keep no order: a cell may not serve two moves of a step
                move = serial[k]
                x, y = src
                gx, gy, ax, ay, bx, by, cx, cy = _FLAT[move.joint, move.direction]
                cells = (src, (x + gx, y + gy), (x + ax, y + ay), (x + bx, y + by),
                         (x + cx, y + cy))
                if not busy.isdisjoint(cells):
                    held.append(key)
                    continue
            if stays_connected(occupied, src):
                occupied.discard(src)  # the rest of the step sees what stays put
                busy.update(cells)
                chosen.append(k)
            else:
                held.append(key)
        if not chosen:
            return None
        for key in held:
            heapq.heappush(ready, key)
        step_moves = []
        for k in chosen:
            move = serial[k]
            step_moves.append(move)
            occupied.add(move.dst)
            done[k] = 1
        for k in chosen:
            later = after[k]
            if later is None:
                continue
            after[k] = None
            for j in later:
                left = waiting[j] - 1
                if left:
                    waiting[j] = left
                else:
                    del waiting[j]
                    heapq.heappush(ready, j - levels[j] * total if fine else j)
        steps.append(Step(step_moves))
    return steps
