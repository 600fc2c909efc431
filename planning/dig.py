"""Digs: the journey flow's way into a goal cell, or out of a cell, that goal
modules wall in (used above the local method's ``LOCAL_LIMIT``, and below it
when no flow plans without them: shapes with holes).

A *hole* is a goal cell that no order of fills can enter: entering needs three
free sides in a row, and the goal modules around it stay. A walled-in *end*
is the same seen from a module off the goal that must leave. Blobs of 300
modules stall on both (docs/planning.md, "Digs").

A dig empties a set of cells, does the hole or the end, and fills the set
again:

* **a hole**: the goal is peeled once from the outside in (:func:`goal_peel`:
  each goal cell keeps the trio of cells peeled before it with the fewest
  cells behind them). Everything built after the hole in that order is the
  set; the modules on it, and the ends on the free sides its build needs,
  park where they can roll; a parked module fills the hole, and the others
  refill the set in build order (the outermost cells may stay voids, which
  the flow fills later from outside). When that dig fails, the peel around
  the modules standing now (:func:`state_peel`) is tried, where it parks
  fewer of them;
* **an end**: the current shape is peeled around it (:func:`_peeled`); the
  cells the cheapest trio of its sides needs park, the end takes the
  deepest emptied goal cell it can roll to (or leaves to a park), and the
  set is refilled in the reverse order. When that leaves as many cells
  walled in (the module left out, parked first, walled in where it waits),
  the end leaves to a park itself and every parked module refills;
* **a cavity**: an end packed with other walled-in ends (a cavity of the goal
  full of modules, :func:`_walled_cluster`): the peel around it with the end
  itself peelable gives the closure of every end of the cavity; the cells
  of all of them park (the ends stay out) and the goal cells refill. It is
  kept instead of the dig of the end alone when it adds fewer steps of
  dependent moves (:func:`~hexbot.planning.schedule.critical_chain`) per cell
  it frees: one cavity dug at once spares parking and refilling its wall
  once per end, but a big cavity can cost more than the few ends near its
  rim.

A module of a hole's set that rolls to a void of the goal (one whose fill
walls in nothing) stays there instead of parking: the flow refills the set
later from the ends, which have to travel anyway. Modules that hang on the
set alone leave with it. A dig that failed is not tried again until a
module near it has moved. For a void that no end reaches, a goal module
nearer the end fills it (:func:`propagate`, the thesis' void propagation).
Holes with big closures are dug before the flow fills anything
(:func:`dig_deep`); one still deeper than a dig reaches fails the flow at
once (:func:`check_depth`), and so does an end walled in deeper than that
before the flow starts (:func:`check_ends`).

A dig is kept only when fewer goal cells and ends are walled in afterwards
(so two digs in a row cannot undo each other), and a flow makes at most
``DIGS``.
Every module moves by rolls or journeys (:func:`hexbot.planning.journey.journey`),
so each intermediate configuration is connected and every rotation legal.
"""

from __future__ import annotations

import heapq
from functools import partial

from hexbot.planning.budget import PlanningFailure
from hexbot.planning.flow import _enterable
from hexbot.planning.hexlattice import Cell, distance, neighbors
from hexbot.planning.journey import CROSSING_STATES, _rolls, journey
from hexbot.planning.robust import Peel, _free_run, fillable, is_cut, unwind
from hexbot.planning.schedule import critical_chain
from hexbot.planning.windows import _can_leave, disc

