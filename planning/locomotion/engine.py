"""Synchronous rule engine for square-lattice locomotion.

Each round every module looks at the same snapshot, picks the
highest-priority rule variant whose precondition holds (at most one), and then
all chosen actions apply together. Before applying, the round is checked:
targets must be empty, slides and convex transitions must be carried by
cells that do not move this round, and no cell may be entered (or swept) by
two modules. After applying, the robot must still be connected. The first
broken invariant stops the run with a `Violation`.

Data layout: the lattice is one int16 array indexed ``[x, y]`` (0 empty,
1 obstacle, 2 + s a module in state s), used through its flat view; modules
are flat cell indices. Preconditions compile to numpy gathers over the flat
view, so a round costs a handful of array operations, not a Python loop per
module. The array grows (obstacles replicated from the edge, so floors and
walls continue) whenever a module comes near its border.
"""

from __future__ import annotations

import hashlib
from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from hexbot.errors import ScenarioError
from hexbot.planning.locomotion import connectivity
from hexbot.planning.locomotion.rules import (
    EMPTY,
    LOOP_RADIUS,
    LOOPED,
    MODULE,
    OBSTACLE,
    SIMPLE,
    And,
    Atom,
    Expr,
    Not,
    Or,
    RuleSet,
    Variant,
    rotate,
)

Cell = tuple[int, int]
EMPTY_CODE, OBSTACLE_CODE, MODULE_BASE = 0, 1, 2
# How a `looped` path may pass a module (Engine._loop_through).
LOOP_NEVER, LOOP_ALWAYS, LOOP_UNLESS_SIMPLE, LOOP_AHEAD = 0, 1, 2, 3


def _needs_simple(v: Variant) -> bool:
    """Whether the variant asks `simple` of the module itself, unconditionally."""
    parts = [a for c in v.conditions for a in (c.args if isinstance(c, And) else (c,))]
    return any(isinstance(a, Atom) and SIMPLE in a.classes and not a.negated
               and a.offset == (0, 0) for a in parts)


@dataclass
class Violation:
    """An invariant broke: which round, where, and which rules did it."""

    round: int
    kind: str  # collision | target-occupied | inside-obstacle | unsupported-move | disconnected
    cells: list[Cell]
    rules: list[str]
    message: str

    def to_dict(self) -> dict:
        return {
            "round": self.round,
            "kind": self.kind,
            "cells": [list(c) for c in self.cells],
            "rules": self.rules,
            "message": self.message,
        }


@dataclass
class Deadlock:
    """No rule fired in a round and the goal was not reached, or the whole
    configuration came back to an earlier one (a livelock: the run would
    repeat for ever without reaching the goal)."""

    round: int
    moving_states: dict[str, int]  # modules per non-resting state
    message: str
    repeats_round: int | None = None  # livelock: the earlier round it equals

    def to_dict(self) -> dict:
        out = {"round": self.round, "states": self.moving_states, "message": self.message}
        if self.repeats_round is not None:
            out["repeats_round"] = self.repeats_round
        return out


@dataclass
class Goal:
    """When a run is done. ``advance``: k modules came to rest in new cells;
    ``beyond``: every module is past the obstacle, (position . direction) > threshold."""

    advance: int | None = None
    direction: Cell | None = None
    threshold: int | None = None

    def reached_beyond(self, xy: np.ndarray) -> bool:
        if self.direction is None or self.threshold is None:
            return False
        prog = xy[:, 0] * self.direction[0] + xy[:, 1] * self.direction[1]
        return bool((prog > self.threshold).all())


