"""The ``robust`` planner: the thesis' idea (fill voids with electrons) made safe.

Serial core. While voids remain: pick a mover (an electron, or a goal module
that must step aside) that is not a cut vertex, search breadth-first over
Table 4-3 rotations, with every other module fixed, a path to a void, and
move it there. The module travels over the configuration minus itself,
which is connected, so every intermediate configuration is connected; every
rotation has its substrate and its goal and three swept cells empty. A void
is only filled when the cells still to fill can then be entered in some
order (:func:`fillable`); goal modules that wall a void in step aside
(:func:`must_move`) or park outside the goal. If the forward search gets
stuck (or exceeds its budget, :func:`direct_budget`), the same search runs
from the goal back to the start and the moves are reversed (every rotation
is undone by the opposite one over the same cells); if that fails too, the
local method (:mod:`hexbot.planning.local`: window searches and a kernel
flow, up to ``LOCAL_LIMIT`` modules) tries; then the plan goes through a
compact middle ball (:mod:`hexbot.planning.middle`:
initial -> ball -> goal, both halves direct; plans a few times the distance
bound) and, when that stalls as well, through a canonical strip
(:mod:`hexbot.planning.canonical`), which does not stall on notched goals.

Detours. Before the schedule, a module's moves that a shorter roll can
replace, with the others' moves in between still legal, are replaced
(:mod:`hexbot.planning.tidy`; round trips are dropped).

Parallel schedule. The serial moves are list-scheduled into time steps: a
move runs as soon as no earlier pending move touches its cells (start,
goal, swept cells, substrate) or its module, and the modules that stay put
in the step remain connected. A moving module is never a substrate and no
two moves of a step share a cell. If that schedule gets stuck, the serial
order is packed greedily instead (always possible). Both live in
:mod:`hexbot.planning.schedule` and count against the time budget; when it
runs out there, the plan runs one move per step and says so in a warning.

Failures are reported, never hidden: disconnected inputs, different module
counts, immobile configurations (Fig. 4-6: no module can rotate without
breaking connectivity), goal cells that can never be entered, and searches
that find no plan (restricted pivoting has locked configurations, so no
planner is complete on every pair; see docs/planning.md).
"""

from __future__ import annotations

from collections import Counter, deque
from collections.abc import Callable
from dataclasses import dataclass, replace

from hexbot.planning.bounds import move_lower_bound
from hexbot.planning.budget import (
    DEFAULT_BUDGET,
    MAX_MOVES,
    NO_DEADLINE,
    Deadline,
    PlanningFailure,
)
from hexbot.planning.configuration import Configuration, is_connected
from hexbot.planning.hexlattice import LETTER_CELLS, ROTATIONS, Cell, distance, neighbors
from hexbot.planning.moves import Move, new_move
from hexbot.planning.plan import Plan, Step
from hexbot.planning.schedule import (  # noqa: F401 - re-exported (exact.py, tests)
    pack_consecutive,
    schedule,
    schedule_parallel,
    stays_connected,
)

# Precomputed Table 4-3 offsets: (rule, substrate, goal, swept) relative to (0, 0).
_RULES = [(rule, *rule.at((0, 0))) for rule in ROTATIONS]


#: How many times one goal cell may be emptied to make room (bounds the search).
ASIDE_LIMIT = 3


def _single_arc(occupied: set[Cell], cell: Cell) -> bool:
    """True when the occupied neighbours of ``cell`` form one contiguous arc:
    then removing ``cell`` cannot disconnect anything."""
    ring = [n in occupied for n in neighbors(cell)]
    if all(ring):
        return True
    changes = sum(1 for i in range(6) if ring[i] and not ring[i - 1])
    return changes <= 1


def is_cut(occupied: set[Cell], cell: Cell) -> bool:
    """Would removing ``cell`` disconnect ``occupied`` (one piece)? The searches
    of :func:`~hexbot.planning.schedule.stays_connected` meet nearby when it
    does not; a search of the whole set took 46 ms a call at 10,000 modules."""
    return not stays_connected(occupied, cell)


