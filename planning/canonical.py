"""Reconfiguration through a canonical strip: the robust planner's complete fallback.

The direct planner (:mod:`hexbot.planning.robust`) fills goal voids greedily
and can wall itself in. This module goes through an intermediate shape
instead, as the literature on pivoting modules does:

1. **initial -> strip.** The module on the *anchor* (the configuration's
   rightmost cell, topmost among those) never moves. The strip is a line of
   ``LEAD`` cells, then a ``width``-row parallelogram that grows to the right
   of it, column by column, bottom to top (:func:`strip_cells`). Every cell right of the
   anchor's column is empty, so the strip touches the rest only at the anchor.
   For each strip cell in turn, the mover is the module farthest (in contact
   hops) from the anchor that is not a cut vertex and has a Table 4-3 path to
   the cell with everything else fixed. A farthest module is never a cut
   vertex of the contact graph, which is why peeling from the far end keeps
   movers available; the next strip cell always has its occupied sides in
   one arc of at most three (5, 6, 1 for a column cell), so it is enterable.
2. **strip -> strip.** The strips of the initial and the goal have the same
   shape; they are shifted one onto the other in hops of at most ``HOP``
   cells, each in the strip's own order (:func:`_hop`), by the direct planner
   when that stalls (convex shapes have no notches, so it does not stall there).
3. **strip -> goal** is step 1 run on the goal and reversed: every rotation is
   undone by the opposite one over the same cells (:func:`undone`). The goal
   is gathered first: failures mostly happen there.

Each step raises :class:`PlanningFailure` when it cannot continue; the
caller then tries a narrower strip (width 1 is a line, which needs the most
moves and stalls least).
"""

from __future__ import annotations

import bisect
import heapq
from collections import deque

from hexbot.planning import _strip
from hexbot.planning.budget import MAX_MOVES, NO_DEADLINE, BudgetExhausted, Deadline
from hexbot.planning.configuration import (
    Configuration,
    Module,
)
from hexbot.planning.hexlattice import (
    ROTATIONS,
    Cell,
    distance,
    neighbors,
    rotate_cell,
    wrap,
)
from hexbot.planning.moves import TURN, Move, new_move
from hexbot.planning.robust import (
    _AROUND12,
    ROTATION_MASKS,
    PlanningFailure,
    serial_moves,
)
from hexbot.planning.schedule import _AROUND, stays_connected

#: Largest shift (cells) of one strip -> strip hop of the direct planner.
HOP = 1


def anchor_of(cells: frozenset[Cell] | set[Cell]) -> Cell:
    """The rightmost cell, topmost among those: nothing lies right of its column
    above it, nor anywhere right of its column."""
    return max(cells)


#: Cells of the lead-in: a line from the anchor to the strip's first column.
LEAD = 2


def strip_cells(anchor: Cell, count: int, width: int, lead: int | None = None) -> list[Cell]:
    """The ``count - 1`` cells added right of ``anchor``, in build order: a
    line of ``lead`` cells, then the ``width``-row columns."""
    lead = LEAD if lead is None else lead
    cells: list[Cell] = [(anchor[0] + k, anchor[1]) for k in range(1, min(lead, count - 1) + 1)]
    column = len(cells) + 1
    while len(cells) < count - 1:
        for row in range(width):
            if len(cells) < count - 1:
                cells.append((anchor[0] + column, anchor[1] + row))
        column += 1
    return cells


def strip_shape(anchor: Cell, count: int, width: int) -> frozenset[Cell]:
    return frozenset([anchor, *strip_cells(anchor, count, width)])


# Table 4-3 by the occupancy around a mobile module. Every rotation only looks at
# the 12 cells within two steps of it (6 neighbours, 6 second-ring cells between
# them): the C searches (``planning/_strip.c``) read those as the bits of a mask
# and try the rotations in the order of ROTATIONS (the order robust._moves_from
# tries them, so they find the same paths as the generic search).
_strip.set_rules(_AROUND12, ROTATION_MASKS, _AROUND)

#: Farthest modules (never cut vertices) tried with a path search each, before the
#: search outward from the target (see :meth:`StripGrid.pick`).
FARTHEST = 4


