"""Reconfiguration through a canonical strip: the robust planner's complete fallback.

The direct planner (:mod:`hexbot.planning.robust`) fills goal voids greedily
and can wall itself in. This module goes through an intermediate shape
instead, as the literature on pivoting modules does:

1. **initial -> strip.** The module on the *anchor* (the configuration's
   rightmost cell, topmost among those) never moves. The strip is a
   ``width``-row parallelogram that grows to the right of it, column by
   column, bottom to top (:func:`strip_cells`). Every cell right of the
   anchor's column is empty, so the strip touches the rest only at the anchor.
   For each strip cell in turn, the mover is the module farthest (in contact
   hops) from the anchor that is not a cut vertex and has a Table 4-3 path to
   the cell with everything else fixed. A farthest module is never a cut
   vertex of the contact graph, which is why peeling from the far end keeps
   movers available; the next strip cell always has its occupied sides in
   one arc of at most three (5, 6, 1 for a column cell), so it is enterable.
2. **strip -> strip.** The strips of the initial and the goal have the same
   shape; the direct planner shifts one onto the other in hops of at most
   ``HOP`` cells (convex shapes have no notches, so it does not stall there).
3. **strip -> goal** is step 1 run on the goal and reversed: every rotation is
   undone by the opposite one over the same cells (:func:`reverse_move`).

Each step raises :class:`PlanningFailure` when it cannot continue; the
caller then tries a narrower strip (width 1 is a line, which needs the most
moves and stalls least).
"""

from __future__ import annotations

from collections import deque
from dataclasses import replace

from hexbot.planning.budget import NO_DEADLINE, BudgetExhausted, Deadline
from hexbot.planning.configuration import (
    Configuration,
    Module,
    articulation_points,
    contact_hops,
)
from hexbot.planning.hexlattice import Cell, distance, rotate_cell, wrap
from hexbot.planning.moves import Move, orientation_after
from hexbot.planning.robust import (
    PlanningFailure,
    _moves_from,
    _single_arc,
    reverse_move,
    serial_moves,
    unwind,
)

#: Largest shift (cells) of one strip -> strip hop of the direct planner.
HOP = 1


def anchor_of(cells: frozenset[Cell] | set[Cell]) -> Cell:
    """The rightmost cell, topmost among those: nothing lies right of its column
    above it, nor anywhere right of its column."""
    return max(cells)


def strip_cells(anchor: Cell, count: int, width: int) -> list[Cell]:
    """The ``count - 1`` cells added right of ``anchor``, in build order."""
    cells: list[Cell] = []
    column = 1
    while len(cells) < count - 1:
        for row in range(width):
            if len(cells) < count - 1:
                cells.append((anchor[0] + column, anchor[1] + row))
        column += 1
    return cells


def strip_shape(anchor: Cell, count: int, width: int) -> frozenset[Cell]:
    return frozenset([anchor, *strip_cells(anchor, count, width)])


def _path_to(occupied: set[Cell], start: Cell, target: Cell) -> list | None:
    """Shortest Table 4-3 path of the module at ``start`` to ``target``, others fixed."""
    parent: dict[Cell, tuple | None] = {start: None}
    queue = deque([start])
    while queue:
        cell = queue.popleft()
        for rule, sub, goal in _moves_from(cell, occupied, start):
            if goal in parent:
                continue
            parent[goal] = (cell, rule, sub)
            if goal == target:
                return unwind(parent, goal)
            queue.append(goal)
    return None


def _reaching(occupied: set[Cell], target: Cell) -> set[Cell]:
    """Empty cells from which a module can roll to ``target`` with every module fixed
    (one search outward from the target: rotations are reversible over the same cells)."""
    seen = {target}
    queue = deque([target])
    while queue:
        cell = queue.popleft()
        for _, _, goal in _moves_from(cell, occupied, cell):
            if goal not in seen:
                seen.add(goal)
                queue.append(goal)
    return seen


#: Modules tried with the local arc test before the linear pass (see :func:`_pick_mover`).
QUICK = 3


