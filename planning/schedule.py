"""Parallel schedules of serial plans: which moves can share a time step.

List scheduling over a dependency graph. A move depends on the earlier moves
it would collide with if run in the same step or before them: the last
earlier move of its module, the last earlier move whose cells (start, goal,
swept) include one of its cells or its substrate, and the earlier moves that
used one of its cells as their substrate since. A move whose dependencies
all ran in earlier steps sees its cells exactly as the serial plan does, so
it is legal in the next step if the modules that stay put stay connected:
each step takes the ready moves in serial order and keeps one only if its
module is not a cut vertex of what stays (a local test, usually one look at
its neighbours). A moving module is never a substrate and no two moves of a
step share a cell.

The graph is built incrementally over a window of the ``WINDOW`` earliest
unscheduled moves, so that each move is looked at a constant number of times
(plus once per step it waits as a cut vertex) and memory follows the window,
not the plan. The old scheduler rescanned up to a few hundred pending moves
every step (quadratic-ish on the five-million-move strip plans of 10,000
modules).

The list schedule can get stuck: moves that ran early (out of serial order)
may leave every ready move a cut vertex. :func:`schedule_in_pieces` then
schedules the two halves of the plan one after the other, and so on down
where they jam again (a single move never jams: it is legal where the serial
plan makes it), so parallelism is lost only at those barriers. Until session
14 a jam packed the whole serial order greedily instead
(:func:`pack_consecutive`, kept for tests: it never looks ahead), seven times
the makespan on a blob of 1,000 (docs/planning.md, *Parallel schedule*).
"""

from __future__ import annotations

import heapq
from collections import deque

from hexbot.planning.budget import NO_DEADLINE, BudgetExhausted, Deadline
from hexbot.planning.configuration import Configuration
from hexbot.planning.hexlattice import ROTATIONS, SIDE_OFFSETS, SIDES, Cell
from hexbot.planning.moves import Move
from hexbot.planning.plan import Step

#: Unscheduled moves the dependency graph holds at a time (candidates of a step).
WINDOW = 20_000

#: Steps between two looks at the deadline.
DEADLINE_EVERY = 256

_AROUND = [SIDE_OFFSETS[s] for s in SIDES]


def _one_arc(mask: int) -> bool:
    ring = [bool(mask >> i & 1) for i in range(6)]
    return sum(1 for i in range(6) if ring[i] and not ring[i - 1]) <= 1


#: ring of occupied neighbours (bit i: side i + 1) -> do they form at most one arc?
_ONE_ARC = [_one_arc(mask) for mask in range(64)]
_BITS = [(dx, dy, 1 << i) for i, (dx, dy) in enumerate(_AROUND)]

# (joint, direction) -> offsets of the goal and the three swept cells from the start
_CELLS = {(r.joint, r.direction): (r.goal, *r.swept) for r in ROTATIONS}
_FLAT = {key: tuple(v for cell in cells for v in cell) for key, cells in _CELLS.items()}


def cells_of(move: Move) -> tuple[Cell, ...]:
    """The cells a move needs: its start, its goal and the three swept cells."""
    x, y = move.src
    return ((x, y), *((x + dx, y + dy) for dx, dy in _CELLS[move.joint, move.direction]))


def stays_connected(occupied: set[Cell], cell: Cell) -> bool:
    """Is ``occupied`` without ``cell`` still one piece (``occupied`` being one)?

    Every piece left would touch ``cell``, so its occupied neighbours must stay
    connected to each other: none or one, or one contiguous arc of them, is
    enough; otherwise a breadth-first search from each, taking turns, merging
    where they meet (local when nothing splits, the smaller side when it does).
    """
    x, y = cell
    mask = 0
    for dx, dy, bit in _BITS:
        if (x + dx, y + dy) in occupied:
            mask |= bit
    if _ONE_ARC[mask]:
        return True
    seeds = [(x + dx, y + dy) for dx, dy, bit in _BITS if mask & bit]
    owner = {c: i for i, c in enumerate(seeds)}
    owner[cell] = -1  # removed: never entered
    label = list(range(len(seeds)))

    def root(i: int) -> int:
        while label[i] != i:
            label[i] = label[label[i]]
            i = label[i]
        return i

    frontiers = {i: deque([c]) for i, c in enumerate(seeds)}
    while True:
        for i in list(frontiers):
            queue = frontiers.get(i)
            if queue is None:  # merged into another search this round
                continue
            if not queue:  # ran dry before meeting the others: a piece is cut off
                return False
            cx, cy = queue.popleft()
            for dx, dy in _AROUND:
                n = (cx + dx, cy + dy)
                if n not in occupied:
                    continue
                other = owner.get(n)
                if other is None:
                    owner[n] = i
                    queue.append(n)
                    continue
                if other < 0:
                    continue
                other = root(other)
                if other != i:
                    label[other] = i
                    queue.extend(frontiers.pop(other))
                    if len(frontiers) == 1:
                        return True