class StripGrid:
    """The occupied cells of a strip route as a grid the C searches read
    (``planning/_strip.c``: most of a 10,000-module strip's time was spent in
    these searches in Python). The caller keeps it in step with its own set
    (:meth:`put`); it spans ``occupied`` and ``span`` (the cells it will
    fill: the strip, a search's target) with ``MARGIN`` cells around them.
    The C side refuses a cell closer than 3 to the edge: a searched cell
    touches a module, and a rotation looks 2 cells further."""

    MARGIN = 5

    def __init__(self, occupied: set[Cell] | frozenset[Cell], span=()) -> None:
        xs = [x for x, _ in occupied] + [x for x, _ in span]
        ys = [y for _, y in occupied] + [y for _, y in span]
        self.xmin, self.ymin = min(xs) - self.MARGIN, min(ys) - self.MARGIN
        self._grid = _strip.grid(self.xmin, self.ymin, max(xs) - self.xmin + self.MARGIN + 1,
                                 max(ys) - self.ymin + self.MARGIN + 1)
        for cell in occupied:
            _strip.put(self._grid, cell, True)

    def put(self, cell: Cell, occupied: bool) -> None:
        _strip.put(self._grid, cell, occupied)

    def path(self, start: Cell, target: Cell) -> list | None:
        """Shortest Table 4-3 path (hops as :func:`robust.unwind` gives them) of the
        module at ``start`` to ``target``, others fixed; the mover counts as absent
        (neither an obstacle nor a substrate, as in ``robust._moves_from``)."""
        return _rules(_strip.path(self._grid, start, target))

    def nearest(self, cells: list[Cell], target: Cell) -> list[tuple[int, int]]:
        """(rotations, k) for each module ``cells[k]`` whose first rotation lands
        where a module rolls to ``target`` from, every module fixed: the fewest
        rotations from such a landing cell to ``target``."""
        return _strip.nearest(self._grid, cells, target)

    def pick(self, order: list[Cell], target: Cell, farthest: int = 0) -> tuple[int, list] | None:
        """The first module of ``order`` that may leave and roll to ``target``, with
        its path.

        The first ``farthest`` modules of ``order`` are at the largest distance
        from the anchor, so none is a cut vertex: up to ``FARTHEST`` of them get a
        path search each, with no cut test. Otherwise one search outward from the
        target finds the cells a module can roll to it from, and the modules are
        scanned in order for one with a first rotation into them that cannot
        disconnect anything (farthest, or neighbours in one arc); only when none
        qualifies, one cut-vertex pass decides for the others. The outward search
        counts the mover as an obstacle (and as a possible substrate), so each
        candidate's path is still searched; when no candidate has one, each module
        is searched on its own (rare). All of it runs in C."""
        picked = _strip.pick(self._grid, order, target, farthest, min(farthest, FARTHEST))
        return None if picked is None else (picked[0], _rules(picked[1]))


def _rules(hops: list | None) -> list | None:
    """The C searches' hops with their rotation index turned into the rotation."""
    if hops is None:
        return None
    return [(src, dst, ROTATIONS[rule], sub) for src, dst, rule, sub in hops]


def path_to(occupied: set[Cell] | frozenset[Cell], start: Cell, target: Cell) -> list | None:
    """Shortest Table 4-3 path of the module at ``start`` to ``target``, others
    fixed (:meth:`StripGrid.path` on a grid made for this one search)."""
    return StripGrid(occupied, (target,)).path(start, target)


def _hops_from(occupied: set[Cell], roots: list[Cell]) -> dict[Cell, int]:
    """Contact hops from the nearest of ``roots`` (one breadth-first pass, level by
    level; the same numbers as ``configuration.contact_hops``, inline: to_strip
    recomputes them whenever a module nearer than the farthest had to move)."""
    hops = dict.fromkeys(roots, 0)
    frontier = list(roots)
    depth = 0
    while frontier:
        depth += 1
        reached = []
        for x, y in frontier:
            for dx, dy in _AROUND:
                n = (x + dx, y + dy)
                if n in occupied and n not in hops:
                    hops[n] = depth
                    reached.append(n)
        frontier = reached
    return hops


