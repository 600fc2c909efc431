"""Reconfiguration through a compact middle shape: the short detour of the robust planner.

When the direct method stalls on the notches of a goal (or of the initial,
backwards), the planner used to go straight to the canonical strip, whose
plans are tens to hundreds of times the distance bound because every module
walks to a far-away line. A compact *ball* (the cells nearest a centre, the
last ring filled as one contiguous arc) has no notches, and placed at the
centre of both configurations it is close to both, so:

1. **initial -> ball** by the direct method (forward);
2. **ball -> goal** by the direct method run from the goal to the ball and
   reversed (every rotation is undone by the opposite one over the same cells).

Several balls are tried (:func:`middles`): seven for small configurations,
one for large ones, where each failed try costs seconds. Both halves keep
the direct method's guarantees (connected, collision-free,
Table 4-3). Nothing here is complete: any :class:`PlanningFailure` sends the
caller on to the canonical strip, which stays the complete fallback.
"""

from __future__ import annotations

from hexbot.planning.budget import NO_DEADLINE, BudgetExhausted, Deadline
from hexbot.planning.canonical import replay
from hexbot.planning.configuration import Configuration
from hexbot.planning.hexlattice import SIDE_OFFSETS, Cell
from hexbot.planning.moves import Move
from hexbot.planning.robust import PlanningFailure, reversed_plan, serial_moves


def ring(center: Cell, radius: int) -> list[Cell]:
    """The cells at ``radius`` from ``center``, walked once around (consecutive
    cells touch, so any prefix is one contiguous arc)."""
    if radius == 0:
        return [center]
    sides = [SIDE_OFFSETS[s] for s in (1, 2, 3, 4, 5, 6)]
    # start ``radius`` steps out along side 5, then walk sides 1..6 in turn: a closed loop
    x, y = center[0] + sides[4][0] * radius, center[1] + sides[4][1] * radius
    cells = []
    for dx, dy in sides:
        for _ in range(radius):
            cells.append((x, y))
            x, y = x + dx, y + dy
    return cells


def ball(center: Cell, count: int) -> frozenset[Cell]:
    """``count`` cells: full rings around ``center``, then an arc of the next ring."""
    cells: list[Cell] = []
    radius = 0
    while len(cells) < count:
        cells += ring(center, radius)[: count - len(cells)]
        radius += 1
    return frozenset(cells)


def middle_center(initial: frozenset[Cell], goal: frozenset[Cell]) -> Cell:
    """The lattice cell at the mean of both configurations (axial means are linear,
    so this is the centroid in the plane too)."""
    cells = list(initial) + list(goal)
    return (round(sum(x for x, _ in cells) / len(cells)),
            round(sum(y for _, y in cells) / len(cells)))


#: How many middle shapes to try before giving up: all seven balls for small
#: configurations (a failed try costs milliseconds there, and on 500 random pairs of
#: 3-30 modules seven tries left 8 pairs to the strip instead of 53), one above
#: ``SMALL`` modules (a failed try costs about 0.2 s at 100 modules, 6-9 s at 1,000).
TRIES = (7, 1)
SMALL = 40


def middles(initial: frozenset[Cell], goal: frozenset[Cell]) -> list[frozenset[Cell]]:
    """Candidate middle shapes, most promising first: the ball at the centre of
    both configurations, then balls nudged around it (which notches a ball meets
    decides whether the direct method stalls). Balls beat square parallelograms
    in the measurements (docs/planning.md)."""
    count = len(initial)
    cx, cy = middle_center(initial, goal)
    nudge = max(1, round(count ** 0.5 / 4))
    centers = [(cx, cy)] + [(cx + dx * nudge, cy + dy * nudge)
                            for dx, dy in (SIDE_OFFSETS[s] for s in (1, 2, 3, 4, 5, 6))]
    shapes: list[frozenset[Cell]] = []
    for center in centers:
        shape = ball(center, count)
        if shape not in shapes:
            shapes.append(shape)
    return shapes[: TRIES[0] if count <= SMALL else TRIES[1]]


def via_middle(initial: Configuration, goal: frozenset[Cell], max_moves: int,
               fixed: Cell | None = None, budget: int | None = None,
               deadline: Deadline = NO_DEADLINE) -> list[Move]:
    """Serial moves initial -> middle -> goal (raises :class:`PlanningFailure`),
    trying each shape of :func:`middles` in turn."""
    failures = []
    for middle in middles(initial.cells, goal):
        try:
            return _via(initial, goal, middle, max_moves, fixed, budget, deadline)
        except BudgetExhausted:
            raise
        except PlanningFailure as exc:
            failures.append(str(exc))
    raise PlanningFailure("no middle shape worked (" + "; ".join(failures[:2]) + ")")


def _via(initial: Configuration, goal: frozenset[Cell], middle: frozenset[Cell],
         max_moves: int, fixed: Cell | None, budget: int | None,
         deadline: Deadline = NO_DEADLINE) -> list[Move]:
    if fixed is not None and fixed not in middle:
        # the fixed module would have to move into the ball
        raise PlanningFailure(f"the middle ball does not hold the fixed module at {fixed}")
    first = serial_moves(initial, middle, max_moves, fixed, budget, aside_limit=None,
                         deadline=deadline, method="middle ball")
    at_middle = replay(initial, first)
    last = reversed_plan(at_middle, goal, max_moves - len(first), fixed, budget,
                         aside_limit=None, deadline=deadline, method="middle ball")
    return first + last
