"""The local method of the robust planner: moves that grow with the distance to
travel, not with the number of modules.

Its planners (*flows*) each run from the start to the goal and, when none
plans, from the goal back to the start (reversed: every rotation is undone by
the opposite one over the same cells):

* the **journey flows** (:mod:`hexbot.planning.journey`, three ranking
  policies): one void at a time, a module rolls along the surface and
  crosses from segment to segment with wall modules stepping aside and back;
* the **window flow** (:func:`hexbot.planning.windows.window_flow`): the
  modules off the goal are assigned to the empty goal cells (cheapest
  assignment), and the nearest pairs are joined by the fewest rotations
  inside a corridor around them (A*);
* the **kernel flow** (:mod:`hexbot.planning.flow`): a core of common modules
  stays, voids next to it are filled in an order that walls in nothing,
  by journeys and chains (void propagation), with window fixes when stuck.

Up to ``LOCAL_LIMIT`` modules all flows run forward and the shortest plan is
kept; above it only the journey flows, with digs (:mod:`hexbot.planning.dig`),
and the first plan is taken; backward
only when none succeeds. Up to ``LOCAL_LIMIT``, when no flow plans either
way, the journey flows with digs run last (``DUG_FLOWS``: shapes with holes
need them at any size). None is complete (restricted pivoting
makes that impossible for a fast planner); a failure hands over to the next
method of :func:`hexbot.planning.robust.plan_robust`. Measured in
docs/planning.md ("Local method").
"""

from __future__ import annotations

from collections.abc import Callable
from functools import partial

from hexbot.planning import dig
from hexbot.planning.budget import NO_DEADLINE, BudgetExhausted, Deadline, PlanningFailure
from hexbot.planning.configuration import Configuration
from hexbot.planning.flow import kernel_flow
from hexbot.planning.hexlattice import Cell
from hexbot.planning.journey import POLICIES, journey_flow
from hexbot.planning.moves import Move
from hexbot.planning.tracker import Tracker
from hexbot.planning.windows import window_flow

#: Up to this many modules the local method runs all its flows; above, only the
#: journey flows (the kernel and window flows planned none of the 300-module
#: bench pairs tried, each failure costing 16-53 s, and none at 1,000).
LOCAL_LIMIT = 150
#: Above this many modules the local method is not tried at all. Until session
#: 20 this was 2,000: at 10,000 the journey flow stalled on the bench scramble
#: (44 goal cells left after 299 s in session 8; 11 after 32 s in session 20);
#: since the finish (:mod:`hexbot.planning.finish`) carries the last ends in
#: legs, it plans that scramble locally.
JOURNEY_LIMIT = 10_000
#: Up to this many modules (above ``LOCAL_LIMIT``) the local method may take
#: ``DIG_SECONDS`` of CPU time, for its digs (the bench's slowest blob of
#: 1,000 takes 8.4 s, blob seed 6 beyond the bench 16.5 s).
DIG_SIZE = 1000
DIG_SECONDS = 30.0
#: Above ``DIG_SIZE`` the cap is 1 s + n / ``LARGE_RATE`` (68 s at 10,000: the
#: scramble's flow takes about 32 s and its finish 2.5 s there; a blob of
#: 10,000 that stalls leaves the strip more than 200 s of the 300 s budget).
LARGE_RATE = 150


#: A pair where fewer than this share of the modules keep their cell is a
#: global change (a walk to a new place, a rebuild), not what the local method
#: is for: it gets ``GLOBAL_SECONDS``. On goals one column apart from the start
#: (``hexbot bench planning --cases``, "apart") its flows planned the pairs of
#: 10 modules in 0.1-0.6 s each and spent their whole cap failing at 30 and
#: 100 (16 and 30 s) before the middle ball planned in 0.07-0.8 s. The bench's
#: pairs keep 30 % of their cells or more (blobs of 10).
GLOBAL_SHARE = 0.25
GLOBAL_SECONDS = 2.0


def local_cap(initial: Configuration, goal: frozenset[Cell]) -> float:
    """The local method's time cap for this pair: ``local_seconds``, or
    ``GLOBAL_SECONDS`` for a global change."""
    if len(initial.cells & goal) < GLOBAL_SHARE * len(initial):
        return min(GLOBAL_SECONDS, local_seconds(len(initial)))
    return local_seconds(len(initial))