#: Digs one flow may make; modules one dig may park.
DIGS = 40
DIG_LIMIT = 40
#: Holes whose closure has more cells than this are dug first (:func:`dig_deep`).
DEEP = 25
#: How far around an end its shape is peeled.
DIG_REACH = 10
#: A dig that failed is not tried again until a module within this distance
#: of its target has moved.
SAME_RADIUS = 12
#: Parks: the farthest cell a module rolls to within a depth of rotations (so
#: the next modules of the set still get out past it), else a journey to one of
#: the ``PARKS`` nearest border cells within ``PARK_RADIUS``. A dig whose
#: modules cannot all park is tried again with the next depth (10 alone left
#: one blob of 300 stuck, 15 alone another: docs/planning.md, "Digs").
PARK_DEPTHS = (10, 15)
PARKS = 10
PARK_RADIUS = 6
#: A stuck flow's sweep: each end that can roll, to this many nearest voids.
SWEEP_VOIDS = 4
#: Void propagation: how far from the void its filler may be, fillers tried
#: per void, and propagations per flow (each moves a void nearer an end).
PROPAGATE_REACH = 4
PROPAGATE_TRIES = 6
PROPAGATIONS = 400
#: Voids farther than this from every free end are not propagated: moving a
#: void one filler at a time over such a distance is a transport, the sweep's
#: and the finish's job (the blob of 10,000 spent 80 s of propagations on a lobe
#: about 100 cells from the ends and filled 7 voids; the blobs of 1,000
#: propagate from at most 32).
PROPAGATE_FAR = 40
#: States of a journey to a park (a cheap pass: most parks are rolls).
PARK_STATES = 300
#: Parts hanging on a dig's set smaller than this leave with it.
HANGING = 5
#: A module of a hole's set stops at a void it rolls to within this many
#: rotations (instead of parking and coming back).
VOID_DEPTH = 30

_PEELS: dict = {}
_STATE_PEELS: dict = {}


def forget() -> None:
    """Drop the cached peels: their closures hold one set per goal cell (818 MiB
    at 10,000 modules), which the strip tried after a failed flow does not need."""
    _PEELS.clear()
    _STATE_PEELS.clear()


def dig_holes(tracker, goal: frozenset[Cell], fixed: Cell | None, deadline,
              failed: set | None = None) -> bool:
    """Dig into one hole of the goal (tried in cell order). True when one was filled."""
    for hole in sorted(fillable(goal, set(goal - tracker.occupied))):
        if deadline.expired():
            return False
        if _tried(tracker, goal, fixed, hole, failed):
            return True
    return False


def dig_deep(tracker, goal: frozenset[Cell], fixed: Cell | None, deadline,
             failed: set | None = None) -> bool:
    """Dig into one hole whose closure has more than ``DEEP`` cells (deepest
    first). A flow digs these before it fills anything: its fills would fill
    the closure, which then has too many modules to dig (``DIG_LIMIT``), and
    the modules dug out still have voids to go to."""
    _, closure, _ = goal_peel(goal)
    holes = [h for h in fillable(goal, set(goal - tracker.occupied))
             if len(closure.get(h, ())) > DEEP]
    for hole in sorted(holes, key=lambda h: (-len(closure[h]), h)):
        if deadline.expired():
            return False
        if _tried(tracker, goal, fixed, hole, failed):
            return True
    return False


def check_depth(occupied: set[Cell], goal: frozenset[Cell], method: str) -> None:
    """Raise :class:`PlanningFailure` when a hole is left whose closure has more
    cells than a dig may move: once the flow has filled them, no dig reaches
    the hole, and the flow would spend its whole time cap to stall on it."""
    _, closure, _ = goal_peel(goal)
    # a hole the peel never reached needs the whole goal moved
    depth = {h: len(closure.get(h, goal)) - 1 for h in fillable(goal, set(goal - occupied))}
    deepest = max(depth, key=lambda h: (depth[h], h), default=None)
    if deepest is not None and depth[deepest] > DIG_LIMIT:
        raise PlanningFailure(f"{method}: goal cell {deepest} is walled in {depth[deepest]} "
                              f"cells deep, more than a dig moves ({DIG_LIMIT})")


