"""Lower bounds on plans: moves (assignment) and time steps (bottleneck).

* **Moves.** A rotation moves one module to a neighbouring cell, so a plan
  sends each module of the initial configuration to a goal cell along at
  least its hex distance. Its move count is at least the cheapest assignment
  of initial cells to goal cells; with a metric cost the shared cells can
  stay put, so that is the cheapest assignment of the cells to leave onto the
  cells to fill (Hungarian method, :func:`scipy.optimize.linear_sum_assignment`).
* **Time steps, plain bottleneck** (:func:`bottleneck_bound`, the issue's
  yardstick). A module moves at most one cell per step, so the makespan
  is at least the smallest possible largest distance of an assignment of
  *all* initial cells onto *all* goal cells (the bottleneck assignment: here
  the shared cells need not stay, a chain of shifts can beat the cells to
  leave). Found by bisection on the distance: at each level, a perfect
  matching of the pairs no farther apart exists when the cheapest assignment
  with cost 1 for a pair farther apart costs nothing
  (:func:`scipy.optimize.linear_sum_assignment`). scipy's
  ``maximum_bipartite_matching`` did the same in most cases in milliseconds,
  but took 44 s on one level of a blob of 1,000 (seed 0, distance 2, where
  989 of 1,000 match); the assignment takes 0.04 s for the whole bisection.
* **Time steps, pivot bound** (:func:`step_bound`). The plain bound lets a
  whole flat side shift at once, but a rotation needs three free sides in a
  row at the start of its step (its goal and two swept cells, Table 4-3;
  within a step no two moves share a cell, so a cell emptied in the step
  does not count). :func:`leave_times` gives each module the earliest step
  it can rotate at all: 1 with three free sides in a row, else the best run
  of three sides of the latest of (1 for an empty cell, one more than the
  neighbour's own earliest step). A module that goes from cell c to another
  cell g makes its first move at step >= leave(c) and, played backwards
  (every rotation can be undone, so a plan of T steps reversed is a plan
  from the goal), its last one at step <= T + 1 - leave_goal(g): so
  T >= leave(c) + dist(c, g) + leave_goal(g) - 2. The same bisection over
  that cost (0 for a module that stays) gives the bound. The bolted module
  never leaves.

All are exact up to ``ASSIGNMENT_LIMIT`` cells to leave and
``BOTTLENECK_LIMIT`` modules (dense distance matrices); above that they fall
back to the nearest-cell bounds (weaker, still valid) and say so in ``kind``.
"""

from __future__ import annotations

import heapq
from dataclasses import dataclass

import numpy as np
from scipy.optimize import linear_sum_assignment

from hexbot.planning.hexlattice import Cell, neighbors

#: Largest number of cells to leave for the exact assignment bound (dense n x n matrix).
ASSIGNMENT_LIMIT = 5000
#: Largest module count for the exact bottleneck bound.
BOTTLENECK_LIMIT = 3000


@dataclass(frozen=True)
class Bound:
    value: int
    kind: str  # "assignment", "bottleneck", "pivot", or "nearest" (the weaker fallback)


def hex_distances(a: list[Cell], b: list[Cell]) -> np.ndarray:
    """Matrix of hex distances (axial coordinates: max(|dx|, |dy|, |dx + dy|))."""
    pa, pb = np.asarray(a, dtype=np.int32), np.asarray(b, dtype=np.int32)
    dx = pa[:, None, 0] - pb[None, :, 0]
    dy = pa[:, None, 1] - pb[None, :, 1]
    return np.maximum(np.maximum(np.abs(dx), np.abs(dy)), np.abs(dx + dy))


def _nearest_sum(a: list[Cell], b: list[Cell], chunk: int = 512) -> tuple[int, int]:
    """(sum over a of the distance to the nearest b, largest such distance)."""
    total, worst = 0, 0
    for i in range(0, len(a), chunk):
        near = hex_distances(a[i:i + chunk], b).min(axis=1)
        total += int(near.sum())
        worst = max(worst, int(near.max()))
    return total, worst


def move_lower_bound(current: frozenset[Cell], goal: frozenset[Cell]) -> Bound:
    """Fewest moves any plan needs (see the module docstring)."""
    leave, fill = sorted(current - goal), sorted(goal - current)
    if not leave or not fill:  # nothing to move, or not a pair (the planners say why)
        return Bound(0, "assignment")
    if len(leave) <= ASSIGNMENT_LIMIT:
        cost = hex_distances(leave, fill)
        rows, cols = linear_sum_assignment(cost)
        return Bound(int(cost[rows, cols].sum()), "assignment")
    return Bound(max(_nearest_sum(leave, fill)[0], _nearest_sum(fill, leave)[0]), "nearest")


def bottleneck_bound(current: frozenset[Cell], goal: frozenset[Cell]) -> Bound:
    """Fewest time steps by distance alone (see the module docstring)."""
    if current == goal:
        return Bound(0, "bottleneck")
    a, b = sorted(current), sorted(goal)
    if len(a) > BOTTLENECK_LIMIT:
        return Bound(max(_nearest_sum(a, b)[1], _nearest_sum(b, a)[1]), "nearest")
    return Bound(_bottleneck(hex_distances(a, b)), "bottleneck")