def local_seconds(count: int) -> float:
    """The local method's own time cap. Up to ``LOCAL_LIMIT`` modules its
    successes take seconds and its failures can search for minutes. Above
    ``DIG_SIZE`` (1 s + n / ``LARGE_RATE``) the cap keeps a failure from spending the
    strip's time; the local method is not tried above ``JOURNEY_LIMIT``.
    Up to ``DIG_SIZE`` modules it is ``DIG_SECONDS``:
    the digs plan the blobs of 300 in 3-9 s and those of 1,000 in 6-17 s,
    where the strip's plans are 9-46 (300) and 126-176 (1,000) times longer
    in moves: a plan that takes hours less to carry out is worth the
    seconds (docs/planning.md, "Digs")."""
    if count <= LOCAL_LIMIT:
        return 10.0 + count / 5
    if count <= DIG_SIZE:
        return DIG_SECONDS
    return 1.0 + count / LARGE_RATE


Flow = Callable[[Tracker, frozenset[Cell], Cell | None, Deadline, str], None]
#: The journey flows first (they plan the most bench pairs, and fast), then the
#: kernel flow (it plans a blob of 100 the journeys miss), then the window flow
#: (its failures are slow): what has planned is kept when the time cap comes.
FLOWS: tuple[tuple[str, Flow], ...] = (
    *((name, partial(journey_flow, policy=policy)) for name, policy in POLICIES.items()),
    ("kernel", kernel_flow),
    ("window", window_flow),
)


def forward(initial: Configuration, goal: frozenset[Cell], flow: Flow, max_moves: int,
            fixed: Cell | None, deadline: Deadline, method: str) -> list[Move]:
    tracker = Tracker(initial, max_moves)
    flow(tracker, goal, fixed, deadline, method)
    return tracker.moves


def backward(initial: Configuration, goal: frozenset[Cell], flow: Flow, max_moves: int,
             fixed: Cell | None, deadline: Deadline, method: str) -> list[Move]:
    """Plan goal -> initial with provisional ids, then reverse it onto the real modules."""
    from hexbot.planning.canonical import replay, undone

    start = Configuration.from_cells(goal, first_id=1_000_000)
    moves = forward(start, initial.cells, flow, max_moves, fixed, deadline, method)
    end = replay(start, moves)
    return undone(moves, {end[c].id: initial[c].id for c in end})


#: Above ``LOCAL_LIMIT``: the journey flows with digs (:mod:`hexbot.planning.dig`).
LARGE_FLOWS: tuple[tuple[str, Flow], ...] = tuple(
    (name, partial(journey_flow, policy=policy, digs=True)) for name, policy in POLICIES.items())


def flows_for(count: int) -> tuple[tuple[str, Flow], ...]:
    """All flows up to ``LOCAL_LIMIT`` modules, the journey flows with digs above."""
    return FLOWS if count <= LOCAL_LIMIT else LARGE_FLOWS


#: Up to ``LOCAL_LIMIT``, when no flow plans either way: the journey flows
#: with digs, forward, then backward. Shapes with holes need them at any size (a hole's
#: ring walls its cell in from the start), where the flows without digs
#: stall and the strip took 25-80 times the move bound at 100 modules.
DUG_FLOWS: tuple[tuple[str, Flow], ...] = tuple(
    (f"{name} with digs", flow) for name, flow in LARGE_FLOWS)


def via_local(initial: Configuration, goal: frozenset[Cell], max_moves: int,
              fixed: Cell | None = None, deadline: Deadline = NO_DEADLINE,
              method: str = "local") -> list[Move]:
    """The shortest plan of the flows run forward; only when none succeeds,
    they run backward. :class:`PlanningFailure` with the reason of every try
    when none succeeds; when the time runs out after a success, that plan."""
    try:
        return _shortest(initial, goal, max_moves, fixed, deadline, method)
    finally:
        dig.forget()


def _shortest(initial: Configuration, goal: frozenset[Cell], max_moves: int,
              fixed: Cell | None, deadline: Deadline, method: str) -> list[Move]:
    failures = []
    best: list[Move] | None = None
    tries = [(forward, flows_for(len(initial))), (backward, flows_for(len(initial)))]
    if len(initial) <= LOCAL_LIMIT:
        tries += [(forward, DUG_FLOWS), (backward, DUG_FLOWS)]
    for direction, flows in tries:
        for name, flow in flows:
            try:
                serial = direction(initial, goal, flow, max_moves, fixed, deadline, method)
            except BudgetExhausted:
                if best is not None:
                    return best
                raise
            except PlanningFailure as exc:
                failures.append(f"{name} {direction.__name__}: {exc}".replace(f"{method}: ", ""))
                continue
            if best is None or len(serial) < len(best):
                best = serial
            if len(initial) > LOCAL_LIMIT:
                return best  # large: the first plan, the time cap is tight
        if best is not None:
            return best
    raise PlanningFailure(f"{method}: " + "; ".join(failures))