def check_ends(occupied: set[Cell], goal: frozenset[Cell], method: str) -> None:
    """Raise :class:`PlanningFailure` when an end cannot leave before more
    modules that stay than a dig moves have made room. The mirror of
    :func:`check_depth`: the current shape is peeled from the outside in
    (:func:`state_peel`, counting only the modules that both shapes keep),
    and an end that is not reached within ``DIG_LIMIT`` of them is walled in
    now. It only gets more walled in as the goal fills round it, because
    ends that leave do not count. On the blob of 10,000 two ends sit side by
    side in a notch of the start, each blocking the other's way out. The
    flow spent its whole time cap on them before the strip planned
    (docs/planning.md, "The blob of 10,000: a notch of the start")."""
    shape = frozenset(occupied)
    order, _, _ = state_peel(shape, shape & goal)
    walled = sorted(end for end in shape - goal if end not in order)
    if walled:
        raise PlanningFailure(
            f"{method}: end {walled[0]} can leave only after more than {DIG_LIMIT} modules "
            f"that stay have moved, more than a dig moves"
            + (f" ({len(walled)} such ends)" if len(walled) > 1 else ""))


def dig_ends(tracker, goal: frozenset[Cell], fixed: Cell | None, deadline,
             failed: set | None = None, beside: bool = False) -> bool:
    """Dig one walled-in end out. True when one left. ``beside``: the last
    resort of a flow that is otherwise stuck, parks beside the dig's set too."""
    occupied = tracker.occupied
    for end in sorted(fillable(frozenset(occupied), occupied - goal) - {fixed}):
        if deadline.expired():
            return False
        if _tried(tracker, goal, fixed, end, failed, beside):
            return True
    return False


def _tried(tracker, goal: frozenset[Cell], fixed: Cell | None, target: Cell,
           failed: set | None, beside: bool = False) -> bool:
    """:func:`_kept`, skipped when it failed before with the same modules
    within ``SAME_RADIUS`` (a stuck flow asks again after every change
    elsewhere)."""
    if failed is None:
        return _kept(tracker, goal, fixed, target, beside)
    occupied = tracker.occupied
    question = ("dig", target, beside,
                frozenset(c for c in disc(target, SAME_RADIUS) if c in occupied))
    if question in failed:
        return False
    if _kept(tracker, goal, fixed, target, beside):
        return True
    failed.add(question)
    return False


def sweep(occupied: set[Cell], goal: frozenset[Cell], ends: set[Cell], voids: set[Cell],
          fixed: Cell | None, failed: set):
    """A journey of any end that can roll to one of its ``SWEEP_VOIDS`` nearest
    voids that can be entered now (the flow's ranked candidates pair voids with
    their nearest ends, which are often walled in), fills that wall nothing in
    first, then the shortest. The hops, or None."""
    peel = Peel(goal, voids)
    open_voids = [v for v in sorted(voids) if _enterable(occupied, v)]
    tries = []
    for end in sorted(ends):
        if end == fixed or not _can_leave(occupied, end) or is_cut(occupied, end):
            continue
        for void in sorted(open_voids, key=lambda v: (distance(end, v), v))[:SWEEP_VOIDS]:
            walls = peel.walls_in(goal, voids, void)
            tries.append((walls, distance(end, void), end, void))
    for _, _, end, void in sorted(tries):
        hops = journey(occupied, end, void, fixed, CROSSING_STATES, failed)
        if hops:
            return hops
    return None


def propagate(occupied: set[Cell], goal: frozenset[Cell], ends: set[Cell], voids: set[Cell],
              fixed: Cell | None, failed: set):
    """The thesis' void propagation, for a void no end reaches: a goal module
    within ``PROPAGATE_REACH`` of the void and nearer the void's nearest free
    end fills it, so the void moves towards that end. Nothing is walled in.
    The hops, or None."""
    free_ends = [e for e in sorted(ends)
                 if e != fixed and _can_leave(occupied, e) and not is_cut(occupied, e)]
    if not free_ends:
        return None
    walled = fillable(goal, voids)
    for void in sorted(voids - walled, key=lambda v: (min(distance(v, e) for e in free_ends), v)):
        end = min(free_ends, key=lambda e: (distance(void, e), e))
        far = distance(void, end)
        if far > PROPAGATE_FAR:
            break  # the voids come nearest first
        movers = [m for m in disc(void, PROPAGATE_REACH)
                  if m in occupied and m in goal and m != fixed and distance(m, end) < far
                  and _can_leave(occupied, m)]
        tried = 0
        for m in sorted(movers, key=lambda m: (distance(m, void) + distance(m, end), m)):
            if tried == PROPAGATE_TRIES:
                break
            if is_cut(occupied, m) or fillable(goal, (voids - {void}) | {m}) - walled:
                continue
            tried += 1
            hops = journey(occupied, m, void, fixed, CROSSING_STATES, failed)
            if hops:
                return hops
    return None


