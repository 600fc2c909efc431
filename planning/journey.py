"""Journeys across surface segments, and the journey flow built on them.

With every other module fixed, a module rolls only within one *segment* of
the surface (:mod:`hexbot.planning.surface`): a 120-degree rotation cannot
cross the mouth of a one-cell inlet. A :func:`journey` still gets a module
from a cell to leave to a cell to fill, in moves that grow with the distance:

1. it rolls, others fixed, to the cell of its segment nearest the target
   along the border (:func:`hexbot.planning.surface.border_steps`);
2. there a *crossing* (:func:`crossing`) takes it over the mouth: an A*
   search over the modules of a small disc around it (radius 2, then 3),
   whose only accepted end is the disc as it was with the traveller moved to
   a border cell nearer the target. The wall modules step aside and come
   back (the "monkey" moves of Akitaya et al.); the one left on the far side
   need not be the one that came, the cells are what count;
3. repeat until the target is reached; each crossing lowers the border
   distance, so a journey ends or fails within ``CROSSINGS`` crossings.

Every intermediate configuration is connected: the configuration without
the traveller never changes between crossings (a crossing restores it), the
traveller starts off a cell that is not a cut vertex, and each module moved
in a crossing has its occupied sides in one arc (it cannot disconnect
anything).

The **journey flow** (:func:`journey_flow`) fills the goal's empty cells one
journey at a time: the ends (modules off the goal) are assigned to the voids
(cheapest assignment), and for each void its assigned end and the nearest
others are candidates, preferring fills that wall in no void still to fill
and no end still to leave (peeling, as :func:`hexbot.planning.robust.fillable`),
then the shortest. It is a local plan: a journey's moves follow the border
distance and a few crossings, never the number of modules. A goal cell that
no order of fills can enter (a hole, a one-cell notch: entering needs three
free sides in a row) is opened first: the goal modules walling it in step
aside off the goal (:func:`channels`) and are refilled later like any void.
When the flow has planned, its long journeys become **relays**
(:func:`relay`): a goal module beside the route takes the first leg, the
traveller the second, and the schedule runs both legs at once.
"""

from __future__ import annotations

from bisect import bisect_right
from collections import deque
from dataclasses import dataclass

import numpy as np

from hexbot.planning import _crossing
from hexbot.planning.budget import PlanningFailure
from hexbot.planning.configuration import Configuration
from hexbot.planning.hexlattice import Cell, distance, neighbors
from hexbot.planning.robust import (
    _AROUND12,
    _OPEN12,
    _RULES,
    Peel,
    _moves_from,
    _single_arc,
    fillable,
    is_cut,
    unwind,
)
from hexbot.planning.schedule import critical_chain, schedule_in_pieces, stays_connected
from hexbot.planning.surface import border_steps
from hexbot.planning.tracker import Hop, Tracker
from hexbot.planning.windows import (
    _LEAVABLE,
    _can_leave,
    assigned_pairs,
    disc,
    distance_matrix,
)

#: Disc radii of a crossing, tried in turn, and the states one search may visit:
#: a cheap pass over many candidate journeys first (most crossings need fewer
#: than 200 states), then a thorough one over the best few.
CROSSING_RADII = (2, 3)
CHEAP_STATES = 300
CROSSING_STATES = 4000
THOROUGH_TRIES = 8
#: With digs, a flow that nothing else moves on tries its best candidate
#: journeys once more with ``LAST_STATES`` per crossing (``LAST_TRIES`` times
#: per flow, ``LAST_PAIRS`` candidates each): on blob 1,000 seed 0 the flow
#: stalled with one void 35 cells from the one end, a journey of 104 rotations
#: whose crossing needs 32,000 states (0.2 s).
LAST_STATES = 40_000
LAST_TRIES = 10
LAST_PAIRS = 3
#: Fills taken back when stuck, and how near a stuck end a fill must be to be taken back.
BACKTRACKS = 20
NEAR = 2
#: Walled-in ends tried for a helper (:func:`_make_room`) when no journey is found.
HELPERS = 4
#: Goal modules tried per end to hand over to (:func:`_hand_over`).
HAND_OVERS = 16
#: Walls stepping aside (:func:`channels`): at most this many at once (a pair
#: needing more is left to the other methods), parking within ``PARK_RADIUS``
#: of the wall, ``PARKS`` cells tried each; a stuck flow opens walls again at
#: most ``ASIDES`` times (the fills close them, so this keeps the flow finite).
ASIDE_LIMIT = 100
PARK_RADIUS = 3
PARKS = 4
ASIDES = 2
#: Crossings one journey may make (each lowers the border distance).
CROSSINGS = 40
#: Ends tried per void besides its assigned one (nearest first).
NEAREST_ENDS = 3
#: Relays (:func:`relay`): journeys of more rotations than ``RELAY_LONG`` are
#: split at a goal module beside their middle third (``RELAY_TRIES`` tried,
#: most evenly placed first) when each part is shorter than ``RELAY_GAIN``
#: times the whole; parts are split again, ``RELAY_DEPTH`` levels deep.
RELAY_LONG = 8
RELAY_TRIES = 6
RELAY_GAIN = 0.8
RELAY_DEPTH = 3
#: With digs, times a stuck flow hands its ends and voids to
#: :func:`hexbot.planning.finish.finish` (legs along the surface) before it fails.
FINISHES = 3
#: After a sweep filled a void (the ranked journeys, the room-making and the
#: hand-overs all failed before it), the next round tries the sweep first.
SWEEP_FIRST = True
#: Longest run of journeys on the critical path reversed (:func:`_reorder`).
REORDER_RUN = 4
#: With digs, a failed journey is tried again only when a module within this
#: distance of its mover or its void has moved.
SAME_AROUND = 4
_FAR = 10**9


