"""Parallel schedules of serial plans: which moves can share a time step.

List scheduling over a dependency graph. A move *changes* two cells (its
start and its goal) and *reads* four (the three swept cells must be empty,
its substrate occupied). It depends on the last earlier move of its module,
on the last earlier move that changed one of its six cells, and, for the
cells it changes, on the earlier moves that read them since. Two moves that
only read the same cell (two rolls sweeping one empty cell, two modules on
one substrate) keep no order: each sees the cell as the serial plan does
whichever runs first, so they need only not sweep it in the same step
(since session 15; when swept cells counted as changed, the longest chains
of the bench's blobs of 1,000 were 12-18 % longer). A move whose
dependencies all ran in earlier steps sees its cells exactly as the serial
plan does, so it is legal in the next step if the modules that stay put stay
connected and no move of the step needs one of its cells: each step takes
the ready moves, longest chain to the end first (:func:`bottom_levels`; up
to ``FINE_MOVES``, see there), and keeps one only if its cells
are free in the step and its module is not a cut vertex of what stays (a
local test, usually one look at its neighbours). A moving module is never a
substrate. No schedule is shorter than :func:`critical_chain`.

The graph is built incrementally over a window of the ``WINDOW`` earliest
unscheduled moves, so that each move is looked at a constant number of times
(plus once per step it waits as a cut vertex) and its edges follow the
window, not the plan. The old scheduler rescanned up to a few hundred pending
moves every step (quadratic-ish on the five-million-move strip plans of 10,000
modules). Since session 17 the list schedule runs in C
(``planning/_schedule.c``, the same steps as the Python one it replaced, which
tests/planning/schedule_reference.py keeps): about 2 us a move instead of 10-18,
and 22 bytes a move of its own (its start as a grid index, module,
rotation, counts), a quarter of what the ``Move`` itself takes.

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

from array import array
from collections import deque
from collections.abc import Iterable

from hexbot.planning import _schedule
from hexbot.planning.budget import NO_DEADLINE, BudgetExhausted, Deadline
from hexbot.planning.configuration import Configuration
from hexbot.planning.hexlattice import ROTATIONS, SIDE_OFFSETS, SIDES, Cell
from hexbot.planning.moves import Move
from hexbot.planning.plan import Step

#: Unscheduled moves the dependency graph holds at a time (candidates of a step).
WINDOW = 20_000

#: Up to this many moves the schedule is the fine one: reads keep no order and
#: a step takes the ready moves with the longest chain to the end first
#: (:func:`bottom_levels`). Beyond it, the coarse one of sessions 9-14: swept
#: cells count as changed and the ready moves go in serial order. The fine
#: schedule shortens the bench's blobs of 1,000 by 3-12 %, a strip plan of
#: 3,000 modules by 14 % and the blob of 10,000 by 4 % (81,724 -> 78,341
#: steps). In Python it took 18 us a move against 10, so until session 17 the
#: strip plans of 10,000 modules (5-12 million moves) got the coarse one; in C
#: both take about 2 us, and every plan of the bench gets the fine one.
FINE_MOVES = 20_000_000

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
    enough; otherwise :func:`meeting_searches` from each (local when nothing
    splits, the smaller side when it does).
    """
    x, y = cell
    mask = 0
    for dx, dy, bit in _BITS:
        if (x + dx, y + dy) in occupied:
            mask |= bit
    if _ONE_ARC[mask]:
        return True
    seeds = [(x + dx, y + dy) for dx, dy, bit in _BITS if mask & bit]
    return meeting_searches(occupied, seeds, (cell,), first_cut=True) is not None


def meeting_searches(occupied: set[Cell], seeds: list[Cell], skip: Iterable[Cell] = (),
                     first_cut: bool = False) -> list[int] | None:
    """Which piece of ``occupied`` without ``skip`` each of ``seeds`` (distinct)
    lies in: one breadth-first search from each, taking turns, merging where
    they meet. A search that runs dry has closed its piece, so the cost is about
    the smaller pieces' size, and the searches stop when one is left running
    (the rest of the configuration is never walked in full). Per seed a label
    (equal labels: one piece); with ``first_cut``, None as soon as a piece
    closes while others still run."""
    owner = {c: i for i, c in enumerate(seeds)}
    for c in skip:
        owner[c] = -1  # never entered
    label = list(range(len(seeds)))

    def root(i: int) -> int:
        while label[i] != i:
            label[i] = label[label[i]]
            i = label[i]
        return i

    frontiers = {i: deque([c]) for i, c in enumerate(seeds)}
    while len(frontiers) > 1:
        for i in list(frontiers):
            queue = frontiers.get(i)
            if queue is None:  # merged into another search this round
                continue
            if not queue:  # ran dry before meeting the others: a piece is cut off
                if first_cut:
                    return None
                del frontiers[i]
                if len(frontiers) == 1:
                    break
                continue
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
                        break
            if len(frontiers) == 1:
                break
    return [root(i) for i in range(len(seeds))]


def _reads_and_changes(move: Move) -> tuple[tuple[Cell, Cell, Cell, Cell], Cell, Cell]:
    """The cells a move reads (its substrate, then its three swept cells) and
    the two it changes (start, goal), as the fine graph sees them (the list
    schedule's hot loop spells this out itself)."""
    x, y = move.src
    gx, gy, ax, ay, bx, by, cx, cy = _FLAT[move.joint, move.direction]
    return ((move.substrate, (x + ax, y + ay), (x + bx, y + by), (x + cx, y + cy)),
            move.src, (x + gx, y + gy))