# The twelve cells a rotation can need (Fig. 4-30's A..L: substrate, goal and
# swept cells all lie among them), and per occupancy mask of those twelve the
# rotations open: twelve look-ups and a table instead of up to sixty.
_AROUND12 = tuple(LETTER_CELLS.values())
_BIT12 = {cell: 1 << i for i, cell in enumerate(_AROUND12)}
_OPEN12 = [
    tuple((rule, sub, goal) for rule, sub, goal, swept in _RULES
          if mask & _BIT12[sub] and not mask & _BIT12[goal]
          and not any(mask & _BIT12[c] for c in swept))
    for mask in range(1 << 12)
]
#: The rotations as the C searches take them (``_strip.c``, ``_tidy.c``, ``_regroup.c``), in
#: ROTATIONS order over the ring ``_AROUND12``: (substrate bit, goal and swept
#: bits, substrate dx, dy, goal dx, dy).
ROTATION_MASKS = [(_BIT12[r.substrate], sum(_BIT12[c] for c in (r.goal, *r.swept)),
                   *r.substrate, *r.goal) for r in ROTATIONS]


_RINGS12: dict[Cell, tuple[Cell, ...]] = {}  # cell -> its twelve cells, built once


def _moves_from(cell: Cell, occupied: set[Cell], mover: Cell):
    """Rotations open to the module travelling from ``mover`` when it stands at
    ``cell`` (``mover``'s own cell counts as empty)."""
    x, y = cell
    ring = _RINGS12.get(cell)
    if ring is None:
        if len(_RINGS12) > 200_000:  # bounded: a planner touches a few thousand
            _RINGS12.clear()
        ring = _RINGS12[cell] = tuple((x + dx, y + dy) for dx, dy in _AROUND12)
    a, b, c, d, e, f, g, h, i, j, k, m = ring
    mask = ((a in occupied) | (b in occupied) << 1 | (c in occupied) << 2
            | (d in occupied) << 3 | (e in occupied) << 4 | (f in occupied) << 5
            | (g in occupied) << 6 | (h in occupied) << 7 | (i in occupied) << 8
            | (j in occupied) << 9 | (k in occupied) << 10 | (m in occupied) << 11)
    if mask and mover != cell:
        bit = _BIT12.get((mover[0] - x, mover[1] - y))
        if bit:
            mask &= ~bit
    return [(rule, (x + sx, y + sy), (x + gx, y + gy))
            for rule, (sx, sy), (gx, gy) in _OPEN12[mask]]


#: Per ring mask (bit i = side i + 1 blocked): the first side of the first
#: run of three free sides in a row, or -1.
_FIRST_FREE_RUN = tuple(next((i for i in range(6) if not mask >> i & 1
                              and not mask >> (i + 1) % 6 & 1
                              and not mask >> (i + 2) % 6 & 1), -1)
                        for mask in range(64))
#: The same per mask: is there such a run?
_RUN_FREE = tuple(run >= 0 for run in _FIRST_FREE_RUN)


def _free_run(blocked: set[Cell] | frozenset[Cell], cell: Cell) -> bool:
    """Does ``cell`` keep three consecutive sides free of ``blocked``?"""
    a, b, c, d, e, f = neighbors(cell)
    return _RUN_FREE[(a in blocked) | (b in blocked) << 1 | (c in blocked) << 2
                     | (d in blocked) << 3 | (e in blocked) << 4 | (f in blocked) << 5]


@dataclass
class _State:
    occupied: set[Cell]
    ids: dict[Cell, int]
    goal: frozenset[Cell]
    #: fruitless searches left before giving up (None: unlimited)
    budget: int | None = None
    deadline: Deadline = NO_DEADLINE
    #: the method's name, for the reason when its deadline passes
    method: str = "direct"

    def electrons(self) -> list[Cell]:
        return sorted(self.occupied - self.goal)

    def voids(self) -> set[Cell]:
        return set(self.goal - self.occupied)


def _void_distances(state: _State, voids: set[Cell]) -> dict[Cell, int]:
    """Rotations needed to reach the nearest void from each empty cell, with every
    module fixed."""
    from hexbot.planning.surface import rolling_distances

    return rolling_distances(state.occupied, voids)


def fillable(goal: frozenset[Cell], voids: set[Cell]) -> set[Cell]:
    """Voids that can never be entered, whatever the order (empty set = all fine).

    Peels the voids from the outside in: a void can be filled last among the
    remaining ones when three consecutive sides of it are outside the goal
    or voids filled after it. Peeling only frees cells, so the greedy peel
    finds an order whenever one exists; what is left cannot be entered.
    """
    return _peel(goal, voids, set(voids))