@dataclass(frozen=True)
class Policy:
    """How the journey flow ranks and tries its candidates. The flow is greedy,
    and which pairs one policy leaves stuck differs from another's, so the
    local method runs a few (measured in docs/planning.md)."""

    #: Rank movers by distance plus ``spread`` times their free sides (hard
    #: modules first, free tips last: they travel anywhere in the endgame).
    spread: float = 0.0
    #: Candidate journeys tried per fill before the flow is stuck.
    tries: int = 24
    #: Per void, also the nearest ends that are not walled in (the nearest
    #: ends often are).
    nearest_free: int = 0
    #: Count a fill beside an end walled in already as walling it in (it loses
    #: a free side it needs to get out later).
    guard_walled: bool = False


#: The policies the local method runs, in order (the first plans the
#: 1,000-module scrambles fastest; the second plans more blobs of 100).
POLICIES = {
    "journey": Policy(),
    "journey, wide": Policy(tries=64, nearest_free=2, guard_walled=True),
    "journey, hard first": Policy(spread=3.0),
}


def _rolls(occupied: set[Cell], start: Cell) -> tuple[dict[Cell, tuple | None], dict[Cell, int]]:
    """Breadth-first (parents, rotations) of every cell the module at ``start``
    rolls to, others fixed."""
    parent: dict[Cell, tuple | None] = {start: None}
    depth = {start: 0}
    queue = deque([start])
    while queue:
        cell = queue.popleft()
        for rule, sub, dst in _moves_from(cell, occupied, start):
            if dst not in parent:
                parent[dst] = (cell, rule, sub)
                depth[dst] = depth[cell] + 1
                queue.append(dst)
    return parent, depth


class _Disc:
    """A crossing's window around (0, 0), indexed once per radius and handed to
    the C search: a window state is an int with one bit per window cell (the
    cells in sorted order, so ascending bits visit them as ``sorted`` does),
    the two rings around it follow as the bits above. Translating the window
    keeps the order, so one index serves every crossing of that radius."""

    def __init__(self, radius: int):
        window = sorted(disc((0, 0), radius))
        inside = set(window)
        rim = {n for c in window for n in neighbors(c)}
        rim |= {n for c in rim for n in neighbors(c)}
        self.cells = cells = window + sorted(rim - inside)
        index = {c: i for i, c in enumerate(cells)}
        self.size = size = len(window)
        center = index[(0, 0)]
        ring6 = [index[n] for c in window for n in neighbors(c)]
        ring12 = [index[(x + dx, y + dy)] for x, y in window for dx, dy in _AROUND12]
        # Window bits only: the rim's modules never move.
        near = [sum(1 << index[n] for n in (c, *neighbors(c)) if index[n] < size)
                for c in window]
        goal_index = [index[(x + gx, y + gy)] if (x + gx, y + gy) in inside else -1
                      for x, y in window for gx, gy in _GOALS]
        self.key = _crossing.add_disc(size, len(cells), center, ring6, ring12, near,
                                      goal_index, len(_GOALS))


#: The goal offsets of the rotations, coded by position for the C search.
_GOALS = sorted({goal for _, _, goal, _ in _RULES})
_crossing.set_rules(_LEAVABLE, [[_GOALS.index(goal) for _, _, goal in options]
                                for options in _OPEN12])
_WORD = (1 << 64) - 1
_DISCS = {radius: _Disc(radius) for radius in CROSSING_RADII}