def goal_peel(goal: frozenset[Cell]):
    """The goal peeled from the outside in (a cell goes when three sides in a
    row are off the goal or gone): per goal cell its round, its closure (the
    cell and every goal cell built after it that its build needs) and its
    trio. Cached for the last goal (a flow asks again and again)."""
    cached = _PEELS.get(goal)
    if cached is not None:
        return cached
    rounds: dict[Cell, int] = {}
    closure: dict[Cell, frozenset[Cell]] = {}
    trios: dict[Cell, tuple[Cell, ...]] = {}
    left = set(goal)
    level = 0
    while left:
        peeled = {}
        for cell in left:
            best = None
            for trio in _trios(cell):
                if all(n not in goal or n in rounds for n in trio):
                    cells = frozenset({cell}).union(*(closure[n] for n in trio if n in goal))
                    if best is None or len(cells) < len(best[0]):
                        best = (cells, trio)
            if best is not None:
                peeled[cell] = best
        if not peeled:
            break  # the rest cannot be built from outside: no dig into it
        for cell, (cells, trio) in peeled.items():
            rounds[cell], closure[cell], trios[cell] = level, cells, trio
        left -= set(peeled)
        level += 1
    _PEELS.clear()
    _PEELS[goal] = (rounds, closure, trios)
    return rounds, closure, trios


def state_peel(goal: frozenset[Cell], occupied: frozenset[Cell]):
    """The goal peeled from the outside in as :func:`goal_peel` does, but each
    goal cell keeps the trio whose build empties the fewest modules standing
    now (a Dijkstra over that count: cells go in order of it, not in rounds):
    per goal cell its place in that order (higher: built earlier), its closure
    and its trio. A hole's dig parks the modules on its closure and trio
    cells; on blob 1,000 seed 4 the deepest hole needs 23 of them instead of
    the goal peel's 37, and others 5 instead of 16 (docs/planning.md, "Digs").
    The cells whose build parks more than ``DIG_LIMIT`` modules are left out
    (the sets grow with the depth: on a scramble of 10,000 a full peel took
    6 s). Cached for the last goal and modules."""
    cached = _STATE_PEELS.get((goal, occupied))
    if cached is not None:
        return cached
    emptied: dict[Cell, frozenset[Cell]] = {}  # cell -> modules its build parks
    closure: dict[Cell, frozenset[Cell]] = {}
    trios: dict[Cell, tuple[Cell, ...]] = {}
    order: dict[Cell, int] = {}
    none: frozenset[Cell] = frozenset()

    def cheapest(cell: Cell):
        best = None
        for trio in _trios(cell):
            parts = []
            for n in trio:
                if n not in goal:
                    parts.append(frozenset((n,)) if n in occupied else none)
                elif n in emptied:
                    parts.append(emptied[n])
                else:
                    break
            else:
                cells = parts[0].union(parts[1], parts[2])
                if best is None or len(cells) < len(best[0]):
                    best = (cells, trio)
        return best

    heap: list[tuple[int, Cell]] = []
    for cell in goal:
        found = cheapest(cell)
        if found is not None:
            heapq.heappush(heap, (len(found[0]), cell))
    while heap:
        size, cell = heapq.heappop(heap)
        if size > DIG_LIMIT:  # no dig parks that many: the cells left are of no use
            break
        if cell in emptied:
            continue
        cells, trio = cheapest(cell)
        if len(cells) != size:  # cheaper since it was queued: queued again
            heapq.heappush(heap, (len(cells), cell))
            continue
        emptied[cell] = cells | {cell} if cell in occupied else cells
        closure[cell] = frozenset({cell}).union(*(closure[n] for n in trio if n in goal))
        trios[cell], order[cell] = trio, len(order)
        for n in neighbors(cell):
            if n in goal and n not in emptied:
                found = cheapest(n)
                if found is not None:
                    heapq.heappush(heap, (len(found[0]), n))
    _STATE_PEELS.clear()
    _STATE_PEELS[goal, occupied] = (order, closure, trios)
    return order, closure, trios