def _pick_mover(occupied: set[Cell], order: list[Cell], target: Cell) -> tuple[int, list] | None:
    """The first module of ``order`` that may leave and roll to ``target``, with its path.

    Usually the farthest module qualifies: the first ``QUICK`` modules whose
    neighbours form one arc (never cut vertices) get a path search each. Otherwise,
    linear work per moved module: one cut-vertex pass, one search outward from the
    target, then one path search for the module it points at. The outward search
    counts the mover as an obstacle (and as a possible substrate), so when it points
    at no one, each module is searched on its own (rare).
    """
    for k, cell in enumerate(order[:QUICK]):
        if _single_arc(occupied, cell):
            path = _path_to(occupied, cell, target)
            if path:
                return k, path
    cuts = articulation_points(occupied)
    reach = _reaching(occupied, target)
    free = [k for k, c in enumerate(order) if c not in cuts]
    likely = [k for k in free
              if any(g in reach for _, _, g in _moves_from(order[k], occupied, order[k]))]
    for k in likely + [k for k in free if k not in set(likely)]:
        path = _path_to(occupied, order[k], target)
        if path:
            return k, path
    return None


def to_strip(config: Configuration, width: int,
             deadline: Deadline = NO_DEADLINE) -> list[Move]:
    """Serial moves that gather ``config`` into the strip at its anchor."""
    occupied = set(config.cells)
    ids = {c: m.id for c, m in config.items()}
    anchor = anchor_of(config.cells)
    built = {anchor}
    moves: list[Move] = []
    order: list[Cell] = []
    for target in strip_cells(anchor, len(config), width):
        deadline.check("canonical strip")
        if target in occupied:  # cannot happen: every cell right of the anchor is empty
            raise PlanningFailure(f"strip cell {target} is occupied")
        if not order:
            # farthest first; taking a farthest module changes no other distance, so the
            # order is only recomputed when a nearer module had to go instead
            hops = contact_hops(occupied, anchor)
            order = sorted((c for c in occupied if c not in built), key=lambda c: (-hops[c], c))
        picked = _pick_mover(occupied, order, target)
        if picked is None:
            raise PlanningFailure(
                f"no module can reach strip cell {target} (width {width}) after "
                f"{len(moves)} moves")
        k, path = picked
        del order[k]
        if k:
            order = []
        module = ids.pop(path[0][0])
        occupied.discard(path[0][0])
        for src, dst, rule, sub in path:
            moves.append(Move(module, src, dst, rule.joint, rule.direction, sub, ids[sub]))
        occupied.add(target)
        ids[target] = module
        built.add(target)
    return moves


def replay(config: Configuration, moves: list[Move]) -> Configuration:
    """The configuration after ``moves`` (fast: one dict, orientation tracked)."""
    cells = dict(config.items())
    for move in moves:
        module = cells.pop(move.src)
        if module.id != move.module:
            raise ValueError(f"module {move.module} is not at {move.src}")
        cells[move.dst] = Module(module.id, orientation_after(module.orientation,
                                                              move.direction))
    return Configuration(cells)