def crossing(occupied: set[Cell], traveller: Cell, radius: int, steps: dict[Cell, int],
             fixed: Cell | None, max_states: int = CROSSING_STATES,
             failed: set | None = None) -> tuple[list[Hop], Cell] | None:
    """Rotations inside the window of ``radius`` around ``traveller`` after which
    the window is as before except that ``traveller``'s cell is empty and a cell
    ``q`` nearer the target (``steps[q] < steps[traveller]``) is occupied:
    (hops, q), or None.

    A* over the window's occupied cells (a state is accepted when generated,
    so the hops are few, not always the fewest); the estimate is the number of
    the window's other modules not home yet (each needs a rotation). States
    are bit masks over the window (:class:`_Disc`); the search itself runs in
    C (``planning/_crossing.c``: most of a large plan's time was spent here).
    ``failed`` remembers the searches that found nothing: a flow asks the same
    question again and again while the cells around a stuck module stay as
    they are."""
    geometry = _DISCS[radius]
    cells, size = geometry.cells, geometry.size
    tx, ty = traveller
    absolute = [(tx + x, ty + y) for x, y in cells]
    bits = [c in occupied for c in absolute]
    start = sum(1 << i for i in range(size) if bits[i])
    # Only the modules within two cells of the window matter to its rotations.
    outside = sum(1 << i for i in range(size, len(cells)) if bits[i])
    bound = steps.get(traveller, _FAR)
    nearer = sum(1 << i for i in range(size) if steps.get(absolute[i], _FAR) < bound)
    if failed is not None:
        question = (traveller, start, outside, max_states, fixed, nearer)
        if question in failed:
            return None
    pinned = 0
    if fixed is not None:
        pinned = sum(1 << i for i in range(size) if absolute[i] == fixed)
    found = _crossing.search(geometry.key, start, outside & _WORD, outside >> 64, pinned,
                             nearer, max_states)
    if found is None:
        if failed is not None:
            failed.add(question)
        return None
    moves, arrived = found
    hops = []
    for mover, target, mask, option in moves:
        rule, (sx, sy), _ = _OPEN12[mask][option]
        x, y = absolute[mover]
        hops.append(((x, y), absolute[target], rule, (x + sx, y + sy)))
    return hops, absolute[arrived]


def _apply(occupied: set[Cell], hops: list[Hop]) -> None:
    for src, dst, _, _ in hops:
        occupied.discard(src)
        occupied.add(dst)


def journey(occupied: set[Cell] | frozenset[Cell], start: Cell, target: Cell,
            fixed: Cell | None = None, max_states: int = CROSSING_STATES,
            failed: set | None = None) -> list[Hop] | None:
    """Rotations taking a module from ``start`` (occupied, not a cut vertex) to
    ``target`` (empty), rolling within segments and crossing between them; the
    other cells end as they were. None when a crossing is not found."""
    occupied = set(occupied)
    steps = border_steps(occupied - {start}, target, stop=start)
    hops: list[Hop] = []
    here = start
    for _ in range(CROSSINGS):
        parent, depth = _rolls(occupied, here)
        if target in parent:
            return hops + unwind(parent, target)
        reached = [c for c in parent if c in steps] or [here]
        best = min(reached, key=lambda c: (steps.get(c, _FAR), depth[c], c))
        if best != here:
            path = unwind(parent, best)
            _apply(occupied, path)
            hops += path
            here = best
        for radius in CROSSING_RADII:
            found = crossing(occupied, here, radius, steps, fixed, max_states, failed)
            if found:
                path, here = found
                _apply(occupied, path)
                hops += path
                break
        else:
            return None
    return None