def _peel(goal, voids, remaining: set[Cell], freed: dict | None = None,
          first: set[Cell] | None = None) -> set[Cell]:
    """The peel of :func:`fillable` from ``remaining`` (the voids not known to
    peel; the others count as peeled), looking first at ``first`` (all of
    ``remaining`` by default; a cell is looked at again when a neighbour
    peels). With ``freed``, each peeled void is listed under the three cells
    of the run of sides that freed it."""
    first = remaining if first is None else first
    queue = deque(first)  # the peel's result does not depend on its order
    queued = set(first)
    pop, push, mark, unmark = queue.popleft, queue.append, queued.add, queued.discard
    while queue:
        v = pop()
        unmark(v)
        if v not in remaining:
            continue
        ring = a, b, c, d, e, f = neighbors(v)
        # a side blocks when it is a goal cell filled before v (a module, or a void still here)
        run = _FIRST_FREE_RUN[(a in goal and (a in remaining or a not in voids))
                              | (b in goal and (b in remaining or b not in voids)) << 1
                              | (c in goal and (c in remaining or c not in voids)) << 2
                              | (d in goal and (d in remaining or d not in voids)) << 3
                              | (e in goal and (e in remaining or e not in voids)) << 4
                              | (f in goal and (f in remaining or f not in voids)) << 5]
        if run >= 0:
            remaining.discard(v)
            if freed is not None:
                for k in (run, run + 1, run + 2):
                    freed.setdefault(ring[k % 6], []).append(v)
            for n in ring:
                if n in remaining and n not in queued:
                    push(n)
                    mark(n)
    return remaining


class Peel:
    """:func:`fillable` kept for a goal and voids, to ask what is left after a
    few cells change (a void filled, a module gone) without peeling everything
    again: only the voids that the changed cells freed, directly or through
    voids they freed, are peeled again, with what was left. The others keep
    the run of free sides that peeled them, so the result is exact (the
    journey flow asks this for every candidate fill; a parallelogram of 1,000
    has 200 voids in one group, and peeling it whole per candidate took 1.6 s
    per fill)."""

    def __init__(self, goal, voids: set[Cell]) -> None:
        self.freed: dict[Cell, list[Cell]] = {}
        self.left = _peel(goal, voids, set(voids), self.freed)

    def after(self, goal, voids: set[Cell], changed) -> set[Cell]:
        """``fillable(goal, voids)`` for a goal and voids that differ from this
        peel's only at the cells ``changed``."""
        again: set[Cell] = set()
        stack = list(changed)
        while stack:
            for v in self.freed.get(stack.pop(), ()):
                if v not in again:
                    again.add(v)
                    stack.append(v)
        # a cell left stuck can peel now only next to a changed cell, or once
        # a neighbour peels (which looks at it again)
        stuck = self.left & voids
        near = {n for c in changed for n in (c, *neighbors(c))} & stuck
        return _peel(goal, voids, (again & voids) | stuck, first=(again & voids) | near)

    def walls_in(self, goal, voids: set[Cell], void: Cell) -> bool:
        """Does filling ``void`` (one of this peel's voids) leave another void
        that could be entered before unenterable?"""
        return bool(self.after(goal, voids - {void}, (void,)) - self.left)


def _allowed(goal: frozenset[Cell], void: Cell, pending: set[Cell]) -> bool:
    """Filling ``void`` now must leave an order in which the other pending cells
    (voids, and cells whose module will step aside) can be entered."""
    return not fillable(goal, pending - {void})


def unwind(parent: dict, node: Cell) -> list:
    """The hops of a breadth-first search from its start to ``node``:
    ``parent`` maps a cell to (previous cell, rule, substrate) or None."""
    path = []
    while parent[node] is not None:
        prev, rule, sub = parent[node]
        path.append((prev, node, rule, sub))
        node = prev
    return path[::-1]