def _hop_anchors(start: Cell, end: Cell, hop: int = HOP) -> list[Cell]:
    """Anchors from ``start`` (excluded) to ``end``, at most ``hop`` cells apart."""
    count = -(-distance(start, end) // hop)
    return [(start[0] + round((end[0] - start[0]) * k / count),
             start[1] + round((end[1] - start[1]) * k / count)) for k in range(1, count + 1)]


def shift_strip(config: Configuration, start: Cell, end: Cell, width: int,
                max_moves: int, deadline: Deadline = NO_DEADLINE) -> list[Move]:
    """Serial moves taking the strip anchored at ``start`` to the one at ``end``."""
    moves: list[Move] = []
    for hop in _hop_anchors(start, end):
        try:
            part = serial_moves(config, strip_shape(hop, len(config), width), max_moves,
                                deadline=deadline, method="canonical strip")
        except BudgetExhausted:
            raise
        except PlanningFailure:
            if distance(start, hop) <= 1:
                raise
            # one cell at a time: a unit shift of a convex strip is the easy case
            part, at = [], config
            for unit in _hop_anchors(start, hop, 1):
                piece = serial_moves(at, strip_shape(unit, len(config), width), max_moves,
                                     deadline=deadline, method="canonical strip")
                part += piece
                at = replay(at, piece)
        moves += part
        config = replay(config, part)
        start = hop
    return moves


def reversed_to_strip(goal: frozenset[Cell], strip: Configuration, width: int,
                      deadline: Deadline = NO_DEADLINE) -> list[Move]:
    """Serial moves from ``strip`` (the goal's strip, with real module ids) to ``goal``."""
    provisional = Configuration.from_cells(goal, first_id=10**6)
    backward = to_strip(provisional, width, deadline)
    end = replay(provisional, backward)
    real = {end[c].id: strip[c].id for c in end}
    return [replace(reverse_move(m), module=real[m.module],
                    substrate_module=real[m.substrate_module]) for m in reversed(backward)]


def default_widths(count: int) -> list[int]:
    """Strip widths to try: about half the side of a square of ``count`` cells, then
    narrower; width 1 (a line) last."""
    wide = max(1, round(count ** 0.5 / 2))
    return sorted({wide, max(1, wide // 3), 1}, reverse=True)


def _rotated(config: Configuration, steps: int) -> Configuration:
    return Configuration({rotate_cell(c, steps): m for c, m in config.items()})


def _rotate_move(move: Move, steps: int) -> Move:
    """The same rotation seen in a frame turned ``steps`` sixth-turns clockwise:
    cells turn, and joint ``j`` becomes joint ``j + steps`` (sides turn with them)."""
    return replace(move, src=rotate_cell(move.src, steps), dst=rotate_cell(move.dst, steps),
                   substrate=rotate_cell(move.substrate, steps),
                   joint=wrap(move.joint + steps))


def _via_strip_once(initial: Configuration, goal: frozenset[Cell], width: int,
                    max_moves: int, deadline: Deadline = NO_DEADLINE) -> list[Move]:
    first = to_strip(initial, width, deadline)
    at_strip = replay(initial, first)
    shift = shift_strip(at_strip, anchor_of(initial.cells), anchor_of(goal), width, max_moves,
                        deadline)
    last = reversed_to_strip(goal, replay(at_strip, shift), width, deadline)
    return first + shift + last


def strip_estimate(initial: frozenset[Cell], goal: frozenset[Cell], turn: int) -> int:
    """A cheap guess of the strip route's length in the frame turned by ``turn``:
    how far the modules are from the anchor they gather at, in both configurations,
    plus every module travelling the part of the way between the two anchors that
    is across the strip's axis (y). A shift along the axis is cheap (the direct
    method slides the strip along itself), one across it moves every module.
    It ranks the six directions; measured on the benchmark's 100-module pairs
    (docs/planning.md), which is also what the weights were chosen on."""
    ra = {rotate_cell(c, -turn) for c in initial}
    rb = {rotate_cell(c, -turn) for c in goal}
    aa, ab = anchor_of(ra), anchor_of(rb)
    return (sum(distance(c, aa) for c in ra) + sum(distance(c, ab) for c in rb)
            + len(ra) * abs(ab[1] - aa[1]))


def via_strip(initial: Configuration, goal: frozenset[Cell], max_moves: int = 10**7,
              widths: list[int] | None = None, fixed: Cell | None = None,
              deadline: Deadline = NO_DEADLINE) -> list[Move]:
    """Serial moves initial -> strip -> goal's strip -> goal (raises PlanningFailure).

    Tries each width of ``widths`` (default :func:`default_widths`) with the strip
    growing in each of the six lattice directions (the whole problem is turned,
    planned, and its moves turned back), the directions ranked by
    :func:`strip_estimate`. A ``fixed`` module (bolted to the base)
    allows only the directions in which it is the anchor of both configurations.
    """
    failures = []
    turns = list(range(6))
    if fixed is not None:
        turns = [t for t in turns
                 if rotate_cell(fixed, -t) == anchor_of({rotate_cell(c, -t) for c in goal})
                 == anchor_of({rotate_cell(c, -t) for c in initial.cells})]
        if not turns:
            raise PlanningFailure(f"the fixed module at {fixed} would have to move (a strip "
                                  "keeps only the extreme module in place, and the fixed one "
                                  "is not extreme in the same direction in both "
                                  "configurations)")
    turns.sort(key=lambda t: (strip_estimate(initial.cells, goal, t), t))
    for width in widths or default_widths(len(initial)):
        for turn in turns:
            try:
                moves = _via_strip_once(_rotated(initial, -turn),
                                        frozenset(rotate_cell(c, -turn) for c in goal),
                                        width, max_moves, deadline)
            except BudgetExhausted:
                raise
            except PlanningFailure as exc:
                failures.append(f"width {width}, direction {turn}: {exc}")
                continue
            if len(moves) > max_moves:
                raise PlanningFailure(f"more than {max_moves} moves needed")
            return [_rotate_move(m, turn) for m in moves]
    raise PlanningFailure("no canonical strip could be built (" + "; ".join(failures[:2])
                          + (f"; {len(failures) - 2} more" if len(failures) > 2 else "") + ")")