def journey_flow(tracker, goal: frozenset[Cell], fixed: Cell | None, deadline,
                 method: str = "local", policy: Policy = POLICIES["journey"],
                 digs: bool = False) -> None:
    """Fill every void by journeys; raises PlanningFailure when stuck.

    First the goal modules walling in a void that no order of fills can enter
    step aside (:func:`channels`, :func:`_step_aside`), and again when the
    flow is stuck after its take-backs (at most ``ASIDES`` times).

    Candidates are ranked and tried as ``policy`` says. When no journey fills a
    void, the flow takes back the latest fill next to a stuck end and makes
    that void wait until the end has left (at most ``BACKTRACKS`` times).
    Then a hand-over (:func:`_hand_over`). With ``digs`` (the local method
    above ``LOCAL_LIMIT``), the flow first digs into the deep holes of the
    goal and fails at once if one is deeper than a dig reaches; a stuck flow
    first digs into a hole, and after the hand-overs sweeps every free end
    to its nearest voids, moves voids no end reaches towards the ends and
    digs walled-in ends out (:mod:`hexbot.planning.dig`), and last tries its
    best journeys with ``LAST_STATES`` per crossing; failed journeys,
    hand-overs and digs are not asked again until the modules around them
    move. Every fill or take-back changes the state, take-backs, digs and
    propagations are bounded, and a hand-over fills a void, so the loop ends. A finished flow's long
    journeys become relays (:func:`relay`)."""
    from hexbot.planning import dig  # dig rolls modules by journeys from here
    from hexbot.planning.finish import finish  # it imports regroup, which imports robust


    _step_aside(tracker, goal, fixed)
    fills: list[tuple[int, Cell]] = []  # (moves before the fill, void filled)
    waits: dict[Cell, set[Cell]] = {}  # void -> cells whose end must leave first
    failed: set = set()  # crossings that found nothing (see crossing)
    backtracks = 0
    asides = ASIDES
    digs_left = dig.DIGS if digs else 0
    propagations = dig.PROPAGATIONS
    last_tries = LAST_TRIES
    finishes = FINISHES if digs else 0
    sweeping = False  # the last fill was a sweep's: try the sweep first again
    if digs:
        dig.check_ends(tracker.occupied, goal, method)
    while digs_left and dig.dig_deep(tracker, goal, fixed, deadline, failed):
        digs_left -= 1
    if digs:
        dig.check_depth(tracker.occupied, goal, method)
    while True:
        deadline.check(method)
        occupied = tracker.occupied
        voids = set(goal - occupied)
        if not voids:  # the relays get their own allowance: the flow has planned
            relay(tracker, goal, fixed, _Allowance(
                relay_journeys(len(occupied)),
                deadline.capped(relay_seconds(len(occupied)))))
            return
        ends = occupied - goal
        if sweeping:
            hops = dig.sweep(occupied, goal, ends, voids, fixed, failed)
            if hops:
                tracker.roll(hops)
                continue
            sweeping = False
        ranked = _candidates(occupied, goal, ends, voids, fixed, policy)
        cut = _CutTest(occupied)
        candidates = []
        for _, m, v in ranked:
            if not (waits.get(v, set()) & ends) - {m} and not cut(m):
                candidates.append((m, v))
                if len(candidates) == policy.tries:
                    break
        before = len(tracker.moves)
        tries = [(m, v, CHEAP_STATES) for m, v in candidates]
        tries += [(m, v, CROSSING_STATES) for m, v in candidates[:THOROUGH_TRIES]]
        for mover, void, states in tries:
            # with digs (large flows), a journey that failed is not tried again
            # until the modules around its two ends change
            question = ("journey", mover, void, states, _around(occupied, mover),
                        _around(occupied, void)) if digs else None
            if question in failed:
                continue
            hops = journey(occupied, mover, void, fixed, states, failed)
            if hops:
                tracker.roll(hops)
                fills.append((before, void))
                break
            if digs:
                failed.add(question)
            deadline.check(method)
        else:
            if digs_left and dig.dig_holes(tracker, goal, fixed, deadline, failed):
                digs_left -= 1
                fills.clear()  # a take-back must not undo the dig
                continue
            targets = _safe_voids(goal, voids) if digs else voids
            hops = _make_room(occupied, goal, ends, voids, fixed, failed, targets,
                              remember=digs)
            if hops:
                tracker.roll(hops)
                continue
            culprit = _latest_fill_near(fills, ends) if backtracks < BACKTRACKS else None
            if culprit is not None:
                backtracks += 1
                moves, void = fills[culprit]
                del fills[culprit:]
                tracker.undo_to(moves)
                waits.setdefault(void, set()).update(e for e in ends if distance(e, void) <= NEAR)
                continue
            if waits:  # the ends waited for may never leave: let their voids be filled
                waits.clear()
                backtracks = BACKTRACKS
                continue
            if asides and _step_aside(tracker, goal, fixed):  # the fills walled voids in
                asides -= 1
                continue
            hops = _hand_over(occupied, goal, ends, voids, fixed, failed, deadline, targets,
                              remember=digs)
            if hops:  # it tries many pairs of journeys
                tracker.roll(hops)
                continue
            hops = dig.sweep(occupied, goal, ends, voids, fixed, failed) if digs else None
            if hops:
                tracker.roll(hops)
                sweeping = SWEEP_FIRST
                continue
            if digs and propagations:
                hops = dig.propagate(occupied, goal, ends, voids, fixed, failed)
                if hops:
                    propagations -= 1
                    tracker.roll(hops)
                    continue
            if digs_left and (dig.dig_holes(tracker, goal, fixed, deadline, failed)
                              or dig.dig_ends(tracker, goal, fixed, deadline, failed)):
                digs_left -= 1
                fills.clear()
                continue
            if digs and last_tries:
                last_tries -= 1
                hops = next(filter(None, (journey(occupied, m, v, fixed, LAST_STATES)
                                          for m, v in candidates[:LAST_PAIRS])), None)
                if hops:
                    tracker.roll(hops)
                    continue
            if finishes:  # ends carried to far voids in legs (planning/finish.py)
                finishes -= 1
                hops = finish(occupied, goal, fixed, deadline)
                if hops:
                    tracker.roll(hops)
                    fills.clear()  # a take-back must not undo them
                    continue
            if digs_left and dig.dig_ends(tracker, goal, fixed, deadline, failed, beside=True):
                digs_left -= 1  # the last resort: an end dug out with parks beside its set
                fills.clear()
                continue
            raise PlanningFailure(
                f"{method}: journeys stuck with {len(voids)} goal cells to fill "
                f"(none of {len(candidates)} journeys found a crossing within "
                f"radius {CROSSING_RADII[-1]} and {CROSSING_STATES} states; "
                f"{backtracks} fills taken back)")


def _around(occupied: set[Cell], cell: Cell) -> frozenset[Cell]:
    """The modules within ``SAME_AROUND`` of ``cell``: a failed question's context."""
    return frozenset(c for c in disc(cell, SAME_AROUND) if c in occupied)


def relay_journeys(count: int) -> int:
    """Journeys the relays and reversed runs of a finished flow may plan
    (:func:`relay`). A count, not seconds, so that a pair gets the same plan
    in every run and on every machine: with a CPU-time cap two runs of blob
    1,000 seed 2 gave 5,088 and 5,112 moves. 1,000 at 1,000 modules, about
    the 3.5 s the cap gave (999-1,673 journeys on the bench's blobs); the
    scrambles of 300 and 1,000 but seed 2 need 76-276."""
    return 250 + 3 * count // 4