def _trios(cell: Cell) -> list[tuple[Cell, ...]]:
    """The six runs of three sides in a row."""
    ring = neighbors(cell)
    return [(ring[i], ring[(i + 1) % 6], ring[(i + 2) % 6]) for i in range(6)]


def _kept(tracker, goal: frozenset[Cell], fixed: Cell | None, target: Cell,
          beside: bool = False) -> bool:
    """Dig at ``target``; kept when fewer cells are walled in afterwards. With
    ``beside`` only the digs of an end that may park beside its set."""
    def walled_in() -> tuple[set[Cell], set[Cell]]:
        """The goal cells and the ends walled in."""
        occupied = tracker.occupied
        return (fillable(goal, set(goal - occupied)),
                fillable(frozenset(occupied), occupied - goal))

    def walled() -> int:
        return sum(map(len, walled_in()))

    holes, ends = walled_in()
    before = len(holes) + len(ends)
    start = len(tracker.moves)

    def first(tries) -> float | None:
        """The first of ``tries`` that walls in fewer cells, its moves kept: the
        longest chain of dependent moves it adds per cell it frees (None: no try)."""
        for dig_once in tries:
            done = dig_once(tracker, goal, fixed, target)
            freed = before - walled() if done else 0
            if freed > 0:
                return critical_chain(tracker.moves[start:])[0] / freed
            tracker.undo_to(start)
        return None

    if target in tracker.occupied:
        # the end takes an emptied goal cell (a parked module stays out), else
        # it leaves to a park itself: the module that stays out was parked
        # first, deepest, and the refill can wall it in (blob 2,000 seed 0)
        single = [partial(_dig_end, depth=depth, shift=shift, beside=beside)
                  for shift in (True, False) for depth in PARK_DEPTHS]
        # a cavity of the goal full of ends is dug out at once when that takes
        # fewer steps per cell freed than digging them one by one (blob 1,000
        # seed 0: five digs of one end or two, each parking the same wall)
        cavity = _walled_cluster(ends - {fixed}, target)
        if len(cavity) < 2:
            return first(single) is not None
        cavity = [partial(_dig_cavity, depth=depth, cluster=cavity, beside=beside)
                  for depth in PARK_DEPTHS]
        at_once = first(cavity)
        if at_once is None:
            return first(single) is not None
        tracker.undo_to(start)
        one = first(single)
        if one is not None and one <= at_once:
            return True
        tracker.undo_to(start)
        return first(cavity) is not None
    if beside:
        return False  # holes are dug with parks beside their sets already
    # a hole: the goal's peel, then the peel around the modules standing now
    # (only when it parks fewer modules: on blob 300 seed 0 digs by it as
    # a fallback made the plan 30 % longer; tried first, it cost two of
    # the eight blobs of 1,000 their local plans)
    occupied = frozenset(tracker.occupied)
    peels = [goal_peel(goal)]
    around = state_peel(goal, occupied)
    fewer = len(_dug(around, target) & occupied)
    if target in around[1] and (target not in peels[0][1]
                                or fewer < len(_dug(peels[0], target) & occupied)):
        peels.append(around)
    return first([partial(_dig_hole, depth=depth, peel=peel)
                  for peel in peels for depth in PARK_DEPTHS]) is not None


def _dug(peel, hole: Cell) -> set[Cell]:
    """The cells a dig into ``hole`` empties by ``peel``: its closure and the
    free sides their builds need (the ends sitting there leave too)."""
    _, closure, trios = peel
    if hole not in closure:
        return set()
    return set(closure[hole]) | {n for c in closure[hole] for n in trios[c]}