def _journey(state: _State, electron: Cell, accept: Callable[[Cell], bool]) -> list | None:
    """Shortest rotation path of ``electron`` to an empty cell ``accept`` takes."""
    state.deadline.check(state.method)
    parent: dict[Cell, tuple[Cell, object, Cell] | None] = {electron: None}
    queue = deque([electron])
    while queue:
        cell = queue.popleft()
        for rule, sub, goal in _moves_from(cell, state.occupied, electron):
            if goal in parent:
                continue
            parent[goal] = (cell, rule, sub)
            if accept(goal):
                return unwind(parent, goal)
            queue.append(goal)
    if state.budget is not None:
        state.budget -= 1
        if state.budget < 0:
            raise PlanningFailure("no plan found: the direct search gave up (too many "
                                  "fruitless searches; the goal likely needs an order it "
                                  "does not try)")
    return None


def must_move(
    goal: frozenset[Cell], voids: set[Cell], fixed: Cell | None = None,
    limit: int | None = None,
) -> set[Cell] | None:
    """Goal cells whose module has to step aside so that every void can be entered.

    Peels voids as :func:`fillable` does; when no void can be peeled, peels a
    module of the goal instead (it will leave and be refilled later),
    preferring those touching the most stuck voids. None when even that fails.
    """
    remaining = set(voids)
    moved: set[Cell] = set()
    while True:
        remaining = fillable(goal, remaining | moved) - moved
        if not remaining:
            return moved
        pending = remaining | moved
        # the cells touching a stuck void win if any qualifies (same choice as a full
        # scan in sorted order); the full scan only when none does
        near = {n for v in remaining for n in neighbors(v) if n in goal} - pending
        best = _step_aside_choice(goal, voids, pending, moved, remaining, sorted(near), fixed)
        if best is None:
            best = _step_aside_choice(goal, voids, pending, moved, remaining,
                                      sorted(goal - pending - near), fixed)
        if best is None:
            return None
        moved.add(best)
        if limit is not None and len(moved) > limit:
            raise PlanningFailure(f"no plan found: more than {limit} goal modules would "
                                  "have to step aside")


def _step_aside_choice(
    goal: frozenset[Cell],
    voids: set[Cell],
    pending: set[Cell],
    moved: set[Cell],
    remaining: set[Cell],
    cells: list[Cell],
    fixed: Cell | None,
) -> Cell | None:
    """The goal module (of ``cells``) that can leave and touches the most stuck voids."""
    best: tuple[int, Cell] | None = None
    for cell in cells:
        if cell == fixed:
            continue
        blocked = {n for n in neighbors(cell) if n in goal and (n not in voids or n in pending)}
        blocked -= moved
        if not _free_run(blocked, cell):
            continue
        touching = sum(1 for n in neighbors(cell) if n in remaining)
        if best is None or touching > best[0]:
            best = (touching, cell)
    return None if best is None else best[1]