def relay_seconds(count: int) -> float:
    """CPU time after which the relays stop even if journeys are left: a net
    for slow machines, about twice what ``relay_journeys`` takes here."""
    return 2.0 + count / 150


class _Allowance:
    """Journeys the relays may still plan, and the time net around them."""

    def __init__(self, journeys: int, deadline) -> None:
        self.left, self.deadline = journeys, deadline

    def expired(self) -> bool:
        return self.left <= 0 or self.deadline.expired()

    def journey(self, *args, **kwargs) -> list[Hop] | None:
        self.left -= 1
        return journey(*args, **kwargs)


def relay(tracker, goal: frozenset[Cell], fixed: Cell | None, allowance: _Allowance) -> None:
    """Split the long journeys of a finished flow into relays, for a shorter makespan.

    A journey takes one module from a cell ``E`` to a void ``V`` and leaves every
    other cell as it was. So does a relay: a goal module ``G`` beside the
    journey's route goes to ``V`` first, and the traveller takes ``G``'s cell.
    The cells after both are the same, so the rolls that follow stay legal;
    but the two legs run side by side in the schedule (they touch only at
    ``G``'s cell, which the first leg leaves at once), so the makespan goes
    from the whole route towards half of it, and the legs are often shorter
    than the whole. Measured in docs/planning.md ("Relays"). The journeys of
    the critical path are split first; stops, keeping what it split, when
    ``allowance`` is spent: it only shortens a finished plan."""
    rolls = tracker.rolled()
    if not any(len(hops) > RELAY_LONG for hops in rolls):
        return
    serial = list(tracker.moves)
    tracker.undo_to(0)
    initial = Configuration.from_cells(tracker.occupied)
    parts = [[hops] for hops in rolls]  # each roll's legs
    split = [len(hops) <= RELAY_LONG for hops in rolls]  # tried already, or short
    # The journeys on the critical path first (it changes as they split), then
    # the others in order, while journeys are left to plan.
    while not allowance.expired():
        legs = [leg for legs in parts for leg in legs]
        owner = [r for r, legs in enumerate(parts) for _ in legs]
        _reroll(tracker, legs)
        _, chain = _critical_path(tracker.moves, tracker.rolls)
        todo = {owner[leg] for leg in chain} - {r for r, done in enumerate(split) if done}
        if not todo:
            break
        _split_rolls(initial, rolls, parts, split, todo, goal, fixed, allowance)
    _split_rolls(initial, rolls, parts, split, set(range(len(rolls))), goal, fixed, allowance)
    legs = _reorder(initial, [leg for legs in parts for leg in legs], fixed, allowance,
                    tracker.max_moves)
    _reroll(tracker, legs)
    # Keep the relays only when they schedule shorter (a reordered plan can jam
    # the list schedule, and its pieces can then be longer).
    if len(schedule_in_pieces(initial, tracker.moves)) > len(schedule_in_pieces(initial, serial)):
        _reroll(tracker, rolls)


def _split_rolls(initial: Configuration, rolls: list[list[Hop]], parts: list[list[list[Hop]]],
                 split: list[bool], which: set[int], goal: frozenset[Cell], fixed: Cell | None,
                 allowance: _Allowance) -> None:
    """Split the rolls in ``which`` not tried yet into relay legs (``parts``).
    A roll's legs end where the roll does, so the cells before each roll are
    the same whichever rolls are split."""
    occupied = set(initial.cells)
    for r, hops in enumerate(rolls):
        if r in which and not split[r] and not allowance.expired():
            split[r] = True
            parts[r] = _split(occupied, hops, goal, fixed, RELAY_DEPTH, allowance)
        _apply(occupied, hops)


def _reroll(tracker, rolls: list[list[Hop]]) -> None:
    tracker.undo_to(0)
    for hops in rolls:
        tracker.roll(hops)


def _reorder(initial: Configuration, rolls: list[list[Hop]], fixed: Cell | None,
             allowance: _Allowance, max_moves: int) -> list[list[Hop]]:
    """Reverse runs of ``REORDER_RUN`` journeys or fewer on the critical path
    when that shortens it. A journey rolls over the cells the one before it
    filled, so a run of fills in one place is a chain; in reverse order each
    traveller goes on further while the next follows. Each journey of the
    reversed run is planned again (same cells left and filled, so the rolls
    after it stay legal); kept when the critical path gets shorter."""
    tracker = Tracker(initial, max_moves)
    _reroll(tracker, rolls)
    best, chain = _critical_path(tracker.moves, tracker.rolls)
    tried: set[tuple[int, int]] = set()
    improved = True
    while improved and not allowance.expired():
        improved = False
        for index in sorted(chain):
            for first, last in _runs_around(index, len(rolls)):
                if (first, last) in tried or allowance.expired():
                    continue
                tried.add((first, last))
                reversed_run = _reversed(initial, rolls, first, last, fixed, allowance)
                if reversed_run is None:
                    continue
                trial = rolls[:first] + reversed_run + rolls[last:]
                _reroll(tracker, trial)
                length, trial_chain = _critical_path(tracker.moves, tracker.rolls)
                if length < best:
                    rolls, best, chain, improved = trial, length, trial_chain, True
                    tried.clear()
                    break
            if improved:
                break
    return rolls