def _dig_hole(tracker, goal: frozenset[Cell], fixed: Cell | None, hole: Cell,
              depth: int, peel) -> bool:
    occupied = tracker.occupied
    rounds, closure, trios = peel
    if hole not in closure:
        return False
    cells = set(closure[hole] - {hole})
    kept_free = _dug(peel, hole)
    removed = kept_free & occupied
    if fixed in removed or len(removed) > DIG_LIMIT:
        return False
    parked = _empty(tracker, goal, fixed, hole, removed, kept_free, depth, margin=False,
                    to_voids=True)
    if parked is None:
        return False
    for cell in sorted(cells | {hole}, key=lambda c: (-rounds[c], c)):
        if not parked:
            break
        if cell in occupied:
            continue
        if not _fill_from(tracker, parked, cell, fixed):
            return cell != hole  # the outermost cells may stay voids
    return True


def _dig_end(tracker, goal: frozenset[Cell], fixed: Cell | None, end: Cell,
             depth: int, shift: bool = True, beside: bool = False) -> bool:
    occupied = tracker.occupied
    gone, close = _peeled(frozenset(occupied), end, fixed)
    sets = [frozenset().union(*(close(n) for n in trio if n in occupied))
            for trio in _trios(end) if all(n not in occupied or n in gone for n in trio)]
    for removed in sorted(sets, key=lambda c: (len(c), sorted(c)))[:2]:
        if fixed in removed or len(removed) > DIG_LIMIT:
            continue
        start = len(tracker.moves)
        order: list[Cell] = []
        parked = _empty(tracker, goal, fixed, end, set(removed), set(removed) | {end}, depth,
                        order=order, beside=beside)
        if parked is not None and not is_cut(occupied, end):
            refill = [c for c in reversed(order) if c in goal]
            parent = _rolls(occupied, end)[0]
            # the end takes the deepest emptied goal cell it rolls to (a parked
            # module stays out in its place), else it leaves to a park
            into = next((c for c in refill if c in parent), None) if shift else None
            found = ((unwind(parent, into), into) if into is not None
                     else _park(occupied, goal, end, fixed, set(removed), depth))
            if found:
                tracker.roll(found[0])
                for cell in refill:  # the outermost cells may stay voids
                    if cell != into and not _fill_from(tracker, parked, cell, fixed):
                        break
                return True
        tracker.undo_to(start)
    return False


def _dig_cavity(tracker, goal: frozenset[Cell], fixed: Cell | None, end: Cell,
                depth: int, cluster: set[Cell], beside: bool = False) -> bool:
    """Dig out ``end`` and the walled-in ends packed with it (``cluster``) at once."""
    occupied = tracker.occupied
    gone, close = _peeled(frozenset(occupied), end, fixed, keep_target=False)
    cluster = cluster & gone
    if len(cluster) < 2:
        return False
    removed = set().union(*(close(c) for c in cluster))
    if fixed in removed or len(removed) > DIG_LIMIT:
        return False
    start = len(tracker.moves)
    order: list[Cell] = []
    parked = _empty(tracker, goal, fixed, end, set(removed), set(removed), depth, order=order,
                    beside=beside)
    if parked is None:
        tracker.undo_to(start)
        return False
    for cell in [c for c in reversed(order) if c in goal]:
        if not _fill_from(tracker, parked, cell, fixed):
            break  # the outermost cells may stay voids
    return True


def _walled_cluster(walled: set[Cell], end: Cell) -> set[Cell]:
    """``end`` and the ``walled`` ends (the walled-in ones) touching it through
    walled-in ends, within ``DIG_REACH``: a cavity of the goal full of modules."""
    found, queue = {end}, [end]
    while queue:
        for n in neighbors(queue.pop()):
            if n in walled and n not in found and distance(n, end) <= DIG_REACH:
                found.add(n)
                queue.append(n)
    return found