def serial_moves(
    initial: Configuration,
    goal: frozenset[Cell],
    max_moves: int,
    fixed: Cell | None = None,
    budget: int | None = None,
    aside_limit: int | None = -1,
    deadline: Deadline = NO_DEADLINE,
    method: str = "direct",
) -> list[Move]:
    """The serial core; raises :class:`PlanningFailure` when stuck, or after
    ``budget`` journey searches that found nothing, or when more than
    ``aside_limit`` goal modules must step aside at the start (-1: ``budget``).
    The module on ``fixed`` (fixed to the base) never moves.

    Movers are the electrons plus goal modules that must step aside
    (:func:`must_move`, or promoted when the electrons alone are stuck);
    each journey ends in a void, so the loop ends.
    """
    state = _State(set(initial.cells), {c: m.id for c, m in initial.items()}, goal, budget,
                   deadline, method)
    aside = must_move(goal, state.voids(), fixed, budget if aside_limit == -1 else aside_limit)
    if aside is None:
        raise PlanningFailure("some goal cell can never be entered, even with modules stepping "
                              "aside (fewer than three consecutive free sides)")
    # how often each cell was made to step aside; capped so that the loop ends
    promoted: Counter[Cell] = Counter(aside)
    moves: list[Move] = []
    while True:
        voids = state.voids()
        movers = sorted((state.occupied - goal) | (aside & state.occupied))
        if not voids:
            return moves
        pending = voids | (aside & state.occupied)
        path = _best_journey(state, movers, voids, pending, fixed, strict=True)
        if path is None:
            # the voids left may be walled in: park the walls well away first
            walls = {c for c in (must_move(goal, pending, fixed) or set()) & state.occupied
                     if promoted[c] < ASIDE_LIMIT}
            for c in sorted(walls):
                path = _park(state, c, pending | walls)
                if path:
                    aside |= walls - aside
                    promoted.update(walls)
                    break
        if path is None:
            path = _best_journey(state, movers, voids, pending, fixed, strict=False)
        if path is None:
            # let one more goal module step aside: the one with the shortest journey
            extra = [c for c in sorted(goal & state.occupied)
                     if promoted[c] < ASIDE_LIMIT and c != fixed]
            for c in extra:
                trial = _best_journey(state, [c], voids, pending | {c}, fixed, strict=False)
                if trial and (path is None or len(trial) < len(path)):
                    path = trial
            # or let a goal module park outside the goal (it becomes an electron)
            parkers = sorted(aside & state.occupied) + extra
            for c in parkers if path is None else ():
                path = _park(state, c, pending | {c})
                if path:
                    break
            if path is None:
                raise PlanningFailure(
                    f"no plan found: stuck after {len(moves)} moves with {len(voids)} voids "
                    "left, no module can reach a void without disconnecting the configuration "
                    "or colliding (the goal may be unreachable by Table 4-3 rotations, or "
                    "need an order this planner does not try)"
                )
            promoted[path[0][0]] += 1
        if len(moves) + len(path) > max_moves:
            raise PlanningFailure(f"more than {max_moves} moves needed")
        start = path[0][0]
        aside.discard(start)  # its module leaves; the cell is a plain void from now on
        module = state.ids.pop(start)
        state.occupied.discard(start)
        for src, dst, rule, sub in path:
            moves.append(new_move(module, src, dst, rule.joint, rule.direction, sub,
                                  state.ids[sub]))
        state.occupied.add(path[-1][1])
        state.ids[path[-1][1]] = module


def _best_journey(
    state: _State,
    movers: list[Cell],
    voids: set[Cell],
    pending: set[Cell],
    fixed: Cell | None,
    strict: bool | None = None,
) -> list | None:
    """A journey of the mover closest (by rotations) to a void it may fill."""
    dist = _void_distances(state, voids)
    ranked = []
    for e in movers:
        if e == fixed or is_cut(state.occupied, e):
            continue
        first = [dist[g] for _, _, g in _moves_from(e, state.occupied, e) if g in dist]
        if first:
            ranked.append((1 + min(first), e))
        elif any(True for _ in _moves_from(e, state.occupied, e)):
            ranked.append((10**9, e))
    ranked.sort()
    def strict_void(cell: Cell) -> bool:
        return cell in voids and _allowed(state.goal, cell, pending)

    for level in ((True, False) if strict is None else (strict,)):
        for _, e in ranked:
            path = _journey(state, e, strict_void if level else voids.__contains__)
            if path:
                return path
    return None


def _park(state: _State, mover: Cell, pending: set[Cell]) -> list | None:
    """A journey of a goal module out of the way: to a cell outside the goal,
    preferably one from which it cannot block the sweep into a cell still to fill."""
    if is_cut(state.occupied, mover):
        return None

    def clear(cell: Cell) -> bool:
        # swept cells lie within two steps of a rotation's goal: park farther away
        return cell not in state.goal and all(distance(cell, p) > 2 for p in pending)

    return _journey(state, mover, clear) or _journey(state, mover, lambda c: c not in state.goal)


def is_immobile(config: frozenset[Cell] | set[Cell], fixed: Cell | None = None) -> bool:
    """Fig. 4-6: no module can rotate without colliding or disconnecting the rest
    (the module on ``fixed`` is bolted to the base)."""
    occupied = set(config)
    if len(occupied) < 2:
        return True
    for cell in sorted(occupied):
        if cell == fixed:
            continue
        if any(True for _ in _moves_from(cell, occupied, cell)) and not is_cut(occupied, cell):
            return False
    return True