def _runs_around(index: int, count: int):
    """(first, last) of the runs of 2..``REORDER_RUN`` rolls holding ``index``."""
    for size in range(2, REORDER_RUN + 1):
        for first in range(max(0, index - size + 1), min(index, count - size) + 1):
            yield first, first + size


def _reversed(initial: Configuration, rolls: list[list[Hop]], first: int, last: int,
              fixed: Cell | None, allowance: _Allowance) -> list[list[Hop]] | None:
    """Rolls ``first:last`` planned again in reverse order (None if one is no journey)."""
    occupied = set(initial.cells)
    for hops in rolls[:first]:
        _apply(occupied, hops)
    moved = [_moved_cells(hops) for hops in rolls[first:last]]
    if any(m is None for m in moved):
        return None
    if {src for src, _ in moved} & {dst for _, dst in moved}:
        return None  # a relay: its legs meet at the helper's cell
    replanned = []
    for src, dst in reversed(moved):
        if is_cut(occupied, src):
            return None
        hops = allowance.journey(occupied, src, dst, fixed, CHEAP_STATES)
        if not hops:
            return None
        _apply(occupied, hops)
        replanned.append(hops)
    return replanned


def _critical_path(moves: list, starts: list[int]) -> tuple[int, set[int]]:
    """Length of the schedule's longest chain of dependent moves
    (:func:`~hexbot.planning.schedule.critical_chain`) and the rolls on it."""
    length, chain = critical_chain(moves)
    return length, {bisect_right(starts, k) - 1 for k in chain}


