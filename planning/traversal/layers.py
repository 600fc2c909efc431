"""Perimeter layers: the probing module's walk over the surface, numbered.

Steps 1-2 of FINDBRIDGECELLS: a virtual probing module rolls clockwise over
the surface from the source end to the goal end and numbers, in ascending
order, each perimeter cell it enters (``layer1``); the same walk over the
surface plus ``layer1`` gives ``layer2``. The walk is the rule of
:func:`~hexbot.planning.traversal.motion.next_rotation` with the surface as
the only occupied cells, so a layer is exactly the path a lone module
follows under the chosen motion model. A cell entered twice (the neck of a
pocket) carries two numbers; ``first`` keeps the first.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from dataclasses import dataclass, field

from hexbot.errors import ScenarioError
from hexbot.planning.traversal.motion import next_rotation
from hexbot.protocol.lattice import SIDES, Cell, neighbor, wrap


class Stuck(ScenarioError):
    """The probing module has no move left at ``cell``; ``walk`` is its way there."""

    def __init__(self, cell: Cell, walk: Layer) -> None:
        super().__init__(f"the probing module is stuck at {list(cell)}")
        self.cell, self.walk = cell, walk


@dataclass
class Layer:
    """Cells in the order the probing module enters them (index = perimeter number)."""

    cells: list[Cell]
    pivots: list[Cell]  # the substrate the probe stood on in each cell
    visits: dict[Cell, list[int]] = field(default_factory=dict)

    def __post_init__(self) -> None:
        if not self.visits:
            for index, cell in enumerate(self.cells):
                self.visits.setdefault(cell, []).append(index)

    def __len__(self) -> int:
        return len(self.cells)

    def __contains__(self, cell: object) -> bool:
        return cell in self.visits

    def first(self, cell: Cell) -> int:
        return self.visits[cell][0]


def start_pivot(cell: Cell, occupied: Callable[[Cell], bool]) -> Cell | None:
    """The substrate a probe at ``cell`` starts from: the occupied side that has
    a free side after it counterclockwise (the end of an occupied arc)."""
    for side in SIDES:
        if occupied(neighbor(cell, side)) and not occupied(neighbor(cell, wrap(side - 1))):
            return neighbor(cell, side)
    return None


def closed_walk(cell: Cell, occupied: Callable[[Cell], bool], model: str,
                limit: int) -> Layer:
    """The probe's walk from ``cell`` until it is back in the same state."""
    pivot = start_pivot(cell, occupied)
    if pivot is None:
        raise ScenarioError(f"cell {list(cell)} touches no occupied cell to roll on")
    cells, pivots = [cell], [pivot]
    seen = {(cell, pivot): 0}
    for _ in range(limit):
        rolled = next_rotation(cells[-1], pivots[-1], "CW", occupied, model)
        if rolled is None:
            raise Stuck(cells[-1], Layer(cells, pivots))
        state = (rolled.dst, rolled.substrate)
        if state in seen:  # the walk closed (the start may lie just off the loop)
            first = seen[state]
            return Layer(cells[first:], pivots[first:])
        seen[state] = len(cells)
        cells.append(rolled.dst)
        pivots.append(rolled.substrate)
    raise ScenarioError(f"the perimeter walk from {list(cell)} does not close in {limit} moves")


def segment(walk: Layer, start: int, end: int) -> Layer:
    """Entries ``start..end`` (inclusive) of a closed walk, cyclically."""
    size = len(walk)
    idx = [(start + k) % size for k in range((end - start) % size + 1)]
    return Layer([walk.cells[i] for i in idx], [walk.pivots[i] for i in idx])


def layer1(surface: frozenset[Cell], modules: Iterable[Cell], goals: Iterable[Cell],
           model: str) -> Layer:
    """The surface perimeter from the tail of the chain to the farthest goal."""
    modules, goals = set(modules), set(goals)
    try:
        walk = closed_walk(min(modules), surface.__contains__, model, 8 * len(surface) + 64)
    except Stuck as stuck:  # past the goals, an open walk is enough (under the surface)
        if not (modules | goals) <= set(stuck.walk.cells):
            raise
        walk = stuck.walk
    marks = [c in modules for c in walk.cells]
    size = len(walk)
    starts = [i for i in range(size) if marks[i] and not marks[i - 1]]
    if not starts:  # the walk is all modules: impossible with goals elsewhere
        raise ScenarioError("the chain of modules covers the whole perimeter")
    tail = starts[0]
    on_walk = set(walk.cells)
    missing = (modules | goals) - on_walk
    if missing:
        raise ScenarioError(
            f"cell {list(min(missing))} is not on the perimeter the modules roll along "
            f"(under the {model} motion model)")
    order = [walk.cells[(tail + k) % size] for k in range(size)]
    if len(starts) > 1 or set(order[: len(modules)]) != modules:
        raise ScenarioError("the modules (M) do not form one chain along the perimeter")
    last_goal = max(k for k, c in enumerate(order) if c in goals)
    first_goal = min(k for k, c in enumerate(order) if c in goals)
    goal_run = set(order[first_goal: last_goal + 1])
    if goal_run != goals:
        raise ScenarioError("the goal cells (G) are not consecutive along the perimeter, "
                            "clockwise after the modules")
    return segment(walk, tail, (tail + last_goal) % size)


def layer2(surface: frozenset[Cell], first: Layer, model: str) -> Layer:
    """The perimeter of surface + layer1, from the source end to the goal end."""
    occupied_cells = surface | set(first.cells)
    occupied = occupied_cells.__contains__
    start = next((neighbor(first.cells[0], s) for s in SIDES
                  if not occupied(neighbor(first.cells[0], s))
                  and start_pivot(neighbor(first.cells[0], s), occupied) is not None), None)
    if start is None:
        return Layer([], [])
    try:
        walk = closed_walk(start, occupied, model, 8 * len(occupied_cells) + 64)
    except Stuck as stuck:  # hexbot model: layer2 only serves 3-bridge patterns
        walk = stuck.walk
    near_end = {neighbor(first.cells[-1], s) for s in SIDES}
    last = max((k for k, c in enumerate(walk.cells) if c in near_end), default=len(walk) - 1)
    return segment(walk, 0, last)