def bottom_levels(serial: list[Move]) -> array:
    """For each move, the longest chain of dependent moves from it to the end of
    the plan (1 for a move nothing waits for): the graph of
    :func:`schedule_parallel` (the fine one), walked backwards cell by cell in
    one pass."""
    levels = array("l", bytes(8 * len(serial)))
    next_of: dict[int, int] = {}  # module -> level of its next move
    next_change: dict[Cell, int] = {}  # cell -> level of the next move changing it
    readers: dict[Cell, int] = {}  # cell -> highest level reading it before that
    next_of_get, next_change_get, readers_get = next_of.get, next_change.get, readers.get
    for k in range(len(serial) - 1, -1, -1):
        move = serial[k]
        reads, src, dst = _reads_and_changes(move)
        sub, a, b, c = reads
        level = 1 + max(next_of_get(move.module, 0),
                        next_change_get(sub, 0), next_change_get(a, 0),
                        next_change_get(b, 0), next_change_get(c, 0),
                        next_change_get(src, 0), readers_get(src, 0),
                        next_change_get(dst, 0), readers_get(dst, 0))
        levels[k] = level
        next_of[move.module] = level
        for cell in reads:
            if readers_get(cell, 0) < level:
                readers[cell] = level
        next_change[src] = next_change[dst] = level
        readers.pop(src, None)
        readers.pop(dst, None)
    return levels


def critical_chain(serial: list[Move]) -> tuple[int, list[int]]:
    """The longest chain of dependent moves of :func:`schedule_parallel`'s fine
    graph (what no schedule of ``serial`` gets below, cut vertices aside): its
    length and its moves, last first."""
    if not serial:
        return 0, []
    level = [0] * len(serial)
    parent = [-1] * len(serial)
    last_of: dict[int, int] = {}  # module -> its last move
    last_change: dict[Cell, int] = {}  # cell -> the last move that changed it
    top_reader: dict[Cell, int] = {}  # cell -> the deepest move reading it since
    last_of_get, last_change_get, top_reader_get = last_of.get, last_change.get, top_reader.get
    for k, move in enumerate(serial):
        reads, src, dst = _reads_and_changes(move)
        deepest, depth = -1, 0
        for j in (last_of_get(move.module), last_change_get(reads[0]),
                  last_change_get(reads[1]), last_change_get(reads[2]),
                  last_change_get(reads[3]), last_change_get(src), last_change_get(dst),
                  top_reader_get(src), top_reader_get(dst)):
            if j is not None and level[j] > depth:
                deepest, depth = j, level[j]
        level[k] = depth = depth + 1
        parent[k] = deepest
        last_of[move.module] = k
        for c in reads:
            j = top_reader_get(c)
            if j is None or level[j] < depth:
                top_reader[c] = k
        last_change[src] = last_change[dst] = k
        top_reader.pop(src, None)
        top_reader.pop(dst, None)
    k = max(range(len(serial)), key=level.__getitem__)
    length, chain = level[k], []
    while k >= 0:
        chain.append(k)
        k = parent[k]
    return length, chain


_schedule.set_rules(_AROUND, _ONE_ARC, [(r.joint, r.direction, _FLAT[r.joint, r.direction],
                                          r.substrate) for r in ROTATIONS])


def schedule_parallel(initial: Configuration, serial: list[Move],
                      deadline: Deadline = NO_DEADLINE,
                      window: int = WINDOW) -> list[Step] | None:
    """List-schedule ``serial`` into time steps (None if it gets stuck).

    Runs in C (``planning/_schedule.c``; tests/planning/schedule_reference.py
    is the same schedule in Python, compared step for step): at about 10 us a
    move in Python, the schedule was most of the time of a strip plan of
    10,000 modules. Raises :class:`~hexbot.planning.budget.BudgetExhausted`
    when ``deadline`` passes."""
    steps = _schedule.schedule(list(initial.cells), list(serial), len(serial) <= FINE_MOVES,
                               window, deadline)
    return None if steps is None else [Step(moves) for moves in steps]


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
    log2 of the plan's length). A single move of a legal plan is always
    scheduled; one that is not raises :class:`ValueError` (a planner's bug)."""
    return _in_pieces(initial, serial, 0, deadline)


def _in_pieces(initial: Configuration, serial: list[Move], first_index: int,
               deadline: Deadline) -> list[Step]:
    steps = schedule_parallel(initial, serial, deadline)
    if steps is not None:
        return steps
    if len(serial) == 1:
        move = serial[0]
        raise ValueError(f"move {first_index + 1} of module {move.module} from {move.src} "
                         f"to {move.dst} cannot run where the plan makes it (a swept cell "
                         "is taken, its substrate is gone or the rest would split)")
    half = len(serial) // 2
    first = _in_pieces(initial, serial[:half], first_index, deadline)
    occupied = set(initial.cells)
    for move in serial[:half]:
        occupied.discard(move.src)
        occupied.add(move.dst)
    middle = Configuration.from_cells(frozenset(occupied))
    return first + _in_pieces(middle, serial[half:], first_index + half, deadline)


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