def _split(occupied: set[Cell], hops: list[Hop], goal: frozenset[Cell], fixed: Cell | None,
           depth: int, allowance: _Allowance) -> list[list[Hop]]:
    """``hops`` as relay legs (itself when it is short, not one journey, or no leg helps)."""
    moved = _moved_cells(hops)
    if len(hops) <= RELAY_LONG or not depth or moved is None:
        return [hops]
    traveller, void = moved
    route = [dst for _, dst, _, _ in hops[len(hops) // 3: 2 * len(hops) // 3 + 1]]
    beside = {n for cell in route for n in neighbors(cell)
              if n in occupied and n in goal and n not in (traveller, fixed)}
    ranked = sorted(beside, key=lambda c: (abs(distance(c, traveller) - distance(c, void)), c))
    for helper in ranked[:RELAY_TRIES]:
        if allowance.expired():
            break
        if is_cut(occupied, helper):
            continue
        first = allowance.journey(occupied, helper, void, fixed)
        if not first or len(first) >= RELAY_GAIN * len(hops):
            continue
        after = set(occupied)
        _apply(after, first)
        if is_cut(after, traveller):
            continue
        second = allowance.journey(after, traveller, helper, fixed)
        if not second or len(second) >= RELAY_GAIN * len(hops):
            continue
        return (_split(occupied, first, goal, fixed, depth - 1, allowance)
                + _split(after, second, goal, fixed, depth - 1, allowance))
    return [hops]


def _moved_cells(hops: list[Hop]) -> tuple[Cell, Cell] | None:
    """(cell left, cell filled) when ``hops`` move one module's worth, else None."""
    count: dict[Cell, int] = {}
    for src, dst, _, _ in hops:
        count[src] = count.get(src, 0) - 1
        count[dst] = count.get(dst, 0) + 1
    left = [c for c, k in count.items() if k < 0]
    filled = [c for c, k in count.items() if k > 0]
    if len(left) != 1 or len(filled) != 1:
        return None
    return left[0], filled[0]


def _step_aside(tracker, goal: frozenset[Cell], fixed: Cell | None) -> bool:
    """Goal modules that wall a void in whatever the order of the fills
    (:func:`channels`) leave the goal, each by a journey to a near empty cell
    off the goal; the flow then refills their cells like any void. A wall
    that cannot leave stays. True when one left."""
    occupied = tracker.occupied
    walls = channels(goal, set(goal - occupied), fixed)
    if not walls or len(walls) > ASIDE_LIMIT:
        return False
    left = set(walls & occupied)
    moved, any_moved = True, False
    while left and moved:  # the outer walls first: the inner ones get out after them
        moved = False
        for wall in sorted(left):
            if wall == fixed or not _can_leave(occupied, wall) or is_cut(occupied, wall):
                continue
            parks = sorted({n for c in disc(wall, PARK_RADIUS) if c in occupied
                            for n in neighbors(c) if n not in occupied and n not in goal},
                           key=lambda c: (distance(c, wall), c))
            for park in parks[:PARKS]:
                hops = journey(occupied, wall, park, fixed)
                if hops:
                    tracker.roll(hops)
                    occupied = tracker.occupied
                    left.discard(wall)
                    moved = any_moved = True
                    break
    return any_moved


def channels(goal: frozenset[Cell], voids: set[Cell], fixed: Cell | None) -> set[Cell]:
    """Goal cells to empty first so that every void can be filled in some order
    (:func:`hexbot.planning.robust.fillable` finds none left): for pockets no
    order fills, the fewest goal cells from them to the outside (a hole);
    around a cell still walled in, the three sides in a row holding the fewest
    goal modules (a narrow notch: entering needs three free sides in a row);
    when neither adds a cell (a way one cell wide), every goal neighbour of
    the cells still walled in. Empty when there is nothing to open; more than
    ``ASIDE_LIMIT`` cells when opening costs that much (then none is opened)."""
    walls: set[Cell] = set()
    remaining = fillable(goal, voids)
    while remaining:
        add = _way_out(goal, remaining, voids | walls, fixed)
        if not add:
            for cell in sorted(remaining):
                add |= _widest_side(goal, cell, voids | walls, fixed)
        if not add - walls:  # a way one cell wide: open it wider
            add = {n for c in remaining for n in neighbors(c)
                   if n in goal and n != fixed} - voids
        add -= walls
        if not add or len(walls) + len(add) > ASIDE_LIMIT:
            return walls | add
        walls |= add
        remaining = fillable(goal, voids | walls)
    return walls


def _widest_side(goal: frozenset[Cell], cell: Cell, free: set[Cell],
                 fixed: Cell | None) -> set[Cell]:
    """The goal modules in the three sides in a row of ``cell`` that hold fewest."""
    ring = neighbors(cell)
    best: set[Cell] | None = None
    for i in range(6):
        window = {ring[(i + k) % 6] for k in range(3)}
        blocked = {c for c in window if c in goal and c not in free}
        if fixed in blocked:
            continue
        if best is None or len(blocked) < len(best):
            best = blocked
    return best or set()


def _way_out(goal: frozenset[Cell], sources: set[Cell], free: set[Cell],
             fixed: Cell | None) -> set[Cell]:
    """The fewest goal cells (not in ``free``) on a way from ``sources`` to a cell
    off the goal (0-1 breadth-first search; the fixed module is no way)."""
    cost = dict.fromkeys(sources, 0)
    parent: dict[Cell, Cell | None] = dict.fromkeys(sources)
    queue = deque(sorted(sources))
    while queue:
        cell = queue.popleft()
        if cell not in goal:
            path = set()
            while cell is not None:
                if cell in goal and cell not in free:
                    path.add(cell)
                cell = parent[cell]
            return path
        for n in neighbors(cell):
            if n == fixed:
                continue
            step = 0 if (n not in goal or n in free) else 1
            if n not in cost or cost[cell] + step < cost[n]:
                cost[n] = cost[cell] + step
                parent[n] = cell
                if step:
                    queue.append(n)
                else:
                    queue.appendleft(n)
    return set()


class _CutTest:
    """``is_cut`` for many cells of one configuration: the local arc test first,
    then :func:`~hexbot.planning.schedule.stays_connected`, whose searches
    from the neighbours meet nearby unless the cell does cut (then the smaller
    side is searched). One articulation-point pass per flow step cost more at
    1,000 modules; a plain search per candidate, most of the time at 3,000."""

    def __init__(self, occupied: set[Cell]) -> None:
        self.occupied = occupied
        self.known: dict[Cell, bool] = {}

    def __call__(self, cell: Cell) -> bool:
        if _single_arc(self.occupied, cell):
            return False
        cut = self.known.get(cell)
        if cut is None:
            cut = self.known[cell] = not stays_connected(self.occupied, cell)
        return cut


def _latest_fill_near(fills: list[tuple[int, Cell]], ends: set[Cell]) -> int | None:
    """Index of the latest fill within ``NEAR`` of a stuck end, or None."""
    for index in range(len(fills) - 1, -1, -1):
        if any(distance(fills[index][1], e) <= NEAR for e in ends):
            return index
    return None


def _make_room(occupied: set[Cell], goal: frozenset[Cell], ends: set[Cell], voids: set[Cell],
               fixed: Cell | None, failed: set, targets: set[Cell] | None = None,
               remember: bool = False) -> list[Hop] | None:
    """One hop of the thesis' void propagation: an end walled in (no three free
    sides in a row) gets out when a goal module beside it goes to a void
    first, then the end takes its cell. (The mirror case, a void walled in,
    was tried and never helped on the bench pairs: entering a cell needs three
    free sides in a row, so two of its neighbours would have to step away.)"""
    by_distance = sorted(fillable(frozenset(occupied), set(ends)),
                         key=lambda e: (min(distance(e, v) for v in voids), e))
    for end in by_distance[:HELPERS]:
        for side in _helpers(occupied, goal, end, fixed):
            question = ("make room", end, side, _around(occupied, end)) if remember else None
            if question in failed:
                continue
            hops = _take_place(occupied, end, side, targets or voids, fixed, failed)
            if hops:
                return hops
            if remember:
                failed.add(question)
    return None


def _hand_over(occupied: set[Cell], goal: frozenset[Cell], ends: set[Cell], voids: set[Cell],
               fixed: Cell | None, failed: set, deadline,
               targets: set[Cell] | None = None, remember: bool = False,
               ) -> list[Hop] | None:
    """An end that rolls but finds no crossing out of its stretch of the surface
    (a bay whose two mouths no crossing passes) hands over: a goal module
    beside that stretch goes to a void by the outer way, then the end takes
    its cell (``HELPERS`` ends, nearest the voids first, ``HAND_OVERS``
    helpers each). The same two journeys as :func:`_make_room`, from further
    away. None when the deadline has passed (the flow then says so)."""
    tried = 0
    for end in sorted(ends, key=lambda e: (min(distance(e, v) for v in voids), e)):
        if tried == HELPERS or deadline.expired():
            return None
        if end == fixed or is_cut(occupied, end):
            continue
        reach = set(_rolls(occupied, end)[0])
        if len(reach) < 2:
            continue
        tried += 1
        helpers = {n for c in reach for n in neighbors(c)
                   if n in occupied and n in goal and n not in (end, fixed)}
        ranked = sorted(helpers, key=lambda h: (min(distance(h, v) for v in voids), h))
        for side in ranked[:HAND_OVERS]:
            # ``remember``: not again until the modules around the two change
            question = ("hand-over", end, side, _around(occupied, end),
                        _around(occupied, side)) if remember else None
            if question in failed:
                continue
            hops = None if is_cut(occupied, side) else _take_place(
                occupied, end, side, targets or voids, fixed, failed)
            if hops:
                return hops
            if remember:
                failed.add(question)
    return None


def _safe_voids(goal: frozenset[Cell], voids: set[Cell]) -> set[Cell]:
    """The voids whose fill walls in no other void."""
    peel = Peel(goal, voids)
    return {v for v in voids if not peel.walls_in(goal, voids, v)}


def _take_place(occupied: set[Cell], end: Cell, side: Cell, voids: set[Cell],
                fixed: Cell | None, failed: set) -> list[Hop] | None:
    """The goal module at ``side`` journeys to one of its two nearest voids,
    then the end takes its cell."""
    for void in sorted(voids, key=lambda v: (distance(side, v), v))[:2]:
        hops = _two_journeys(occupied, (side, void), (end, side), fixed, failed)
        if hops:
            return hops
    return None


def _helpers(occupied: set[Cell], goal: frozenset[Cell], cell: Cell,
             fixed: Cell | None) -> list[Cell]:
    """Goal modules beside ``cell`` that can leave their cell for a while."""
    return [n for n in neighbors(cell)
            if n in goal and n in occupied and n != fixed and not is_cut(occupied, n)]


def _two_journeys(occupied: set[Cell], first: tuple[Cell, Cell], second: tuple[Cell, Cell],
                  fixed: Cell | None, failed: set) -> list[Hop] | None:
    hops = journey(occupied, *first, fixed, failed=failed)
    if not hops:
        return None
    after = set(occupied)
    _apply(after, hops)
    if is_cut(after, second[0]):
        return None
    more = journey(after, *second, fixed, failed=failed)
    return hops + more if more else None


def _candidates(occupied: set[Cell], goal: frozenset[Cell], ends: set[Cell], voids: set[Cell],
                fixed: Cell | None, policy: Policy) -> list[tuple[tuple, Cell, Cell]]:
    """(rank, end, void): per void its assigned end and the nearest others; fills
    that wall in nothing first, then those walling in an end, then a void.

    Each check peels again only what the fill changes (:class:`Peel`)."""
    void_peel, end_peel = Peel(goal, voids), Peel(frozenset(occupied), set(ends))
    walled_ends = end_peel.left
    ranked = []
    by_end, by_void = sorted(ends), sorted(voids)
    cost = distance_matrix(by_end, by_void)
    column = {v: j for j, v in enumerate(by_void)}
    free_rows = np.array([i for i, e in enumerate(by_end) if e not in walled_ends], dtype=np.int64)
    for _, end, void in assigned_pairs(ends, voids, cost):
        walls_void = void_peel.walls_in(goal, voids, void)
        far = cost[:, column[void]]
        nearest = [by_end[i] for i in np.argsort(far, kind="stable")[:NEAREST_ENDS]]
        # and the nearest that can leave at all: the nearest are often walled in
        if policy.nearest_free and len(free_rows):
            order = np.argsort(far[free_rows], kind="stable")[:policy.nearest_free]
            nearest += [by_end[i] for i in free_rows[order]]
        for mover in sorted({end, *nearest}):
            if mover == fixed:
                continue
            # the shape after the fill: moved in place and back (a copy per
            # candidate, or a wrapper answering each look-up, costs more)
            occupied.discard(mover)
            occupied.add(void)
            walled = end_peel.after(occupied, ends - {mover}, (void, mover))
            occupied.discard(void)
            occupied.add(mover)
            walls_end = bool(walled - walled_ends) or (
                policy.guard_walled
                and any(n in walled_ends and n != mover for n in neighbors(void)))
            free = sum(1 for n in neighbors(mover) if n not in occupied)
            ranked.append(((2 * walls_void + walls_end,
                            distance(mover, void) + policy.spread * free), mover, void))
    ranked.sort()
    return ranked
