"""Kernel flow: modules go from the cells to leave to the cells to fill,
next to a core of common modules that never moves.

1. **Kernel.** The common cells (in the start and in the goal) shrink until
   the start can be peeled down to them from the outside in (every other
   start cell can be left, three consecutive sides free, Table 4-3) and the
   goal too (every other goal cell can be entered); a stuck cell makes the
   kernel cells of its freest three-side window leave the kernel. The
   largest piece (the fixed module's) is the *core*; the kernel cells
   dropped for peeling *must leave* (their module goes, the cell is refilled).
2. **Fill next to the core.** A void is a target when it touches the core,
   can be entered now, and filling it walls in neither a void still to
   fill nor a module still to leave (both peels, compared with before). A
   filled target joins the core with the goal modules it touches, so no
   module of the core ever hangs on one that must leave.
3. **Chains.** A target is filled by a module that must leave, or, when none
   can roll there, by a goal module whose cell then becomes the void to fill
   (the thesis' void propagation), up to ``CHAIN_HOPS`` hops, cheapest first.
4. **When stuck:** a window fix (:func:`hexbot.planning.windows.fix_in_window`
   between assigned pairs), then a module that must leave parks off the goal
   away from the voids, then a core module next to a stuck cell leaves the
   core; each is bounded, and the method fails with the reason when none helps.

Every journey is searched with every other module fixed; a mover is never
a cut vertex, so each intermediate configuration is connected.
"""

from __future__ import annotations

import heapq
from collections import Counter, deque

from hexbot.planning.budget import PlanningFailure
from hexbot.planning.canonical import path_to
from hexbot.planning.configuration import contact_hops
from hexbot.planning.hexlattice import Cell, distance, neighbors
from hexbot.planning.robust import _free_run, _moves_from, fillable, is_cut, unwind
from hexbot.planning.surface import rolling_distances
from hexbot.planning.tracker import Tracker
from hexbot.planning.windows import PAIRS_TRIED, assigned_pairs, corridor, fix_in_window

#: Hops of a chain (goal modules passing the void on), chains searched per target,
#: targets tried per step, parks per module, core exits per cell.
CHAIN_HOPS = 10
CHAIN_NODES = 300
TARGETS_TRIED = 8
PARK_LIMIT = 3
LEAVE_CORE_LIMIT = 2
#: Window fixes when stuck: smaller than the window flow's own (they run often).
FIX_RADII = (1, 2)
FIX_STATES = 1000


def _freest_window(cell: Cell, kernel: set[Cell], stuck: set[Cell]) -> list[Cell]:
    """Kernel cells in the three consecutive sides of ``cell`` holding the fewest,
    among the sides clear of other stuck cells if any are (two stuck cells that
    block each other are freed by the kernel around them, not by each other)."""
    ring = neighbors(cell)
    windows = [[ring[(i + k) % 6] for k in range(3)] for i in range(6)]
    clear = [w for w in windows if not any(c in stuck for c in w)] or windows
    return min(([c for c in w if c in kernel] for w in clear), key=len)


def _largest_piece(cells: set[Cell], prefer: Cell | None) -> set[Cell]:
    if prefer is not None and prefer in cells:
        return set(contact_hops(cells, prefer))
    left, best = set(cells), set()
    while left:
        piece = set(contact_hops(left, min(left)))
        left -= piece
        if len(piece) > len(best) or (len(piece) == len(best) and min(piece) < min(best)):
            best = piece
    return best


def kernel(start: frozenset[Cell], goal: frozenset[Cell],
           fixed: Cell | None) -> tuple[set[Cell], set[Cell]]:
    """(core, must leave): see the module docstring, step 1."""
    common = set(start & goal)
    must: set[Cell] = set()
    while True:
        core = _largest_piece(common - must, fixed)
        drop: set[Cell] = set()
        for shape in (start, goal):
            stuck = fillable(shape, set(shape) - core)
            for cell in sorted(stuck):
                drop.update(_freest_window(cell, core, stuck))
        drop.discard(fixed)
        if not drop:
            return core, must
        must |= drop