def check_inputs(initial: Configuration, goal: frozenset[Cell], fixed: Cell | None = None) -> str:
    """Why a reconfiguration is impossible from the start ("" if it may be possible)."""
    if fixed is not None and (fixed not in initial.cells or fixed not in goal):
        return f"the fixed module's cell {fixed} must be occupied in both configurations"
    if len(initial) != len(goal):
        return f"the initial configuration has {len(initial)} modules, the goal {len(goal)} cells"
    if not is_connected(initial.cells):
        return "the initial configuration is not connected"
    if not is_connected(goal):
        return "the goal configuration is not connected (no plan keeps modules together)"
    if initial.cells == goal:
        return ""
    if is_immobile(initial.cells, fixed):
        return ("the initial configuration is immobile (Fig. 4-6): no module can rotate "
                "without colliding or disconnecting the others")
    if is_immobile(goal, fixed):
        return ("the goal configuration is immobile (Fig. 4-6): rotations are reversible, "
                "so no rotation can end in it")
    # A cell entered for the last time has the cells filled before it occupied; if it
    # cannot be peeled even when every other goal module may be placed after it, no
    # order enters it (cells of the initial whose module never moves need no entry).
    stuck = fillable(goal, set(goal) - {fixed}) - initial.cells
    if stuck:
        return (f"goal cell {min(stuck)} can never be entered: it never has three consecutive "
                "free sides, which a Table 4-3 rotation sweeps")
    return ""


#: Above this many modules (and with no fixed module) a failed forward search goes
#: straight to the canonical strip: the backward search rarely helps there and costs seconds.
BACKWARD_LIMIT = 300


#: Above this many modules the middle-ball detour is skipped: its direct searches stall
#: there and each failed try costs seconds (measured: 6-9 s at 1,000 modules).
MIDDLE_LIMIT = 300


def direct_seconds(count: int) -> float:
    """The direct methods' own time cap. A local change plans in well under a
    second at any size; on the bench's 1,000-module pairs the direct method made
    up to 11,740 journeys (7 s) before it stalled, and never planned one there."""
    return 2.0 + count / 500