def _hops_without(occupied: set[Cell], hops: dict[Cell, int], gone: Cell) -> list[Cell]:
    """Update ``hops`` (contact hops from the roots) in place for the module at
    ``gone`` having left ``occupied`` (not a cut vertex: everything stays
    reachable); return the cells whose hops grew.

    Removing a module can only lengthen paths, and only for the cells whose every
    shortest path went through it: found level by level from its neighbours one
    hop farther (a cell keeps its number if a neighbour one hop nearer kept its
    own), then numbered again from their unaffected neighbours. Usually a few
    cells; the same numbers as a new search (:func:`_hops_from`), which costs
    O(n) each time a module nearer than the farthest has to move."""
    h = hops.pop(gone)
    x, y = gone
    level = [n for n in ((x + dx, y + dy) for dx, dy in _AROUND) if hops.get(n) == h + 1]
    grown: set[Cell] = set()
    while level:
        deeper = []
        for u in level:
            if u in grown:
                continue
            d = hops[u] - 1
            ux, uy = u
            around = [(ux + dx, uy + dy) for dx, dy in _AROUND]
            if any(hops.get(w) == d and w not in grown for w in around):
                continue
            grown.add(u)
            deeper.extend(w for w in around if hops.get(w) == d + 2)
        level = deeper
    if not grown:
        return []
    for u in grown:
        del hops[u]
    heap = []
    for u in grown:
        ux, uy = u
        best = min((hops[w] for w in ((ux + dx, uy + dy) for dx, dy in _AROUND) if w in hops),
                   default=None)
        if best is not None:
            heap.append((best + 1, u))
    heapq.heapify(heap)
    while heap:
        d, u = heapq.heappop(heap)
        if u in hops:
            continue
        hops[u] = d
        ux, uy = u
        for dx, dy in _AROUND:
            w = (ux + dx, uy + dy)
            if w in grown and w not in hops:
                heapq.heappush(heap, (d + 1, w))
    return sorted(grown)


#: Above this many cells with longer hops, the order is sorted again (below, each
#: is moved to its place).
RESORT = 64


def to_strip(config: Configuration, width: int,
             deadline: Deadline = NO_DEADLINE, keep: list[Cell] | None = None,
             turn: int = 0) -> list[Move]:
    """Serial moves that gather ``config`` into the strip at its anchor.

    ``turn``: the moves are given in the frame turned by ``turn`` sixth-turns
    (as :func:`_rotate_moves` would turn them, without a second copy of them).

    ``keep``: a path of modules from a fixed module to the anchor that stays put
    (a *spine*, :func:`spine_to`); the others gather farthest from it first. A
    module farthest from a connected set it is not part of is never a cut
    vertex, so the argument of the plain strip carries over."""
    occupied = set(config.cells)
    ids = {c: m.id for c, m in config.items()}
    anchor = anchor_of(config.cells)
    roots = list(keep) if keep else [anchor]
    if anchor not in roots:
        raise ValueError(f"the spine must end at the anchor {anchor}")
    built = set(roots)
    moves: list[Move] = []
    place = _framer(turn)
    joints = {j: wrap(j + turn) for j in range(1, 7)}
    targets = strip_cells(anchor, len(config) - len(roots) + 1, width)
    grid = StripGrid(occupied, targets)
    order: list[Cell] = []
    for target in targets:
        deadline.check("canonical strip")
        if target in occupied:  # cannot happen: every cell right of the anchor is empty
            raise PlanningFailure(f"strip cell {target} is occupied")
        if not order:
            hops = _hops_from(occupied, roots)
            order = sorted((c for c in occupied if c not in built), key=lambda c: (-hops[c], c))
        top = hops[order[0]]
        farthest = next((k for k, c in enumerate(order) if hops[c] != top), len(order))
        picked = grid.pick(order, target, farthest)
        if picked is None:
            raise PlanningFailure(
                f"no module can reach strip cell {target} (width {width}) after "
                f"{len(moves)} moves")
        k, path = picked
        taken = order.pop(k)
        module = ids.pop(taken)
        occupied.discard(taken)
        grid.put(taken, False)
        # farthest first; taking a farthest module changes no other distance; a nearer
        # one may lengthen the hops of the cells behind it, which then move forward
        grown = _hops_without(occupied, hops, taken) if hops[taken] != top else []
        hops.pop(taken, None)  # (a farthest one: nothing behind it to update)
        if len(grown) > RESORT:
            order.sort(key=lambda c: (-hops[c], c))
        elif grown:
            moved = set(grown)
            order = [c for c in order if c not in moved]
            for c in grown:
                bisect.insort(order, c, key=lambda c: (-hops[c], c))
        for src, dst, rule, sub in path:
            moves.append(new_move(module, place(src), place(dst), joints[rule.joint],
                                  rule.direction, place(sub), ids[sub]))
        occupied.add(target)
        grid.put(target, True)
        ids[target] = module
        built.add(target)
    return moves