def _peeled(occupied: frozenset[Cell], target: Cell, fixed: Cell | None,
            keep_target: bool = True):
    """The occupied cells within ``DIG_REACH`` of ``target`` peeled from the
    outside in: the cells that can go, and a function giving a cell's closure
    (the cell and the peeled cells that had to go before it). With
    ``keep_target`` the module at ``target`` stays (the cells that free it)."""
    region = {c for c in disc(target, DIG_REACH)
              if c in occupied and c != fixed and (c != target or not keep_target)}
    gone: set[Cell] = set()
    needs: dict[Cell, list[Cell]] = {}
    changed = True
    while changed:
        changed = False
        for cell in sorted(region - gone):
            best = None
            for trio in _trios(cell):
                if all(n not in occupied or n in gone for n in trio):
                    used = [n for n in trio if n in gone]
                    if best is None or len(used) < len(best):
                        best = used
            if best is not None:
                needs[cell] = best
                gone.add(cell)
                changed = True
    closure: dict[Cell, frozenset[Cell]] = {}

    def close(cell: Cell) -> frozenset[Cell]:
        if cell not in closure:
            closure[cell] = frozenset()  # a cycle cannot recurse
            closure[cell] = frozenset({cell}).union(*(close(n) for n in needs.get(cell, ())))
        return closure[cell]

    return gone, close


def _empty(tracker, goal: frozenset[Cell], fixed: Cell | None, target: Cell,
           removed: set[Cell], kept_free: set[Cell], depth: int,
           order: list[Cell] | None = None, margin: bool = True,
           to_voids: bool = False, beside: bool = False) -> list[Cell] | None:
    """Park the modules of ``removed``, farthest from ``target`` first, off
    ``kept_free``: the parked cells (last parked last), or None when stuck."""
    occupied = tracker.occupied
    left = set(removed)
    parked: list[Cell] = []
    spare = HANGING  # modules hanging on the set that may leave first
    anchor = _anchor(occupied, left)
    while left:
        ready = sorted((c for c in left if _free_run(occupied, c) and not is_cut(occupied, c)),
                       key=lambda c: (-distance(c, target), c))
        if not ready and spare:  # modules hanging on the set alone leave first
            hanging = set().union(*(_hanging(occupied, c) for c in left
                                    if _free_run(occupied, c))) - left - {fixed}
            ready = sorted(c for c in hanging if _free_run(occupied, c)
                           and not is_cut(occupied, c))
            spare -= 1
        if not _leave_one(tracker, goal, fixed, target, ready[:3], left, kept_free, depth,
                          order, parked, anchor, margin, to_voids, beside):
            return None
    return parked


def _leave_one(tracker, goal: frozenset[Cell], fixed: Cell | None, target: Cell,
               ready: list[Cell], left: set[Cell], kept_free: set[Cell], depth: int,
               order: list[Cell] | None, parked: list[Cell], anchor: set[Cell],
               margin: bool, to_voids: bool, beside: bool) -> bool:
    """One of ``ready`` leaves the set: to a void, else to a park off the set's
    sides, else (with ``beside``) to a park beside the set."""
    occupied = tracker.occupied
    for next_to in (False, True) if beside else (False,):
        for cell in ready:
            found = None
            if to_voids and len(left) > 1 and not next_to:
                found = _to_void(occupied, goal, cell, kept_free)
            if found:
                tracker.roll(found[0])
                left.discard(cell)
                _anchored(anchor, cell, found[1])
                return True
            # (a hanging module parks off the set's sides, not to hang on it again)
            found = _park(occupied, goal, cell, fixed, kept_free, depth,
                          (margin or cell not in left) and not next_to, anchor)
            if found:
                tracker.roll(found[0])
                parked.append(found[1])
                _anchored(anchor, cell, found[1])
                if order is not None and cell in left:
                    order.append(cell)
                left.discard(cell)
                return True
    return False