def direct_budget(count: int) -> int:
    """Fruitless journey searches the direct method may make before the planner
    moves on (successful direct plans make almost none; failing ones thousands)."""
    return 10 + min(count // 10, 20)


#: Share of the remaining time budget each method may use before the next one is
#: tried (the last method gets whatever is left).
SHARES = {"direct": 0.5, "direct, backwards": 0.3, "local": 0.3, "middle ball": 0.3}


def plan_robust(
    initial: Configuration,
    goal: frozenset[Cell],
    parallel: bool = True,
    max_moves: int = MAX_MOVES,
    fixed: Cell | None = None,
    budget: float | None = DEFAULT_BUDGET,
    progress: Callable[[str], None] | None = None,
) -> Plan:
    """Plan a connected, collision-free reconfiguration (see the module docstring).

    Methods, in order: the direct one forward, the direct one from the goal
    backwards (both with a search budget), the local method
    (:mod:`hexbot.planning.local`, with its own time cap; above its
    ``LOCAL_LIMIT`` modules it comes first, journey flows only, up to
    ``JOURNEY_LIMIT``), through a compact middle ball
    (:mod:`hexbot.planning.middle`, up to ``MIDDLE_LIMIT`` modules), then
    through a canonical strip (:mod:`hexbot.planning.canonical`). ``plan.method``
    says which one planned. The serial plan then loses the detours nothing
    needed (:mod:`hexbot.planning.tidy`; not the strip's) before the schedule.
    ``budget`` is the time budget in seconds (None: none); each method gets
    its ``SHARES`` of what is left and gives up with a reason when it is used
    up. ``progress`` is told each stage as it starts (a method's name, then
    "tidy" and "schedule"): at 10,000 modules a plan takes minutes.
    """
    tell = progress or (lambda stage: None)
    from hexbot.planning.canonical import replay, via_strip
    from hexbot.planning.local import JOURNEY_LIMIT, LOCAL_LIMIT, local_cap, via_local
    from hexbot.planning.middle import via_middle
    from hexbot.planning.regroup import regroup
    from hexbot.planning.tidy import shorten

    goal = frozenset(goal)
    deadline = Deadline(budget)
    plan = Plan(mode="robust", initial=initial, goal=goal, fixed=fixed)
    plan.lower_bound = move_lower_bound(initial.cells, goal).value
    reason = check_inputs(initial, goal, fixed)
    if reason:
        plan.reason = reason
        return plan
    searches = direct_budget(len(initial))
    n = len(initial)
    methods: list[tuple[str, Callable[[Deadline], list[Move]]]] = [
        ("direct", lambda d: serial_moves(initial, goal, max_moves, fixed, searches,
                                          deadline=d.capped(direct_seconds(n)))),
    ]
    if n <= BACKWARD_LIMIT or fixed is not None:
        methods.append(("direct, backwards", lambda d: reversed_plan(
            initial, goal, max_moves, fixed, searches, deadline=d.capped(direct_seconds(n)))))
    local = ("local", lambda d: via_local(
        initial, goal, max_moves, fixed, deadline=d.capped(local_cap(initial, goal))))
    # Small: the direct plans are the shortest when they exist. Large: the direct
    # methods planned none of the bench pairs, the journey flows most scrambles.
    if n <= JOURNEY_LIMIT:
        methods.insert(len(methods) if n <= LOCAL_LIMIT else 0, local)
    if n <= MIDDLE_LIMIT:
        methods.append(("middle ball", lambda d: via_middle(
            initial, goal, max_moves, fixed, searches, deadline=d)))
    methods.append(("canonical strip", lambda d: via_strip(
        initial, goal, max_moves, fixed=fixed, deadline=d)))
    failures: list[str] = []
    serial: list[Move] | None = None
    for name, method in methods:
        if deadline.expired():
            failures.append(f"{name}: not tried, the time budget of {budget:.3g} s is used up")
            continue
        share = deadline.share(SHARES.get(name, 1.0))
        tell(name)
        try:
            serial = method(share)
        except PlanningFailure as exc:
            failures.append(f"{name}: {exc}" if not str(exc).startswith(name) else str(exc))
            continue
        plan.method = name
        plan.tried = failures  # why it came to this one (a strip plan is long)
        break
    if serial is None:
        plan.reason = "no plan found: " + "; ".join(failures)
        return plan
    tidied = None
    if plan.method != "canonical strip":  # its journeys are shortest rolls already
        tell("tidy")
        tidied = shorten(initial, serial, deadline)
        serial = regroup(initial, tidied, fixed, deadline)
    if not parallel:
        plan.steps = [Step([m]) for m in serial]
    else:
        tell("schedule")
        plan.steps, late = schedule(initial, serial, deadline)
        if tidied is not None and len(tidied) != len(serial):
            # regrouped, a plan has fewer moves but can take more steps (one
            # module makes the moves of two, one after the other): the
            # shorter schedule wins, fewer moves on a tie
            steps, slow = schedule(initial, tidied, deadline)
            if len(steps) < len(plan.steps):
                plan.steps, late = steps, slow
        if late:
            plan.warnings.append(late)
    final = replay(initial, [m for step in plan.steps for m in step.moves])
    plan.reached = final.cells == goal
    if not plan.reached:  # a bug, not a user error: say so loudly
        plan.reason = "internal error: the schedule does not end in the goal"
    return plan


def reverse_move(move: Move) -> Move:
    """The rotation that undoes ``move`` (same substrate, same swept cells)."""
    for rule, (sx, sy), (gx, gy), _ in _RULES:
        x, y = move.dst
        if (x + sx, y + sy) == move.substrate and (x + gx, y + gy) == move.src:
            return new_move(move.module, move.dst, move.src, rule.joint, rule.direction,
                            move.substrate, move.substrate_module)
    raise ValueError(f"no rotation undoes {move}")


def reversed_plan(
    initial: Configuration,
    goal: frozenset[Cell],
    max_moves: int,
    fixed: Cell | None,
    budget: int | None = None,
    aside_limit: int | None = -1,
    deadline: Deadline = NO_DEADLINE,
    method: str = "direct, backwards",
) -> list[Move]:
    """Serial moves from ``initial`` to ``goal`` found by planning from the goal back."""
    from hexbot.planning.canonical import replay

    start = Configuration.from_cells(goal, first_id=1000)  # provisional ids
    backward = serial_moves(start, initial.cells, max_moves, fixed, budget, aside_limit,
                            deadline, method)
    config = replay(start, backward)
    real = {config[c].id: initial[c].id for c in config}
    return [
        replace(reverse_move(m), module=real[m.module], substrate_module=real[m.substrate_module])
        for m in reversed(backward)
    ]