def _bottleneck(cost: np.ndarray) -> int:
    """The smallest largest cost of a perfect assignment (bisection on the levels)."""
    levels = np.unique(cost)
    lo, hi = 0, len(levels) - 1  # a perfect matching exists at levels[hi]
    while lo < hi:
        mid = (lo + hi) // 2
        far = cost > levels[mid]
        rows, cols = linear_sum_assignment(far)
        if not far[rows, cols].any():
            hi = mid
        else:
            lo = mid + 1
    return int(levels[lo])


#: Leave time of a module that can never rotate (the bolted one, or one only it frees).
#: Above any real bound: a pair's distances stay below 4 x ``COORD_LIMIT`` and a
#: leave time below the module count (it was 2^20, and pairs farther apart than
#: that lost their bounds as if no plan could exist); int64 sums of two stay exact.
NEVER = 1 << 40


def leave_times(cells: frozenset[Cell], fixed: Cell | None = None) -> dict[Cell, int]:
    """The earliest step at which each module of ``cells`` can make a rotation
    (see the module docstring): a shortest-path pass, since a module's time
    only grows with its neighbours' and each settles once."""
    time = dict.fromkeys(cells, NEVER)

    def earliest(cell: Cell) -> int:
        free = [1 if n not in time else time[n] + 1 for n in neighbors(cell)]
        return min(max(free[i], free[i - 1], free[i - 2]) for i in range(6))

    heap = []
    for cell in cells:
        if cell != fixed:
            time[cell] = earliest(cell)
            heap.append((time[cell], cell))
    heapq.heapify(heap)
    settled: set[Cell] = set()
    while heap:
        t, cell = heapq.heappop(heap)
        if cell in settled or t != time[cell] or t >= NEVER:
            continue
        settled.add(cell)
        for n in neighbors(cell):
            if n in time and n not in settled and n != fixed:
                better = earliest(n)
                if better < time[n]:
                    time[n] = better
                    heapq.heappush(heap, (better, n))
    return time


def step_bound(current: frozenset[Cell], goal: frozenset[Cell],
               fixed: Cell | None = None) -> Bound:
    """Fewest time steps any plan needs: the pivot bound (module docstring)."""
    if current == goal:
        return Bound(0, "pivot")
    a, b = sorted(current), sorted(goal)
    leave, arrive = leave_times(frozenset(current), fixed), leave_times(frozenset(goal), fixed)
    start = np.array([leave[c] for c in a], dtype=np.int64)
    end = np.array([arrive[c] for c in b], dtype=np.int64)
    if len(a) > BOTTLENECK_LIMIT:
        return Bound(_nearest_pivot(current, goal, leave, arrive), "nearest")
    dist = hex_distances(a, b).astype(np.int64)
    cost = np.where(dist == 0, 0, dist + start[:, None] + end[None, :] - 2)
    return Bound(_bottleneck(cost), "pivot")


@dataclass(frozen=True)
class PlanBounds:
    """What no plan of a pair can beat: the bench's columns and the CLI's report."""

    moves: Bound  # assignment (or nearest)
    time_steps: Bound  # the pivot bound (or nearest)
    bottleneck: Bound  # the plain bottleneck bound, the yardstick (or nearest)

    def as_json(self) -> dict[str, dict[str, int | str]]:
        return {name: {"value": bound.value, "kind": bound.kind}
                for name, bound in (("moves", self.moves), ("time_steps", self.time_steps),
                                    ("bottleneck", self.bottleneck))}


def plan_bounds(current: frozenset[Cell], goal: frozenset[Cell],
                fixed: Cell | None = None) -> PlanBounds:
    """The three bounds of the pair (0.2-0.4 s at 1,000 modules, about 2 s at
    10,000); ``fixed``: the module bolted to the base."""
    current, goal = frozenset(current), frozenset(goal)
    return PlanBounds(move_lower_bound(current, goal), step_bound(current, goal, fixed),
                      bottleneck_bound(current, goal))


def _nearest_pivot(current, goal, leave, arrive, chunk: int = 256) -> int:
    """The pivot bound's fallback: a module on a cell to leave goes to some
    other goal cell, and a cell to fill is entered by a module from some
    other cell; each alone, with its cheapest partner (weaker, valid)."""
    worst = 0
    for movers, partners, own, other in ((sorted(current - goal), sorted(goal), leave, arrive),
                                         (sorted(goal - current), sorted(current), arrive, leave)):
        extra = np.array([other[c] for c in partners], dtype=np.int64)
        for i in range(0, len(movers), chunk):
            part = movers[i:i + chunk]
            dist = hex_distances(part, partners).astype(np.int64)
            cost = np.where(dist == 0, NEVER, dist + extra[None, :]).min(axis=1)
            cost += np.array([own[c] for c in part], dtype=np.int64) - 2
            worst = max(worst, int(cost.max()))
    return worst