@dataclass
class RunResult:
    status: str  # advanced | reached | rounds-exhausted | deadlock | violation
    rounds: int
    advanced: int
    moves_per_module: list[int]
    advance_rounds: list[int]  # advance_rounds[k-1] = round when advance reached k
    violation: Violation | None = None
    deadlock: Deadlock | None = None
    positions: list[Cell] = field(default_factory=list)
    states: list[str] = field(default_factory=list)
    obstacles: list[Cell] = field(default_factory=list)
    rule_counts: dict[str, int] = field(default_factory=dict)

    def to_dict(self, final_state: bool = True) -> dict:
        out: dict = {
            "status": self.status,
            "rounds": self.rounds,
            "advanced": self.advanced,
            "moves_per_module": self.moves_per_module,
            "total_moves": int(sum(self.moves_per_module)),
            "rule_counts": self.rule_counts,
        }
        if self.violation:
            out["violation"] = self.violation.to_dict()
        if self.deadlock:
            out["deadlock"] = self.deadlock.to_dict()
        if final_state:
            pairs = zip(self.positions, self.states, strict=True)
            out["final"] = {"modules": [[x, y, s] for (x, y), s in pairs]}
        return out


class World:
    """The lattice, the modules and their bookkeeping arrays."""

    def __init__(
        self,
        obstacles: list[Cell],
        modules: list[Cell],
        states: list[str],
        module_states: list[str] | None = None,
        margin: int = 4,
        extend_axis: int | None = 0,
    ):
        if not modules:
            raise ScenarioError("a scenario needs at least one module")
        obs = set(obstacles)
        clash = [m for m in modules if m in obs]
        if clash:
            raise ScenarioError(f"module inside an obstacle at {clash[0]}")
        if len(set(modules)) != len(modules):
            raise ScenarioError("two modules in one cell")
        self.state_names = list(states)
        # Obstacles at the ends of this axis (x: 0, y: 1) continue without end:
        # floors (and walls, for rotated scenarios) never run out.
        self.extend_axis = extend_axis
        pts = list(obs) + list(modules)
        xs = [p[0] for p in pts]
        ys = [p[1] for p in pts]
        x0, y0 = min(xs) - margin, min(ys) - margin
        w, h = max(xs) - x0 + margin + 1, max(ys) - y0 + margin + 1
        self.ox, self.oy = -x0, -y0
        self.grid = np.zeros((w, h), dtype=np.int16)
        for x, y in obs:
            self.grid[x + self.ox, y + self.oy] = OBSTACLE_CODE
        if obs and extend_axis is not None:
            g = np.moveaxis(self.grid, extend_axis, 0)  # a view: writes go to grid
            idx = [p[extend_axis] + (self.ox, self.oy)[extend_axis] for p in obs]
            lo, hi = min(idx), max(idx)
            g[:lo] = g[lo]
            g[hi + 1 :] = g[hi]
        init = module_states or [states[0]] * len(modules)
        self.state = np.array([states.index(s) for s in init], dtype=np.int16)
        self.pos = np.array(
            [(x + self.ox) * h + (y + self.oy) for x, y in modules], dtype=np.int64
        )
        self.flat.reshape(-1)[self.pos] = MODULE_BASE + self.state
        self.initial = np.zeros((w, h), dtype=bool)
        self.initial.reshape(-1)[self.pos] = True
        self.counted = np.zeros((w, h), dtype=bool)

    @property
    def height(self) -> int:
        return self.grid.shape[1]

    @property
    def flat(self) -> np.ndarray:
        return self.grid.reshape(-1)

    def xy(self, cells: np.ndarray | None = None) -> np.ndarray:
        cells = self.pos if cells is None else cells
        return np.stack([cells // self.height - self.ox, cells % self.height - self.oy], axis=1)

    def cell_list(self, cells: np.ndarray) -> list[Cell]:
        return [(int(x), int(y)) for x, y in self.xy(np.asarray(cells, dtype=np.int64))]

    def needs_room(self, cells: np.ndarray, reach: int) -> bool:
        w, h = self.grid.shape
        x, y = cells // h, cells % h
        lo = reach + 1
        return bool(
            (x < lo).any() or (y < lo).any() or (x >= w - lo).any() or (y >= h - lo).any()
        )

    def grow(self, reach: int) -> None:
        """Enlarge the array on every crowded side; obstacles continue from the edge."""
        w, h = self.grid.shape
        x, y = self.pos // h, self.pos % h
        want = max(2 * reach + 2, 16)
        pad = (
            (want if x.min() <= reach + 1 else 0, want if x.max() >= w - reach - 2 else 0),
            (want if y.min() <= reach + 1 else 0, want if y.max() >= h - reach - 2 else 0),
        )
        obstacles = self.grid == OBSTACLE_CODE
        for axis in (0, 1):
            along = [(0, 0), (0, 0)]
            along[axis] = pad[axis]
            mode = "edge" if axis == self.extend_axis else "constant"
            obstacles = np.pad(obstacles, along, mode=mode)
        new = np.where(obstacles, OBSTACLE_CODE, EMPTY_CODE).astype(np.int16)
        sl = (slice(pad[0][0], pad[0][0] + w), slice(pad[1][0], pad[1][0] + h))
        new[sl] = self.grid
        self.grid = new
        self.initial = np.pad(self.initial, pad)
        self.counted = np.pad(self.counted, pad)
        self.ox += pad[0][0]
        self.oy += pad[1][0]
        nh = self.grid.shape[1]
        self.pos = (x + pad[0][0]) * nh + (y + pad[1][0])


Check = Callable[[np.ndarray], np.ndarray]


class Engine:
    """Runs one rule set on one world, round by round."""

    def __init__(
        self,
        ruleset: RuleSet,
        world: World,
        check_connectivity: bool = True,
        frame: int = 0,
    ):
        self.rs = ruleset
        self.world = world
        self.check_connectivity = check_connectivity
        self.nstates = len(ruleset.states)
        if world.state_names != ruleset.states:
            raise ScenarioError("world and rule set disagree on the states")
        self.variants: list[Variant] = ruleset.ordered_variants(frame)
        self.flow = rotate((1, 0), frame)  # the scenario's direction of travel
        self.loop_through = self._loop_through()
        self.reach = ruleset.reach()
        self.round = 0
        self.moves = np.zeros(world.pos.size, dtype=np.int64)
        self.advanced = 0
        self.advance_rounds: list[int] = []
        self.rule_counts = np.zeros(len(self.variants), dtype=np.int64)
        self._luts: dict[tuple[frozenset[str], bool], np.ndarray] = {}
        self.resting_lut = np.array([s in ruleset.resting for s in ruleset.states], dtype=bool)
        self.support_lut = self._lut(frozenset(ruleset.support))
        self.become = np.array(
            [ruleset.states.index(v.become) if v.become else -1 for v in self.variants],
            dtype=np.int16,
        )
        self.has_move = np.array([v.move is not None for v in self.variants], dtype=bool)
        self.move_xy = np.array([v.move or (0, 0) for v in self.variants], dtype=np.int64)
        if world.needs_room(world.pos, self.reach):
            world.grow(self.reach)
        self._compile()
        if check_connectivity and not connectivity.connected(
            world.flat, world.height, world.pos
        ):
            raise ScenarioError("the initial robot is not connected")

    # --- compilation ----------------------------------------------------

    def _lut(self, classes: frozenset[str]) -> np.ndarray:
        lut = np.zeros(MODULE_BASE + self.nstates, dtype=bool)
        for c in classes:
            if c == EMPTY:
                lut[EMPTY_CODE] = True
            elif c == OBSTACLE:
                lut[OBSTACLE_CODE] = True
            elif c == MODULE:
                lut[MODULE_BASE:] = True
            else:
                lut[MODULE_BASE + self.rs.states.index(c)] = True
        return lut

    def _atom_lut(self, atom: Atom) -> np.ndarray:
        key = (atom.classes, atom.negated)
        if key not in self._luts:
            lut = self._lut(atom.classes)
            self._luts[key] = ~lut if atom.negated else lut
        return self._luts[key]

    def _expr(self, e: Expr) -> Check:
        flat, h = self.world.flat, self.world.height
        if isinstance(e, Atom) and LOOPED in e.classes:
            looped, negated = self._looped, e.negated
            at = e.offset[0] * h + e.offset[1]
            return lambda p: ~looped(p + at) if negated else looped(p + at)
        if isinstance(e, Atom) and SIMPLE in e.classes:
            simple, negated = self._simple, e.negated
            at = e.offset[0] * h + e.offset[1]
            return lambda p: ~simple(p + at) if negated else simple(p + at)
        if isinstance(e, Atom):
            lut, off = self._atom_lut(e), e.offset[0] * h + e.offset[1]
            return lambda p: lut[flat[p + off]]
        if isinstance(e, Not):
            inner = self._expr(e.arg)
            return lambda p: ~inner(p)
        parts = [self._expr(a) for a in e.args]
        if isinstance(e, And):
            def conj(p: np.ndarray) -> np.ndarray:
                out = parts[0](p)
                for f in parts[1:]:
                    out &= f(p)
                return out
            return conj
        assert isinstance(e, Or)

        def disj(p: np.ndarray) -> np.ndarray:
            out = parts[0](p)
            for f in parts[1:]:
                out |= f(p)
            return out
        return disj

    def _simple(self, cells: np.ndarray) -> np.ndarray:
        """`simple` at each cell: its occupied ring cells form one run holding
        all its edge neighbours (a module there can leave without a local cut)."""
        h = self.world.height
        occupied = self.world.flat[cells[:, None] + connectivity.ring_offsets(h)[None, :]]
        weights = (1 << np.arange(8)).astype(np.int64)
        return connectivity.SIMPLE[(occupied >= MODULE_BASE).astype(np.int64) @ weights]

    def _loop_through(self) -> np.ndarray:
        """Per cell code, how a `looped` path may use a module in that state:
        ALWAYS (resting, never moves), UNLESS_SIMPLE (resting, every move of
        the state needs `simple`), AHEAD (resting and may leave on a cycle:
        only a module ahead of us in the flow), or NEVER (not resting)."""
        use = np.full(MODULE_BASE + self.nstates, LOOP_NEVER, dtype=np.int8)
        for s, name in enumerate(self.rs.states):
            if name not in self.rs.resting:
                continue
            moves = [v for v in self.variants if v.rule.state == name and v.move is not None]
            if not moves:
                use[MODULE_BASE + s] = LOOP_ALWAYS
            elif all(_needs_simple(v) for v in moves):
                use[MODULE_BASE + s] = LOOP_UNLESS_SIMPLE
            else:
                use[MODULE_BASE + s] = LOOP_AHEAD
        return use

    def _looped(self, p: np.ndarray) -> np.ndarray:
        """`looped`: the module's edge neighbours stay joined without it, within
        LOOP_RADIUS, through modules that cannot leave in this round: modules
        that never move, stoppers that move only when `simple` and are not, and
        stoppers that may leave on a cycle only when they are *ahead* of us in
        the flow (the scenario's direction, then its left). Of two openers on
        one cycle only the one behind, which may count the other, leaves: the
        cycle is opened once (without the order three openers of one ring left
        together and split it). A search per candidate: the rules put it last."""
        flat, h = self.world.flat, self.world.height
        use = self.loop_through
        fx, fy = self.flow
        edges = (h, 1, -h, -1)
        out = np.zeros(p.size, dtype=bool)
        for i, c in enumerate(p.tolist()):
            cx, cy = divmod(c, h)
            key = (fx * cx + fy * cy, -fy * cx + fx * cy)

            def usable(r: int, key: tuple[int, int] = key) -> bool:
                how = use[flat[r]]
                if how == LOOP_ALWAYS:
                    return True
                if how == LOOP_NEVER:
                    return False
                if how == LOOP_UNLESS_SIMPLE:  # pinned unless `simple`
                    return not self._simple(np.array([r]))[0]
                rx, ry = divmod(r, h)
                return (fx * rx + fy * ry, -fy * rx + fx * ry) > key

            ends = [c + d for d in edges if flat[c + d] >= MODULE_BASE]
            if use[flat[c]] == LOOP_NEVER or len(ends) < 2 or not all(map(usable, ends)):
                continue
            seen, todo = {c, ends[0]}, [ends[0]]
            while todo:
                q = todo.pop()
                for d in edges:
                    r = q + d
                    if r in seen or flat[r] < MODULE_BASE:
                        continue
                    rx, ry = divmod(r, h)
                    if abs(rx - cx) > LOOP_RADIUS or abs(ry - cy) > LOOP_RADIUS:
                        continue
                    if not usable(r):
                        continue
                    seen.add(r)
                    todo.append(r)
            out[i] = all(n in seen for n in ends[1:])
        return out

    def _compile(self) -> None:
        """Per state, the variants that apply to it, as lists of filters.

        A variant whose first condition asks a cell for module states (``W is
        HEADD``) also gets an *anchor*: when those states are rarer than the
        modules to test, the candidates are found from the anchor modules
        (each one names the module it could serve) instead of testing all."""
        self.by_state: list[list[tuple[int, list[Check], tuple | None]]] = [
            [] for _ in range(self.nstates)
        ]
        h = self.world.height
        for vid, v in enumerate(self.variants):
            parts: list[Expr] = []
            for c in v.conditions:  # top-level 'and' splits into filters: cheaper
                parts.extend(c.args if isinstance(c, And) else (c,))
            filters = [self._expr(part) for part in parts]
            anchor = None
            first = parts[0] if parts else None
            if (isinstance(first, Atom) and not first.negated and SIMPLE not in first.classes
                    and first.classes <= set(self.rs.states)):
                ids = tuple(sorted(self.rs.states.index(c) for c in first.classes))
                anchor = (ids, first.offset[0] * h + first.offset[1])
            self.by_state[self.rs.states.index(v.rule.state)].append((vid, filters, anchor))
        self.move_off = self.move_xy[:, 0] * h + self.move_xy[:, 1]

    # --- one round --------------------------------------------------------------

    def decide(self) -> np.ndarray:
        """Variant id chosen by each module on the current snapshot, -1 for none."""
        w = self.world
        chosen = np.full(w.pos.size, -1, dtype=np.int64)
        counts = np.bincount(w.state, minlength=self.nstates)
        members: dict[tuple[int, ...], np.ndarray] = {}
        rare: dict[tuple[int, ...], int] = {}  # how many modules are in these states
        who: np.ndarray | None = None  # module index by flat cell, built on demand
        for s in range(self.nstates):
            idx = np.flatnonzero(w.state == s)
            for vid, filters, anchor in self.by_state[s]:
                if idx.size == 0:
                    break
                todo = filters
                if anchor is not None:
                    ids, off = anchor
                    if ids not in rare:
                        rare[ids] = int(counts[list(ids)].sum())
                if anchor is not None and rare[ids] < idx.size:
                    if ids not in members:
                        members[ids] = np.flatnonzero(np.isin(w.state, ids))
                    if who is None:
                        who = np.full(w.flat.size, -1, dtype=np.int64)
                        who[w.pos] = np.arange(w.pos.size)
                    cand = who[w.pos[members[ids]] - off]
                    cand = cand[cand >= 0]
                    cand = cand[(w.state[cand] == s) & (chosen[cand] < 0)]
                    todo = filters[1:]  # the anchor test holds by construction
                else:
                    cand = idx
                sel = np.arange(cand.size)
                p = w.pos[cand]
                for f in todo:
                    if sel.size == 0:
                        break
                    keep = f(p)
                    sel, p = sel[keep], p[keep]
                if sel.size:
                    chosen[cand[sel]] = vid
                    idx = idx[chosen[idx] < 0]
        return chosen

    def _labels(self, chosen: np.ndarray, movers: np.ndarray) -> list[str]:
        return sorted({self.variants[int(chosen[m])].label for m in movers})

    def _violation(self, kind: str, cells: np.ndarray, chosen, movers, message: str) -> Violation:
        cell_list = sorted(set(self.world.cell_list(cells)))
        return Violation(self.round, kind, cell_list, self._labels(chosen, movers), message)

    def check_moves(
        self, chosen: np.ndarray, mv: np.ndarray
    ) -> tuple[np.ndarray, Violation | None]:
        """Target cells of the movers ``mv``, or the first broken move invariant."""
        w = self.world
        flat, h = w.flat, w.height
        a = w.pos[mv]
        d = self.move_xy[chosen[mv]]
        b = a + self.move_off[chosen[mv]]
        occ = flat[b]
        if (occ == OBSTACLE_CODE).any():
            bad = np.flatnonzero(occ == OBSTACLE_CODE)
            return b, self._violation(
                "inside-obstacle", np.concatenate([a[bad], b[bad]]), chosen, mv[bad],
                "a module would move into an obstacle cell",
            )
        if (occ != EMPTY_CODE).any():
            bad = np.flatnonzero(occ != EMPTY_CODE)
            return b, self._violation(
                "target-occupied", np.concatenate([a[bad], b[bad]]), chosen, mv[bad],
                "a module would move into a cell occupied at the start of the round",
            )
        moving = np.zeros(flat.size, dtype=bool)
        moving[a] = True

        def carrier(c: np.ndarray) -> np.ndarray:
            return self.support_lut[flat[c]] & ~moving[c]

        slide = (d[:, 0] == 0) | (d[:, 1] == 0)
        swept = np.full(mv.size, -1, dtype=np.int64)
        ok = np.ones(mv.size, dtype=bool)
        if slide.any():
            ia = np.flatnonzero(slide)
            dd = d[ia]
            side = -dd[:, 1] * h + dd[:, 0]  # a perpendicular neighbour
            step = b[ia] - a[ia]
            left = carrier(a[ia] + side) & carrier(a[ia] + side + step)
            right = carrier(a[ia] - side) & carrier(a[ia] - side + step)
            ok[ia] = left | right
        if (~slide).any():
            ic = np.flatnonzero(~slide)
            vert = a[ic] + d[ic, 1]  # (0, dy)
            horiz = a[ic] + d[ic, 0] * h  # (dx, 0)
            via_horiz = carrier(vert) & (flat[horiz] == EMPTY_CODE)  # pivot below/above
            via_vert = carrier(horiz) & (flat[vert] == EMPTY_CODE)  # pivot beside
            ok[ic] = via_horiz | via_vert
            swept[ic] = np.where(via_horiz, horiz, vert)
        if not ok.all():
            bad = np.flatnonzero(~ok)
            return b, self._violation(
                "unsupported-move", np.concatenate([a[bad], b[bad]]), chosen, mv[bad],
                "a slide or convex transition has no carrying module that stays put",
            )
        claims = np.concatenate([b, swept[swept >= 0]])
        owners = np.concatenate([np.arange(mv.size), np.flatnonzero(swept >= 0)])
        uniq, counts = np.unique(claims, return_counts=True)
        if (counts > 1).any():
            dup = uniq[counts > 1]
            who = mv[owners[np.isin(claims, dup)]]
            return b, self._violation(
                "collision", np.concatenate([dup, w.pos[who]]), chosen, who,
                "two modules would enter or sweep the same cell",
            )
        return b, None

    def step(self) -> tuple[bool, Violation | None]:
        """Run one round. Returns (something happened, violation or None)."""
        self.round += 1
        w = self.world
        chosen = self.decide()
        acting = np.flatnonzero(chosen >= 0)
        if acting.size == 0:
            return False, None
        np.add.at(self.rule_counts, chosen[acting], 1)
        mv = acting[self.has_move[chosen[acting]]]
        targets = np.empty(0, dtype=np.int64)
        if mv.size:
            targets, bad = self.check_moves(chosen, mv)
            if bad:
                return True, bad
        new_state = self.become[chosen[acting]]
        changed = acting[new_state >= 0]
        w.state[changed] = new_state[new_state >= 0]
        flat = w.flat
        vacated = w.pos[mv]
        flat[vacated] = EMPTY_CODE
        w.pos[mv] = targets
        self.moves[mv] += 1
        flat[w.pos[acting]] = MODULE_BASE + w.state[acting]
        if mv.size and self.check_connectivity:
            if not connectivity.certify(flat, w.height, vacated, targets) and not (
                connectivity.connected(flat, w.height, w.pos)
            ):
                pieces = connectivity.components(flat, w.height, w.pos)
                small = np.array([c for p in pieces[1:] for c in p], dtype=np.int64)
                return True, self._violation(
                    "disconnected", small, chosen, mv,
                    f"the robot split into {len(pieces)} pieces; cells of the smaller ones",
                )
        self._count_advance(acting)
        if mv.size and w.needs_room(targets, self.reach):
            w.grow(self.reach)
            self._compile()
        return True, None

    def _count_advance(self, acting: np.ndarray) -> None:
        """Cells outside the initial robot where a module came to rest, counted once."""
        w = self.world
        rest = acting[self.resting_lut[w.state[acting]]]
        if rest.size == 0:
            return
        cells = w.pos[rest]
        fresh = cells[~w.initial.reshape(-1)[cells] & ~w.counted.reshape(-1)[cells]]
        if fresh.size:
            w.counted.reshape(-1)[fresh] = True
            for _ in range(fresh.size):
                self.advanced += 1
                self.advance_rounds.append(self.round)

    # --- a whole run ------------------------------------------------------------

    def run(
        self,
        max_rounds: int,
        goal: Goal | None = None,
        on_round: Callable[[Engine], None] | None = None,
    ) -> RunResult:
        goal = goal or Goal()
        status, violation, deadlock = "rounds-exhausted", None, None
        w = self.world
        seen: dict[bytes, int] = {self._fingerprint(): self.round}
        if on_round:
            on_round(self)
        while self.round < max_rounds:
            acted, violation = self.step()
            if violation:
                status = "violation"
                break
            if not acted:
                self.round -= 1  # the empty round is not counted
                if goal.reached_beyond(w.xy()):
                    status = "reached"
                    break
                status = "deadlock"
                deadlock = self._deadlock_report()
                break
            if on_round:
                on_round(self)
            if goal.advance is not None and self.advanced >= goal.advance:
                status = "advanced"
                break
            if goal.reached_beyond(w.xy()):
                status = "reached"
                break
            key = self._fingerprint()
            if key in seen:
                status = "deadlock"
                deadlock = self._deadlock_report(repeats=seen[key])
                break
            seen[key] = self.round
        return self.result(status, violation, deadlock)

    def _fingerprint(self) -> bytes:
        """Digest of the configuration: positions (with the lattice's origin
        and shape, which give them meaning) and states."""
        w = self.world
        h = hashlib.blake2b(digest_size=16)
        h.update(np.array([w.ox, w.oy, *w.grid.shape], dtype=np.int64).tobytes())
        h.update(w.pos.tobytes())
        h.update(w.state.tobytes())
        return h.digest()

    def _deadlock_report(self, repeats: int | None = None) -> Deadlock:
        w = self.world
        counts: dict[str, int] = {}
        for s in w.state.tolist():
            name = self.rs.states[s]
            if name not in self.rs.resting:
                counts[name] = counts.get(name, 0) + 1
        if repeats is not None:
            return Deadlock(
                self.round,
                counts,
                f"livelock: round {self.round} repeats the configuration of round {repeats}",
                repeats_round=repeats,
            )
        return Deadlock(
            self.round + 1,
            counts,
            f"no rule fires in round {self.round + 1} and the goal is not reached",
        )

    def result(self, status: str, violation=None, deadlock=None) -> RunResult:
        w = self.world
        obst = np.argwhere(w.grid == OBSTACLE_CODE)
        counts: dict[str, int] = {}
        for v, n in zip(self.variants, self.rule_counts.tolist(), strict=True):
            if n:
                counts[v.rule.label] = counts.get(v.rule.label, 0) + n
        return RunResult(
            status=status,
            rounds=self.round,
            advanced=self.advanced,
            moves_per_module=self.moves.tolist(),
            advance_rounds=list(self.advance_rounds),
            violation=violation,
            deadlock=deadlock,
            positions=w.cell_list(w.pos),
            states=[self.rs.states[s] for s in w.state.tolist()],
            obstacles=[(int(x) - w.ox, int(y) - w.oy) for x, y in obst],
            rule_counts=counts,
        )