def replay(config: Configuration, moves: list[Move]) -> Configuration:
    """The configuration after ``moves`` (fast: one dict of (id, orientation), the
    modules made once at the end; a strip route replays millions of moves)."""
    cells = {c: (m.id, m.orientation) for c, m in config.items()}
    for move in moves:
        module, facing = cells.pop(move.src)
        if module != move.module:
            raise ValueError(f"module {move.module} is not at {move.src}")
        cells[move.dst] = (module, (facing + TURN[move.direction]) % 6)
    return Configuration({c: Module(i, o) for c, (i, o) in cells.items()})


def _hop_anchors(start: Cell, end: Cell, hop: int = HOP) -> list[Cell]:
    """Anchors from ``start`` (excluded) to ``end``, at most ``hop`` cells apart."""
    count = -(-distance(start, end) // hop)
    return [(start[0] + round((end[0] - start[0]) * k / count),
             start[1] + round((end[1] - start[1]) * k / count)) for k in range(1, count + 1)]


def _free_three(blocked: set[Cell], cell: Cell) -> bool:
    """Has ``cell`` three consecutive sides outside ``blocked`` (a rotation can enter it)?"""
    x, y = cell
    free = [(x + dx, y + dy) not in blocked for dx, dy in _AROUND]
    return any(free[i] and free[i - 1] and free[i - 2] for i in range(6))


def _fill_order(targets: list[Cell], occupied: set[Cell]) -> list[Cell] | None:
    """``targets`` (in build order) in an order in which each can be entered, the
    modules in ``occupied`` counted as staying (those that leave may still be
    there): peeled from the last one filled, the latest in build order first
    among those with three consecutive free sides; None if some never has."""
    remaining = set(targets)
    index = {c: i for i, c in enumerate(targets)}
    blocked = occupied | remaining
    heap = [(-index[c], c) for c in targets if _free_three(blocked, c)]
    heapq.heapify(heap)
    queued = {c for _, c in heap}
    peeled = []
    while heap:
        _, cell = heapq.heappop(heap)
        remaining.discard(cell)
        blocked.discard(cell)
        peeled.append(cell)
        x, y = cell
        for dx, dy in _AROUND:
            n = (x + dx, y + dy)
            if n in remaining and n not in queued and _free_three(blocked, n):
                heapq.heappush(heap, (-index[n], n))
                queued.add(n)
    return None if remaining else peeled[::-1]


def _hop(config: Configuration, start: Cell, end: Cell, width: int,
         deadline: Deadline) -> list[Move] | None:
    """Serial moves taking the strip at ``start`` to the one at the neighbouring
    anchor ``end``, in the strip's own order; None when it gets stuck.

    The cells to fill are filled in the build order of the new strip as far as
    each can then be entered (:func:`_fill_order`); each gets the module, among
    those that leave, whose first rotation lands nearest to it (one search
    outward from the cell), that is not a cut vertex (local test) and has a path
    (a search each). Cells that stay never move.
    The direct method did this before, with its general void-order test on
    every candidate void: most of the time of a strip route at 3,000 modules."""
    count = len(config)
    new_order = [end, *strip_cells(end, count, width)]
    new = set(new_order)
    old_order = [start, *strip_cells(start, count, width)]
    if set(old_order) != config.cells:
        return None
    occupied = set(config.cells)
    ids = {c: m.id for c, m in config.items()}
    leavers = [c for c in reversed(old_order) if c not in new]  # farthest first
    order = _fill_order([c for c in new_order if c not in occupied], occupied)
    if order is None:
        return None
    grid = StripGrid(occupied, order)
    moves: list[Move] = []
    for target in order:
        deadline.check("canonical strip")
        ranked = sorted((d, k, leavers[k]) for d, k in grid.nearest(leavers, target))
        for _, _k, cell in ranked:
            if stays_connected(occupied, cell):
                path = grid.path(cell, target)
                if path:
                    break
        else:
            return None
        leavers.remove(cell)
        module = ids.pop(cell)
        occupied.discard(cell)
        grid.put(cell, False)
        for src, dst, rule, sub in path:
            moves.append(new_move(module, src, dst, rule.joint, rule.direction, sub, ids[sub]))
        occupied.add(target)
        grid.put(target, True)
        ids[target] = module
    return moves


def _direct_hop(config: Configuration, start: Cell, hop: Cell, width: int,
                max_moves: int, deadline: Deadline) -> list[Move]:
    """The same hop by the direct method (one cell at a time when it stalls)."""
    try:
        return serial_moves(config, strip_shape(hop, len(config), width), max_moves,
                            deadline=deadline, method="canonical strip")
    except BudgetExhausted:
        raise
    except PlanningFailure:
        if distance(start, hop) <= 1:
            raise
    part, at = [], config
    for unit in _hop_anchors(start, hop, 1):
        piece = serial_moves(at, strip_shape(unit, len(config), width), max_moves,
                             deadline=deadline, method="canonical strip")
        part += piece
        at = replay(at, piece)
    return part


def shift_strip(config: Configuration, start: Cell, end: Cell, width: int,
                max_moves: int, deadline: Deadline = NO_DEADLINE) -> list[Move]:
    """Serial moves taking the strip anchored at ``start`` to the one at ``end``:
    unit hops (:func:`_hop`), each by the direct method when that gets stuck."""
    moves: list[Move] = []
    for hop in _hop_anchors(start, end):
        part = _hop(config, start, hop, width, deadline)
        if part is None:
            part = _direct_hop(config, start, hop, width, max_moves, deadline)
        moves += part
        if len(moves) > max_moves:
            raise PlanningFailure(f"more than {max_moves} moves needed")
        config = replay(config, part)
        start = hop
    return moves


def reversed_to_strip(goal: frozenset[Cell], strip: Configuration, width: int,
                      deadline: Deadline = NO_DEADLINE, turn: int = 0) -> list[Move]:
    """Serial moves from ``strip`` (the goal's strip, with real module ids) to ``goal``,
    given in the frame turned by ``turn`` (see :func:`to_strip`)."""
    provisional, backward = _gather_goal(goal, width, deadline, turn)
    return _ungather(provisional, backward, strip, turn)


def _gather_goal(goal: frozenset[Cell], width: int, deadline: Deadline,
                 turn: int) -> tuple[Configuration, list[Move]]:
    """The goal (provisional ids) and its gathering into its strip (moves turned
    by ``turn``): the first half of :func:`reversed_to_strip`."""
    provisional = Configuration.from_cells(goal, first_id=10**6)
    return provisional, to_strip(provisional, width, deadline, turn=turn)


def _ungather(provisional: Configuration, backward: list[Move], strip: Configuration,
              turn: int) -> list[Move]:
    """The gathering undone from ``strip``, with its real module ids (consumes
    ``backward``): the second half of :func:`reversed_to_strip`."""
    end = replay(_rotated(provisional, turn), backward)
    strip = _rotated(strip, turn)
    real = {end[c].id: strip[c].id for c in end}
    return undone(backward, real)


# (substrate dx, dy, goal dx, dy) from a mobile module -> the rotation (at most one)
_BY_OFFSETS = {(*rule.at((0, 0))[0], *rule.at((0, 0))[1]): rule for rule in ROTATIONS}


def undone(backward: list[Move], real: dict[int, int]) -> list[Move]:
    """``backward`` undone move by move, last first, its provisional module ids
    renamed by ``real``: each rotation is undone by the one from its end cell over
    the same substrate back to its start (``robust.reverse_move``, by a table).
    Consumes ``backward`` (empty afterwards)."""
    out = []
    while backward:  # consumed from its end: the two lists together hold one plan
        m = backward.pop()
        x, y = m.dst
        rule = _BY_OFFSETS.get((m.substrate[0] - x, m.substrate[1] - y,
                                m.src[0] - x, m.src[1] - y))
        if rule is None:
            raise ValueError(f"no rotation undoes {m}")
        out.append(new_move(real[m.module], m.dst, m.src, rule.joint, rule.direction,
                            m.substrate, real[m.substrate_module]))
    return out


def default_widths(count: int) -> list[int]:
    """Strip widths to try: about half the side of a square of ``count`` cells, then
    narrower; width 1 (a line) last."""
    wide = max(1, round(count ** 0.5 / 2))
    return sorted({wide, max(1, wide // 3), 1}, reverse=True)


def _rotated(config: Configuration, steps: int) -> Configuration:
    return Configuration({rotate_cell(c, steps): m for c, m in config.items()})


def _framer(steps: int):
    """Cell -> the same cell turned ``steps`` sixth-turns, one tuple per cell for a
    whole plan (millions of moves over a few thousand cells)."""
    turned: dict[Cell, Cell] = {}

    def turn(cell: Cell) -> Cell:
        out = turned.get(cell)
        if out is None:
            out = turned[cell] = rotate_cell(cell, steps)
        return out

    return turn


def _rotate_moves(moves: list[Move], steps: int) -> list[Move]:
    """The same rotations seen in a frame turned ``steps`` sixth-turns clockwise:
    cells turn, and joint ``j`` becomes joint ``j + steps`` (sides turn with them).
    In place (one copy of a long plan at a time); each cell is turned once and
    shared by the moves that use it."""
    if not steps % 6:
        return moves
    turn = _framer(steps)
    joints = {j: wrap(j + steps) for j in range(1, 7)}
    for i, m in enumerate(moves):
        moves[i] = new_move(m.module, turn(m.src), turn(m.dst), joints[m.joint],
                            m.direction, turn(m.substrate), m.substrate_module)
    return moves


def _via_strip_once(initial: Configuration, goal: frozenset[Cell], width: int,
                    max_moves: int, deadline: Deadline = NO_DEADLINE,
                    turn: int = 0) -> list[Move]:
    """initial -> strip -> goal's strip -> goal, the strips growing in the frame
    turned by ``turn``: the problem is turned, planned, and its moves turned back
    (the two gatherings, nearly all of the moves, make them turned back at once).

    The goal is gathered first: when a width or direction fails, it is mostly
    there (scrambled goals are ragged), and then the initial's gathering, as
    long, is not wasted (a 10,000-module scramble lost 17-20 s per failed try)."""
    turned = _rotated(initial, -turn)
    goal_turned = frozenset(rotate_cell(c, -turn) for c in goal)
    provisional, backward = _gather_goal(goal_turned, width, deadline, turn)
    first = to_strip(turned, width, deadline, turn=turn)
    at_strip = _rotated(replay(initial, first), -turn)
    shift = shift_strip(at_strip, anchor_of(turned.cells), anchor_of(goal_turned), width,
                        max_moves, deadline)
    at_goal_strip = replay(at_strip, shift)
    first += _rotate_moves(shift, turn)
    del shift
    first += _ungather(provisional, backward, at_goal_strip, turn)
    return first


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


def spine_to(cells: frozenset[Cell] | set[Cell], start: Cell, end: Cell) -> list[Cell]:
    """A shortest contact path of modules from ``start`` to ``end`` (both included)."""
    parent: dict[Cell, Cell | None] = {start: None}
    queue = deque([start])
    while queue:
        cell = queue.popleft()
        if cell == end:
            break
        for n in neighbors(cell):
            if n in cells and n not in parent:
                parent[n] = cell
                queue.append(n)
    if end not in parent:
        raise PlanningFailure(f"{end} is not connected to {start}")
    path = [end]
    while parent[path[-1]] is not None:
        path.append(parent[path[-1]])
    return path[::-1]


def to_fixed_strip(config: Configuration, fixed: Cell, turn: int, width: int,
                   deadline: Deadline = NO_DEADLINE) -> tuple[list[Move], int]:
    """Serial moves gathering ``config`` into the strip anchored at the ``fixed``
    module, which never moves, and the turn of the frame that strip grows in.

    A strip needs its anchor extreme, and the fixed module rarely is. So, in the
    frame turned by ``turn``: keep a spine, a shortest contact path from the fixed
    module to the extreme module, and gather everything else into the strip at the
    extreme module (:func:`to_strip` with ``keep``). What is left is the spine and
    the strip; turned half a turn, its extreme module lies on the spine (the strip
    is beyond the old anchor) and differs from the old anchor, so the next spine is
    a strictly shorter part of this one. Repeat, turning half a turn each time,
    until the extreme module is the fixed one: then the whole configuration is the
    strip at the fixed module. At most one stage per module of the first spine.
    """
    moves: list[Move] = []
    current = config
    stages = None
    while True:
        deadline.check("canonical strip")
        turned = _rotated(current, -turn)
        anchor = anchor_of(turned.cells)
        spine = spine_to(turned.cells, rotate_cell(fixed, -turn), anchor)
        stages = len(spine) if stages is None else stages - 1
        if stages < 1:  # cannot happen: each spine is shorter than the last
            raise PlanningFailure("the spine did not shrink")
        part = to_strip(turned, width, deadline, keep=spine, turn=turn)
        moves += part
        current = replay(current, part)
        if len(spine) == 1:
            return moves, turn
        turn = (turn + 3) % 6


def via_fixed_strip(initial: Configuration, goal: frozenset[Cell], fixed: Cell,
                    width: int, turn: int,
                    deadline: Deadline = NO_DEADLINE,
                    max_moves: int = MAX_MOVES) -> list[Move]:
    """initial -> strip at the fixed module -> goal, the fixed module never moving
    (:func:`to_fixed_strip` both ways; the two strips grow in the same frame or
    in opposite ones, and the fixed module is extreme in both, so one more
    gathering turns one into the other). Gives up as soon as the moves pass
    ``max_moves`` (each side of a 10,000-module pair takes half a minute)."""
    first, end_turn = to_fixed_strip(initial, fixed, turn, width, deadline)
    _within(len(first), max_moves)
    at = replay(initial, first)
    provisional = Configuration.from_cells(goal, first_id=10**6)
    backward, goal_turn = to_fixed_strip(provisional, fixed, turn, width, deadline)
    _within(len(first) + len(backward), max_moves)
    if goal_turn != end_turn:
        turn_over, _ = to_fixed_strip(at, fixed, goal_turn, width, deadline)
        first += turn_over
        at = replay(at, turn_over)
    end = replay(provisional, backward)
    if end.cells != at.cells:  # a bug, not a user error
        raise PlanningFailure("internal error: the two strips at the fixed module differ")
    real = {end[c].id: at[c].id for c in end}
    first += undone(backward, real)
    return first


def _within(count: int, max_moves: int) -> None:
    if count > max_moves:
        raise PlanningFailure(f"more than {max_moves} moves needed")


def via_strip(initial: Configuration, goal: frozenset[Cell], max_moves: int = MAX_MOVES,
              widths: list[int] | None = None, fixed: Cell | None = None,
              deadline: Deadline = NO_DEADLINE) -> list[Move]:
    """Serial moves initial -> strip -> goal's strip -> goal (raises PlanningFailure).

    Tries each width of ``widths`` (default :func:`default_widths`) with the strip
    growing in each of the six lattice directions (the whole problem is turned,
    planned, and its moves turned back), the directions ranked by
    :func:`strip_estimate`. With a ``fixed`` module (bolted to the base) the strip
    grows at that module (:func:`via_fixed_strip`).
    """
    failures = []
    turns = sorted(range(6), key=lambda t: (strip_estimate(initial.cells, goal, t), t))
    for width in widths or default_widths(len(initial)):
        for turn in turns:
            try:
                if fixed is not None:
                    moves = via_fixed_strip(initial, goal, fixed, width, turn, deadline,
                                            max_moves)
                    _within(len(moves), max_moves)
                    return moves
                moves = _via_strip_once(initial, goal, width, max_moves, deadline, turn)
            except BudgetExhausted:
                raise
            except PlanningFailure as exc:
                failures.append(f"width {width}, direction {turn}: {exc}")
                continue
            _within(len(moves), max_moves)
            return moves
    raise PlanningFailure("no canonical strip could be built (" + "; ".join(failures[:2])
                          + (f"; {len(failures) - 2} more" if len(failures) > 2 else "") + ")")