def _anchor(occupied: set[Cell], left: set[Cell]) -> set[Cell]:
    """The largest piece of the modules a dig keeps (``occupied`` without ``left``):
    a park must touch it, not hang on the structure through the set's cells,
    which would make the set's last modules cut vertices that cannot leave
    (holes 100 seed 5: parks rolled out along a module that hung on the set
    and the dig stalled with 4 of 24 to go)."""
    rest = occupied - left
    best: set[Cell] = set()
    while rest:
        piece, queue = set(), [rest.pop()]
        while queue:
            cell = queue.pop()
            piece.add(cell)
            for n in neighbors(cell):
                if n in rest:
                    rest.discard(n)
                    queue.append(n)
        if len(piece) > len(best):
            best = piece
    return best


def _anchored(anchor: set[Cell], left_cell: Cell, park: Cell) -> None:
    """The anchor after a module rolled from ``left_cell`` to ``park``."""
    anchor.discard(left_cell)
    if any(n in anchor for n in neighbors(park)):
        anchor.add(park)


def _hanging(occupied: set[Cell], cell: Cell) -> set[Cell]:
    """The modules that hold on to the structure only through ``cell``: its
    neighbours' parts of fewer than ``HANGING`` cells once ``cell`` is empty."""
    hanging: set[Cell] = set()
    for n in neighbors(cell):
        if n not in occupied or n in hanging:
            continue
        part, queue = {n}, [n]
        while queue and len(part) < HANGING:
            for m in neighbors(queue.pop()):
                if m in occupied and m != cell and m not in part:
                    part.add(m)
                    queue.append(m)
        if len(part) < HANGING:
            hanging |= part
    return hanging


def _park(occupied: set[Cell], goal: frozenset[Cell], cell: Cell, fixed: Cell | None,
          avoid: set[Cell], depth_limit: int, margin: bool = True,
          anchor: set[Cell] | None = None):
    """(hops, park) taking the module at ``cell`` off ``avoid`` (and, with
    ``margin``, off its neighbours), onto a cell touching ``anchor`` when
    given, or None."""
    def allowed(p: Cell) -> bool:
        return (p not in avoid and not (margin and any(n in avoid for n in neighbors(p)))
                and (anchor is None or any(n in anchor and n != cell for n in neighbors(p))))

    parent, depth = _rolls(occupied, cell)
    rolled = [p for p in parent if p != cell and allowed(p)]
    if rolled:
        near = [p for p in rolled if depth[p] <= depth_limit]
        off_goal = [p for p in near if p not in goal]
        if off_goal or near:
            park = max(off_goal or near, key=lambda p: (depth[p], p))
        else:
            park = min(rolled, key=lambda p: (depth[p], p))
        return unwind(parent, park), park
    border = {n for c in disc(cell, PARK_RADIUS) if c in occupied
              for n in neighbors(c) if n not in occupied}
    for park in sorted((p for p in border if allowed(p)),
                       key=lambda p: (p in goal, distance(p, cell), p))[:PARKS]:
        hops = journey(occupied, cell, park, fixed, PARK_STATES)
        if hops:
            return hops, park
    return None


def _to_void(occupied: set[Cell], goal: frozenset[Cell], cell: Cell, avoid: set[Cell]):
    """(hops, void): the module at ``cell`` rolls to the nearest void of the goal
    off ``avoid`` whose fill walls in no other void, or None."""
    parent, depth = _rolls(occupied, cell)
    voids = set(goal - occupied)
    peel = None
    for p in sorted((p for p in parent if p in voids and p not in avoid
                     and depth[p] <= VOID_DEPTH), key=lambda p: (depth[p], p)):
        peel = peel or Peel(goal, voids)
        if not peel.walls_in(goal, voids, p):
            return unwind(parent, p), p
    return None


def _fill_from(tracker, parked: list[Cell], cell: Cell, fixed: Cell | None) -> bool:
    """A parked module (the last parked first) journeys to ``cell``."""
    occupied = tracker.occupied
    for i in reversed(range(len(parked))):
        if parked[i] not in occupied:  # a crossing of an earlier refill moved it on
            continue
        if is_cut(occupied, parked[i]):
            continue
        hops = journey(occupied, parked[i], cell, fixed)
        if hops:
            tracker.roll(hops)
            parked.pop(i)
            return True
    return False

