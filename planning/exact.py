"""The ``exact`` mode: fewest moves, by A* over configurations (small n only).

States are sets of occupied cells (modules are interchangeable for the count;
the ids are replayed afterwards). A state's successors are the Table 4-3
rotations of its modules that are not cut vertices (one articulation pass per
state) and not fixed to the base: the module rolls over the rest, which stays
connected, and ends touching its substrate. The heuristic is the assignment
bound of :mod:`hexbot.planning.bounds`: one move changes it by at most one, so
it is consistent and the first goal popped is optimal.

It is the yardstick for the robust planner (its optimality gap on the small
cases). The search gives up with a reason past ``EXACT_LIMIT`` modules,
past its time budget, or past ``STATE_LIMIT`` stored states (memory).
"""

from __future__ import annotations

import heapq
import itertools

from hexbot.planning.bounds import move_lower_bound
from hexbot.planning.budget import DEFAULT_BUDGET, Deadline, PlanningFailure
from hexbot.planning.configuration import Configuration, articulation_points
from hexbot.planning.hexlattice import Cell
from hexbot.planning.moves import Move
from hexbot.planning.plan import Plan, Step
from hexbot.planning.robust import _moves_from, check_inputs, schedule_parallel

#: Largest module count the exact mode accepts.
EXACT_LIMIT = 14
#: Largest number of configurations kept (about 1 KiB each).
STATE_LIMIT = 2_000_000

State = frozenset[Cell]
Hop = tuple[Cell, Cell, object, Cell]  # (from, to, rule, substrate)


def successors(state: State, fixed: Cell | None = None):
    """(hop, next state) for every legal single rotation."""
    cuts = articulation_points(state)
    for cell in state:
        if cell == fixed or cell in cuts:
            continue
        for rule, sub, goal in _moves_from(cell, state, cell):
            yield (cell, goal, rule, sub), state - {cell} | {goal}


def shortest_hops(start: State, goal: State, fixed: Cell | None = None,
                  deadline: Deadline | None = None) -> list[Hop]:
    """The fewest rotations from ``start`` to ``goal`` (raises PlanningFailure)."""
    deadline = deadline or Deadline(DEFAULT_BUDGET)
    bound: dict[State, int] = {}

    def h(state: State) -> int:
        value = bound.get(state)
        if value is None:
            value = bound[state] = move_lower_bound(state, goal).value
        return value

    tie = itertools.count()
    best = {start: 0}
    parent: dict[State, tuple[State, Hop] | None] = {start: None}
    frontier = [(h(start), 0, next(tie), start)]
    while frontier:
        _, neg_g, _, state = heapq.heappop(frontier)
        g = -neg_g
        if g > best[state]:
            continue
        if state == goal:
            hops: list[Hop] = []
            while parent[state] is not None:
                state, hop = parent[state]  # type: ignore[misc]
                hops.append(hop)
            return hops[::-1]
        if len(best) > STATE_LIMIT:
            raise PlanningFailure(f"exact: gave up after {STATE_LIMIT} configurations "
                                  "(memory bound), no plan of fewer than "
                                  f"{g + h(state)} moves")
        deadline.check(f"exact (searched {len(best)} configurations, no plan of fewer than "
                       f"{g + h(state)} moves)")
        for hop, nxt in successors(state, fixed):
            if g + 1 < best.get(nxt, 1 << 30):
                best[nxt] = g + 1
                parent[nxt] = (state, hop)
                # deeper first among equal f: reaches the goal sooner
                heapq.heappush(frontier, (g + 1 + h(nxt), -(g + 1), next(tie), nxt))
    raise PlanningFailure("exact: no sequence of Table 4-3 rotations reaches the goal "
                          "(every reachable configuration was searched)")


def plan_exact(initial: Configuration, goal: frozenset[Cell], fixed: Cell | None = None,
               budget: float | None = DEFAULT_BUDGET, parallel: bool = True) -> Plan:
    """A plan with the fewest moves (``plan.reason`` says why when there is none)."""
    goal = frozenset(goal)
    plan = Plan(mode="exact", initial=initial, goal=goal, method="A*", fixed=fixed)
    plan.lower_bound = move_lower_bound(initial.cells, goal).value
    reason = check_inputs(initial, goal, fixed)
    if not reason and len(initial) > EXACT_LIMIT:
        reason = (f"exact: {len(initial)} modules, the exact search takes at most "
                  f"{EXACT_LIMIT} (use --mode robust)")
    if reason:
        plan.reason = reason
        return plan
    try:
        hops = shortest_hops(initial.cells, goal, fixed, Deadline(budget))
    except PlanningFailure as exc:
        plan.reason = str(exc)
        return plan
    ids = {c: m.id for c, m in initial.items()}
    serial = []
    for src, dst, rule, sub in hops:
        module = ids.pop(src)
        serial.append(Move(module, src, dst, rule.joint, rule.direction, sub, ids[sub]))
        ids[dst] = module
    steps = schedule_parallel(initial, serial) if parallel else None
    plan.steps = steps or [Step([m]) for m in serial]
    plan.reached = set(ids) == goal
    return plan