def _enterable(occupied: set[Cell], cell: Cell) -> bool:
    blocked = {n for n in neighbors(cell) if n in occupied}
    return bool(blocked) and _free_run(blocked, cell)


def _applied(occupied: set[Cell], chain: list) -> set[Cell]:
    after = set(occupied)
    for start, path in chain:
        after.discard(start)
        after.add(path[-1][1])
    return after


class KernelFlow:
    def __init__(self, tracker: Tracker, goal: frozenset[Cell], fixed: Cell | None,
                 deadline, method: str = "local") -> None:
        self.t = tracker
        self.goal = goal
        self.fixed = fixed
        self.deadline = deadline
        self.method = method
        self.core, self.must = kernel(frozenset(tracker.occupied), goal, fixed)
        self.parked: Counter[Cell] = Counter()
        self.left_core: Counter[Cell] = Counter()
        self._absorb(sorted(self.core))

    # -- roles ------------------------------------------------------------
    def is_end(self, cell: Cell) -> bool:
        """The module on ``cell`` has to leave it."""
        return cell not in self.goal or cell in self.must

    def ends(self) -> set[Cell]:
        return {c for c in self.t.occupied if self.is_end(c)}

    # -- the loop -----------------------------------------------------------
    def run(self) -> None:
        while True:
            self.deadline.check(self.method)
            voids = set(self.goal - self.t.occupied)
            if not voids:
                return
            ends = self.ends()
            for target in self._targets(voids, ends)[:TARGETS_TRIED]:
                chain = self._chain(target)
                if chain:
                    for _, path in chain:
                        self.t.roll(path)
                    self.must.discard(chain[-1][0])
                    self.core.add(target)
                    self._absorb([target])
                    break
            else:
                if not (self._window_fix(ends, voids) or self._park(ends, voids)
                        or self._leave_core(ends, voids)):
                    raise PlanningFailure(
                        f"{self.method}: stuck with {len(voids)} goal cells to fill and "
                        f"{len(ends)} modules to move (no chain, window fix or park helps)")

    def _targets(self, voids: set[Cell], ends: set[Cell]) -> list[Cell]:
        occupied, goal, core = self.t.occupied, self.goal, self.core
        pending = set(goal) - core
        walled_voids = fillable(goal, pending)
        walled_ends: set[Cell] | None = None
        targets = []
        for v in sorted(voids):
            if not any(n in core for n in neighbors(v)) or not _enterable(occupied, v):
                continue
            if fillable(goal, pending - {v}) - walled_voids:
                continue
            if any(n in ends for n in neighbors(v)):
                if walled_ends is None:
                    walled_ends = fillable(frozenset(occupied), set(ends))
                if fillable(frozenset(occupied | {v}), ends - {v}) - walled_ends:
                    continue
            targets.append(v)
        if ends:
            targets.sort(key=lambda v: (min(distance(v, e) for e in ends), v))
        return targets

    def _chain(self, target: Cell) -> list | None:
        """[(start cell, path)] in order: goal modules passing the void on, last a
        module that must leave (cheapest in rotations first)."""
        heap = [(0, 0, target, [])]
        tie = nodes = 0
        while heap and nodes < CHAIN_NODES:
            cost, _, void, chain = heapq.heappop(heap)
            nodes += 1
            occupied = _applied(self.t.occupied, chain) if chain else self.t.occupied
            used = {s for s, _ in chain} | {p[-1][1] for _, p in chain}
            reach = rolling_distances(occupied, [void])
            guess: dict[Cell, int] = {}
            for cell in reach:
                for m in neighbors(cell):
                    if m in occupied and m != self.fixed and m not in used and m not in guess:
                        firsts = [reach[g] for _, _, g in _moves_from(m, occupied, m) if g in reach]
                        if firsts:
                            guess[m] = 1 + min(firsts)
            for _, m in sorted((g, m) for m, g in guess.items()):
                end = self.is_end(m)
                if (not end and len(chain) >= CHAIN_HOPS) or is_cut(occupied, m):
                    continue
                path = path_to(occupied, m, void)
                if not path:
                    continue
                if end:
                    return chain + [(m, path)]
                tie += 1
                heapq.heappush(heap, (cost + len(path), tie, m, chain + [(m, path)]))
        return None

    def _absorb(self, seeds: list[Cell]) -> None:
        """Goal modules touching the core join it, unless that walls in a void still
        to fill or a module still to leave."""
        occupied, goal = self.t.occupied, self.goal
        grow = list(seeds)
        while grow:
            cell = grow.pop()
            for n in neighbors(cell):
                if n not in goal or n not in occupied or n in self.core or n in self.must:
                    continue
                pending = set(goal) - self.core
                if fillable(goal, pending - {n}) - fillable(goal, pending):
                    continue
                ends = self.ends()
                if any(x in ends for x in neighbors(n)):
                    rest = ends | (pending & occupied) - {n}
                    shape = frozenset(occupied)
                    if fillable(shape, rest) - fillable(shape, rest | {n}):
                        continue
                self.core.add(n)
                grow.append(n)

    def _window_fix(self, ends: set[Cell], voids: set[Cell]) -> bool:
        for radius in FIX_RADII:
            for _, end, void in assigned_pairs(ends, voids)[:PAIRS_TRIED]:
                self.deadline.check(self.method)  # a search can take a while
                window = corridor(end, void, radius)
                hops = window and fix_in_window(self.t.occupied, self.goal, window,
                                                self.fixed, FIX_STATES)
                if hops:
                    self.t.roll(hops)
                    for src, _, _, _ in hops:
                        self.core.discard(src)
                        self.must.discard(src)
                    self.core &= self.t.occupied
                    self._absorb(sorted(self.core))
                    return True
        return False

    def _park(self, ends: set[Cell], voids: set[Cell]) -> bool:
        """A module that must leave goes off the goal, two cells clear of every void
        (modules blocking a void of the core's border first)."""
        border_voids = [v for v in sorted(voids) if any(n in self.core for n in neighbors(v))]
        first = sorted({m for v in border_voids for m in neighbors(v) if m in ends})
        for m in first + sorted(ends - set(first)):
            if m == self.fixed or self.parked[m] >= PARK_LIMIT or is_cut(self.t.occupied, m):
                continue
            path = self._park_path(m, voids)
            if path:
                self.t.roll(path)
                dst = path[-1][1]
                self.parked[dst] = self.parked.pop(m, 0) + 1
                self.must.discard(m)
                return True
        return False

    def _park_path(self, start: Cell, voids: set[Cell]) -> list | None:
        parent: dict = {start: None}
        queue = deque([start])
        while queue:
            cell = queue.popleft()
            for rule, sub, dst in _moves_from(cell, self.t.occupied, start):
                if dst in parent:
                    continue
                parent[dst] = (cell, rule, sub)
                if dst not in self.goal and all(distance(dst, v) > 2 for v in voids):
                    return unwind(parent, dst)
                queue.append(dst)
        return None

    def _leave_core(self, ends: set[Cell], voids: set[Cell]) -> bool:
        """A core module next to a stuck cell leaves the core (it must leave now)."""
        occupied = self.t.occupied
        near = sorted({n for x in sorted(ends) + sorted(voids) for n in neighbors(x)
                       if n in self.core and n != self.fixed
                       and self.left_core[n] < LEAVE_CORE_LIMIT})
        for cell in near:
            if is_cut(occupied, cell) or not any(True for _ in _moves_from(cell, occupied, cell)):
                continue
            self.core.discard(cell)
            self.must.add(cell)
            self.left_core[cell] += 1
            return True
        return False


def kernel_flow(tracker: Tracker, goal: frozenset[Cell], fixed: Cell | None, deadline,
                method: str = "local") -> None:
    KernelFlow(tracker, goal, fixed, deadline, method).run()