def schedule_parallel(initial: Configuration, serial: list[Move],
                      deadline: Deadline = NO_DEADLINE,
                      window: int = WINDOW) -> list[Step] | None:
    """List-schedule ``serial`` into time steps (None if it gets stuck).

    Raises :class:`~hexbot.planning.budget.BudgetExhausted` when ``deadline``
    passes."""
    total = len(serial)
    occupied = set(initial.cells)
    steps: list[Step] = []
    # dependency graph of the admitted, unscheduled moves
    waiting: dict[int, int] = {}  # move -> dependencies not yet run
    after: dict[int, list[int]] = {}  # move -> moves that depend on it
    done = bytearray(total)  # 1 once scheduled in an earlier step
    last_use: dict[Cell, int] = {}  # cell -> last admitted move needing it
    leaning: dict[Cell, set[int]] = {}  # cell -> unscheduled moves on it as substrate since
    last_of: dict[int, int] = {}  # module -> its last admitted move
    ready: list[int] = []  # heap of moves whose dependencies all ran
    admitted = 0

    last_use_get, leaning_pop, leaning_get = last_use.get, leaning.pop, leaning.get
    after_get, last_of_get = after.get, last_of.get

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
            sub = move.substrate
            j = last_use_get(sub)
            if j is not None and not done[j]:
                deps.append(j)
            for c in ((x, y), (x + gx, y + gy), (x + ax, y + ay), (x + bx, y + by),
                      (x + cx, y + cy)):
                j = last_use_get(c)
                if j is not None and not done[j]:
                    deps.append(j)
                leaners = leaning_pop(c, None)
                if leaners:
                    deps.extend(leaners)
                last_use[c] = k
            last_of[move.module] = k
            leaners = leaning_get(sub)
            if leaners is None:
                leaning[sub] = {k}
            else:
                leaners.add(k)
            if deps:
                for j in deps:
                    later = after_get(j)
                    if later is None:
                        after[j] = [k]
                    else:
                        later.append(k)
                waiting[k] = len(deps)
            else:
                heapq.heappush(ready, k)
        if len(steps) % DEADLINE_EVERY == 0:
            deadline.check("parallel schedule")
        chosen: list[int] = []
        held: list[int] = []
        while ready:
            k = heapq.heappop(ready)
            src = serial[k].src
            if stays_connected(occupied, src):
                occupied.discard(src)  # the rest of the step sees what stays put
                chosen.append(k)
            else:
                held.append(k)
        if not chosen:
            return None
        for k in held:
            heapq.heappush(ready, k)
        step_moves = []
        for k in chosen:
            move = serial[k]
            step_moves.append(move)
            occupied.add(move.dst)
            done[k] = 1
            leaners = leaning.get(move.substrate)
            if leaners is not None:
                leaners.discard(k)
        for k in chosen:
            for j in after.pop(k, ()):
                left = waiting[j] - 1
                if left:
                    waiting[j] = left
                else:
                    del waiting[j]
                    heapq.heappush(ready, j)
        steps.append(Step(step_moves))
    return steps


def pack_consecutive(initial: Configuration, serial: list[Move],
                     deadline: Deadline = NO_DEADLINE) -> list[Step]:
    """Greedy packing of consecutive independent serial moves (never stuck)."""
    steps: list[Step] = []
    occupied = set(initial.cells)
    i = 0
    while i < len(serial):
        if len(steps) % DEADLINE_EVERY == 0:
            deadline.check("parallel schedule")
        used: set[Cell] = set()
        subs: set[Cell] = set()
        modules: set[int] = set()
        chosen: list[Move] = []
        while i < len(serial):
            move = serial[i]
            fp = set(cells_of(move))
            if chosen and (
                move.module in modules
                or fp & used
                or move.substrate in used
                or fp & subs
                or not stays_connected(occupied, move.src)
            ):
                break
            occupied.discard(move.src)
            used |= fp
            subs.add(move.substrate)
            modules.add(move.module)
            chosen.append(move)
            i += 1
        for move in chosen:
            occupied.add(move.dst)
        steps.append(Step(chosen))
    return steps


def schedule_in_pieces(initial: Configuration, serial: list[Move],
                       deadline: Deadline = NO_DEADLINE) -> list[Step]:
    """The list schedule of ``serial``; where it gets stuck, the list schedules
    of its halves, one after the other (recursively: the depth is at most
    log2 of the plan's length, and a single move is always scheduled)."""
    steps = schedule_parallel(initial, serial, deadline)
    if steps is not None:
        return steps
    half = len(serial) // 2
    first = schedule_in_pieces(initial, serial[:half], deadline)
    occupied = set(initial.cells)
    for move in serial[:half]:
        occupied.discard(move.src)
        occupied.add(move.dst)
    middle = Configuration.from_cells(frozenset(occupied))
    return first + schedule_in_pieces(middle, serial[half:], deadline)


def schedule(initial: Configuration, serial: list[Move],
             deadline: Deadline = NO_DEADLINE) -> tuple[list[Step], str]:
    """Time steps for ``serial`` within ``deadline``, and a warning ("" if none).

    The list schedule, in pieces where it gets stuck; when the time budget
    runs out first, one move per step (legal, but no parallelism)."""
    try:
        return schedule_in_pieces(initial, serial, deadline), ""
    except BudgetExhausted:
        return [Step([m]) for m in serial], (
            f"parallel schedule: the time budget of {deadline.seconds:.3g} s ran out, "
            "so the plan runs one move per step")
