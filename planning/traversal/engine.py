"""MOVEMODULE (Fig. 10) for every module, in synchronous rounds, with the
invariants checked every round.

Each module knows only the map, the bridge map computed from it, ``n``, its
own cell and memory, and which of its six neighbour cells are occupied
(now and in the last round or two: a cell that changed means a module in
motion). No messages. Per round, every module decides from the state at the
start of the round; the engine then checks all decided moves together and
applies them. A broken invariant stops the run with the round, the modules and the
rule that moved them.

Decisions the paper leaves open (docs/traversal.md, "MOVEMODULE"):
- a module may start, or leave a Bridge or Support cell, when none of its
  neighbour cells changed in the last round; this yields the 2-cell spacing
  (under the hexbot model the last two rounds: a 3-cell spacing, since a
  rigid rotation sweeps a cell two away);
- under the hexbot model a module whose way, where it folds back on itself,
  would cross the way of a module ahead in the same round holds back its
  start by the fewest rounds that avoid it (:func:`start_holds`, computed
  from the map as the bridge map is: the modules ahead are where the map and
  this same rule put them); the module ahead always goes first;
- a Bridge module counts the modules that pass as the entries into the last
  cell next to it on the way over the bridge (``Group.pass_cells``);
- a module leaving a Bridge cell never enters the pocket it closed;
- a module that reaches a goal cell stops when the next goal cell is
  occupied or when it is the last one.
"""

from __future__ import annotations

import dataclasses
import sys
from dataclasses import dataclass, field
from typing import Any

from hexbot.planning.traversal.bridges import BridgeMap, Group
from hexbot.planning.traversal.motion import (
    Rolled,
    body_cells,
    next_rotation,
    required_empty,
)
from hexbot.protocol.lattice import SIDE_OFFSETS, SIDES, Cell

STATUSES = ("reached", "deadlock", "violation")
_OFFSETS = tuple(SIDE_OFFSETS[s] for s in SIDES)  # a cell's neighbours: (x + dx, y + dy)
_NEXT_TO = frozenset(_OFFSETS)


def _next_to(a: Cell, b: Cell) -> bool:
    """``distance(a, b) == 1``."""
    return (b[0] - a[0], b[1] - a[1]) in _NEXT_TO


@dataclass
class Module:
    ident: int
    cell: Cell
    pivot: Cell
    phase: str = "chain"  # chain moving bridge resume temp to-support support done
    direction: str = "CW"
    group: Group | None = None
    count: int = 0
    served: set[int] = field(default_factory=set)  # id() of groups served
    avoid: set[Cell] = field(default_factory=set)
    rule: str = "start"  # the part of MOVEMODULE that made its last move
    deferred: int = 0  # rounds it could have started and did not (its start hold)
    resume_rule: str = ""
    to_support_rule: str = ""


@dataclass
class MoveRecord:
    module: int
    src: Cell
    dst: Cell
    substrate: Cell
    substrate_module: int | None  # None: a surface cell
    joint: int
    direction: str
    rule: str

    def as_json(self) -> dict[str, Any]:
        return {"module": self.module, "from": list(self.src), "to": list(self.dst),
                "joint": self.joint, "direction": self.direction,
                "substrate": list(self.substrate), "rule": self.rule}


@dataclass
class Violation:
    round: int
    invariant: str
    modules: list[int]
    rules: list[str]
    detail: str

    def as_json(self) -> dict[str, Any]:
        return {"round": self.round, "invariant": self.invariant, "modules": self.modules,
                "rules": self.rules, "detail": self.detail}

    def describe(self) -> str:
        return (f"round {self.round}: {self.invariant}: modules {self.modules} "
                f"(rules {', '.join(self.rules)}): {self.detail}")


@dataclass
class Result:
    status: str
    rounds: list[list[MoveRecord]]
    final: dict[int, Cell]
    violation: Violation | None = None
    reason: str = ""
    initial: dict[int, Cell] = field(default_factory=dict)
    holds: tuple[int, ...] = ()  # rounds each module deferred its start (start_holds)

    @property
    def time_steps(self) -> int:
        return max((k + 1 for k, r in enumerate(self.rounds) if r), default=0)

    @property
    def moves(self) -> int:
        return sum(len(r) for r in self.rounds)


class Engine:
    """One run of the traversal on a bridge map."""

    def __init__(self, bmap: BridgeMap, *, stall_rounds: int | None = None,
                 max_rounds: int | None = None, holds: tuple[int, ...] | None = None,
                 active: int | None = None) -> None:
        self.bmap = bmap
        self.surface = bmap.surface.surface
        self.model = bmap.model
        layer = bmap.layer1
        self.n = bmap.surface.n
        self.goal_order = [c for c in layer.cells if c in bmap.surface.goals]
        self.next_goal = {c: (self.goal_order[k + 1] if k + 1 < len(self.goal_order) else None)
                          for k, c in enumerate(self.goal_order)}
        self.roles = bmap.role_of()
        self.fills = bmap.fills
        self.crossing = bmap.crossing
        self.modules = [Module(k + 1, layer.cells[k], layer.pivots[k]) for k in range(self.n)]
        self.chain_cells = [m.cell for m in self.modules]
        self.at: dict[Cell, Module] = {m.cell: m for m in self.modules}
        self.changed: set[Cell] = set()  # in the last round, or two (hexbot model)
        self.changed_last: set[Cell] = set()
        # A rigid rotation sweeps a cell two away (Table 4-3, ring 2), so two
        # modules with two free cells between them can sweep the same cell: under
        # the hexbot model "quiet" covers two rounds, which leaves three free cells.
        self.quiet_rounds = 2 if self.model == "hexbot" else 1
        self.entered: set[Cell] = set()
        self.last_moves: list[tuple[Cell, Cell]] = []
        self.stall_rounds = stall_rounds or 8 * self.n + 40
        self.max_rounds = max_rounds or 20 * (len(layer) + 4 * self.n) + 200
        # modules after the first ``active`` never start (start_holds: the ones
        # ahead of a module, as it computes them from the map)
        self.active = active or self.n
        if holds is None:
            holds = (start_holds(bmap, stall_rounds=stall_rounds, max_rounds=max_rounds)
                     if self.model == "hexbot" else (0,) * self.n)
        self.holds = holds
        self.deferring = False
        # the run so far (:meth:`step`)
        self.initial = {m.ident: m.cell for m in self.modules}
        self.rounds: list[list[MoveRecord]] = []
        self.played = 0  # rounds played
        self.idle = 0  # rounds in a row in which nothing moved (or deferred)

    # -- what a module senses -------------------------------------------------
    def occupied(self, cell: Cell) -> bool:
        return cell in self.surface or cell in self.at

    def quiet(self, m: Module) -> bool:
        """None of the module's neighbour cells changed in the last round (the last
        two under the hexbot model)."""
        x, y, changed = *m.cell, self.changed
        return not any((x + dx, y + dy) in changed for dx, dy in _OFFSETS)

    def sensing(self, m: Module):
        """Occupancy as module ``m`` knows it: its neighbours by contact, farther
        cells only from the map of the surface and the Fill cells the modules
        ahead of it hold (module k passes after the first k - 1 are held)."""
        held = set(self.fills[: m.ident - 1])
        x, y = m.cell
        near = {(x + dx, y + dy) for dx, dy in _OFFSETS}

        def occupied(cell: Cell) -> bool:
            if cell in near:
                return self.occupied(cell)
            return cell in self.surface or cell in held
        return occupied

    def could_start(self, m: Module) -> bool:
        """Module ``m``, still in the chain, may start this round: the chain cell
        of the module before it is empty and its neighbour cells are quiet."""
        k = m.ident - 1
        return k == 0 or (self.chain_cells[k - 1] not in self.at and self.quiet(m))

    # -- MOVEMODULE ---------------------------------------------------------------
    def decide(self, m: Module) -> Rolled | None:
        """The module's move this round, or None (it waits)."""
        rule = "roll"
        if m.phase == "done":
            return None
        if m.phase == "chain":
            k = m.ident - 1
            if m.ident > self.active or not self.could_start(m):
                return None
            if m.deferred < self.holds[k]:  # its way would cross one ahead: not yet
                m.deferred += 1
                self.deferring = True
                return None
            m.phase, rule = "moving", "start"
        elif m.phase == "bridge":
            group = m.group
            assert group is not None
            passed = group.pass_sets.get(m.cell, frozenset())
            # a module moving from one pass cell into another is the same pass
            m.count += sum(1 for src, dst in self.last_moves
                           if dst in passed and src not in passed)
            if m.count < group.passes_needed(m.cell, self.crossing):
                return None
            m.phase, m.resume_rule = "resume", "leave-bridge"
        elif m.phase == "temp":
            group = m.group
            assert group is not None
            if not self.occupied(group.bridge[0]):
                return None
            if m.cell == group.support:  # TempSupport is the Support cell (h): stay
                m.phase = "support"
                return None
            m.phase = "to-support"
            if group.reverse:
                m.direction, m.pivot = "CCW", group.bridge[0]
            rule = m.to_support_rule = "reverse-to-support" if group.reverse else "on-to-support"
        elif m.phase == "support":
            group = m.group
            assert group is not None
            if self.occupied(group.bridge[0]):
                return None
            m.phase, m.direction, m.pivot = "resume", "CW", group.bridge[0]
            m.resume_rule = "leave-support"
        elif m.phase == "to-support":
            rule = m.to_support_rule
        if m.phase == "resume":
            if not self.quiet(m):
                return None
            m.phase, rule = "moving", m.resume_rule
        rolled = next_rotation(m.cell, m.pivot, m.direction, self.sensing(m), self.model,
                               m.avoid.__contains__)
        m.rule = rule
        return rolled

    def arrive(self, m: Module) -> None:
        """What the cell just entered asks of the module (Fig. 10, lines 5-13)."""
        cell = m.cell
        if cell in self.fills:  # hexbot model: a rigid module stays where it got stuck
            m.phase, m.rule = "done", "fill"
            return
        if cell in self.next_goal:
            ahead = self.next_goal[cell]
            if ahead is None or ahead in self.at:
                m.phase = "done"
                return
        role = self.roles.get(cell)
        if m.phase == "to-support":
            assert m.group is not None
            if cell == m.group.support:
                m.phase = "support"
            return
        if role is None or id(role[1]) in m.served:
            return
        kind, group = role
        if kind == "Bridge":
            if group.temp_support is not None and not (
                    self.occupied(group.temp_support)
                    or (group.support is not None and self.occupied(group.support))):
                return  # RIGHT: the first module rolls on to the TempSupport cell
            m.phase, m.group, m.count = "bridge", group, 0
            m.served.add(id(group))
            if not group.through:
                m.avoid |= group.pocket
        elif kind == "TempSupport":
            m.phase, m.group = "temp", group
            m.served.add(id(group))

    # -- invariants -------------------------------------------------------------
    def check(self, rnd: int, actions: list[tuple[Module, Rolled]]) -> Violation | None:
        movers = {m.cell: m for m, _ in actions}

        def fail(invariant: str, mods: list[Module], detail: str) -> Violation:
            return Violation(rnd, invariant, [x.ident for x in mods], [x.rule for x in mods],
                             detail)

        targets: dict[Cell, Module] = {}
        for m, rolled in actions:
            if rolled.dst in targets:
                return fail("one module per cell", [targets[rolled.dst], m],
                            f"both move into {list(rolled.dst)}")
            targets[rolled.dst] = m
            if self.occupied(rolled.dst):
                return fail("one module per cell", [m], f"{list(rolled.dst)} is occupied")
            if not self.occupied(rolled.substrate):
                return fail("no move without a substrate", [m],
                            f"substrate {list(rolled.substrate)} is empty")
            if rolled.substrate in movers:
                return fail("a mover never rolls on a moving module",
                            [m, movers[rolled.substrate]],
                            f"substrate {list(rolled.substrate)} moves in the same round")
            for cell in required_empty(rolled.rotation, rolled.src, self.model)[1:]:
                if self.occupied(cell):
                    return fail("swept cells empty", [m], f"{list(cell)} is occupied "
                                f"({self.model} model)")
        # no move passes through a cell another move passes through or needs empty
        # (for rigid modules: the plan checker's "no two moves need one cell")
        bodies = {m.ident: set(body_cells(rolled.rotation, rolled.src, self.model))
                  for m, rolled in actions}
        for m, rolled in actions:
            needs = {*bodies[m.ident], *required_empty(rolled.rotation, rolled.src, self.model)}
            for other, orolled in actions:
                if other is m:
                    continue
                shared = needs & bodies[other.ident]
                if shared:
                    return fail("swept cells empty", [m, other],
                                f"their rotations cross in {list(min(shared))}")
                if _next_to(rolled.src, orolled.src) or _next_to(rolled.dst, orolled.dst):
                    return fail("moving modules never adjacent", [m, other],
                                f"{list(rolled.src)}->{list(rolled.dst)} and "
                                f"{list(orolled.src)}->{list(orolled.dst)}")
        return None

    def connected(self) -> list[int]:
        """Modules not connected to the surface through other modules."""
        surface, at = self.surface, self.at
        reached = {(x, y) for x, y in at
                   if any((x + dx, y + dy) in surface for dx, dy in _OFFSETS)}
        if len(reached) == len(at):
            return []
        frontier = list(reached)
        while frontier:
            x, y = frontier.pop()
            for dx, dy in _OFFSETS:
                nb = (x + dx, y + dy)
                if nb in at and nb not in reached:
                    reached.add(nb)
                    frontier.append(nb)
        return sorted(at[c].ident for c in at if c not in reached)

    # -- the rounds ---------------------------------------------------------------
    def run(self) -> Result:
        while (result := self.step()) is None:
            pass
        return result

    def step(self) -> Result | None:
        """Play the next round; the result when the run ends (before or in it)."""
        rnd = self.played + 1
        rounds, initial = self.rounds, self.initial
        if rnd > self.max_rounds:
            return self._result("deadlock", rounds, initial,
                                reason=f"not done after {self.max_rounds} rounds")
        if all(m.phase in self._settled(m) for m in self.modules):
            return self._result("reached", rounds, initial)
        self.played = rnd
        self.deferring = False
        actions = [(m, r) for m in self.modules if (r := self.decide(m)) is not None]
        violation = self.check(rnd, actions)
        if violation is not None:
            return self._result("violation", rounds, initial, violation=violation,
                                reason=violation.describe())
        records = []
        for m, rolled in actions:
            sub = self.at.get(rolled.substrate)
            records.append(MoveRecord(m.ident, rolled.src, rolled.dst, rolled.substrate,
                                      sub.ident if sub else None, rolled.rotation.joint,
                                      rolled.rotation.direction, m.rule))
        for m, _ in actions:
            del self.at[m.cell]
        for m, rolled in actions:
            m.cell, m.pivot = rolled.dst, rolled.substrate
            self.at[m.cell] = m
        now = {r.src for r in records} | {r.dst for r in records}
        self.changed = (now | self.changed_last) if self.quiet_rounds == 2 else now
        self.changed_last = now
        self.entered = {r.dst for r in records}
        self.last_moves = [(r.src, r.dst) for r in records]
        for m, _ in actions:
            self.arrive(m)
        rounds.append(records)
        loose = self.connected()
        if loose:
            v = Violation(rnd, "connected to the surface", loose,
                          [self._by_id(i).rule for i in loose],
                          "modules lost contact with the surface")
            return self._result("violation", rounds, initial, violation=v,
                                reason=v.describe())
        self.idle = idle = 0 if records or self.deferring else self.idle + 1
        if idle >= self.stall_rounds:
            waiting = [f"{m.ident}:{m.phase}@{list(m.cell)}" for m in self.modules
                       if m.phase != "done"]
            return self._result("deadlock", rounds[: len(rounds) - idle], initial,
                                reason=f"no module moved for {idle} rounds; waiting: "
                                       + ", ".join(waiting))
        return None

    def fork(self, holds: tuple[int, ...], active: int) -> Engine:
        """A copy of this run as it stands, to go on with other ``holds`` and
        ``active`` (:func:`start_holds`): what the rounds change is copied, the
        map and what is computed from it shared."""
        other = object.__new__(Engine)
        other.__dict__.update(self.__dict__)
        other.modules = [dataclasses.replace(m, served=set(m.served), avoid=set(m.avoid))
                         for m in self.modules]
        other.at = {cell: other.modules[m.ident - 1] for cell, m in self.at.items()}
        other.rounds = list(self.rounds)
        other.holds, other.active = holds, active
        return other

    def _settled(self, m: Module) -> tuple[str, ...]:
        """Phases in which module ``m`` counts as finished: "done"; in a run of the
        first ``active`` modules only (:func:`start_holds`) also waiting for the
        modules behind it: on a Bridge cell (for their passes), a TempSupport
        cell (for the one that will hold the bridge) or a Support cell (for the
        Bridge module to leave); and any phase for the modules that never start."""
        if self.active == self.n:
            return ("done",)
        if m.ident > self.active:
            return (m.phase,)
        return ("done", "bridge", "temp", "support")

    def _by_id(self, ident: int) -> Module:
        return self.modules[ident - 1]

    def _result(self, status: str, rounds: list[list[MoveRecord]], initial: dict[int, Cell],
                violation: Violation | None = None, reason: str = "") -> Result:
        return Result(status, rounds, {m.ident: m.cell for m in self.modules}, violation,
                      reason, initial, tuple(self.holds))


def traverse(bmap: BridgeMap, **options: Any) -> Result:
    if bmap.model == "hexbot" and options.get("holds") is None and not options.get("active"):
        # the search for the holds ends with this very run: no need to run it again
        return _hold_search(bmap, options.get("stall_rounds"), options.get("max_rounds"))[1]
    return Engine(bmap, **options).run()


#: the hold of the module whose start :func:`start_holds` is searching: it never
#: starts, it counts the rounds in which it could have
_NEVER = sys.maxsize


def start_holds(bmap: BridgeMap, *, stall_rounds: int | None = None,
                max_rounds: int | None = None) -> tuple[int, ...]:
    """How many rounds each module defers its start (hexbot model): the fewest
    for which its way, with the modules ahead of it moving as they will, makes
    no move that crosses one of theirs. A module computes this from the map
    alone, in preprocessing like the bridge map: the modules ahead start by the
    same rule and then follow the map's wall-following way, so where each of
    them is in every round is known to it (no messages, no sensing beyond its
    neighbours). Module by module: module ``k`` is run with the first ``k - 1``
    and their holds (the later ones stay in the chain) until each of them is
    done or waits for the modules behind it (on a Bridge, TempSupport or
    Support cell); the first hold whose run breaks no invariant is taken. A
    run that deadlocks (no module moved for ``stall_rounds`` rounds, or not
    done after ``max_rounds``) crossed nothing: its hold is taken too, and the
    run reports the deadlock, not the crossing a shorter hold would make.
    Holding longer than the modules ahead take to settle changes nothing;
    when no hold up to that helps, the hold is 0 and the run reports the
    conflict (docs/traversal.md, "Rigid modules whose ways fold back").
    ``stall_rounds``, ``max_rounds``: the run's (:class:`Engine`), None for
    its defaults."""
    return _hold_search(bmap, stall_rounds, max_rounds)[0]


def _hold_search(bmap: BridgeMap, stall_rounds: int | None,
                 max_rounds: int | None) -> tuple[tuple[int, ...], Result]:
    """:func:`start_holds`, and the run of all modules with them.

    The run of module ``k`` with hold ``h`` (the first ``k`` modules, ``k``
    held ``h`` of the rounds in which it could start) is the same as the run
    with module ``k`` held for good (``base``, in which it stays in the chain)
    up to the round in which it starts: each candidate is a copy of ``base``
    taken at the start of that round (:meth:`Engine.fork`), run on from there.
    The run of the first ``k`` modules with the hold taken is the next
    module's ``ahead``; ``base`` for the next module is the copy of the one for
    module ``k`` at the round in which it starts with that hold. When ``base``
    breaks an invariant before module ``k`` could start the ``h``-th time, so
    do all holds from ``h`` on (the same rounds up to there): the search stops.
    """
    n = bmap.surface.n
    options = {"stall_rounds": stall_rounds, "max_rounds": max_rounds}
    holds = [0] * n

    def with_hold(k: int, hold: int) -> tuple[int, ...]:
        return (*holds[:k], hold, *holds[k + 1:])

    ahead = Engine(bmap, holds=tuple(holds), active=1, **options).run()
    base = Engine(bmap, holds=with_hold(1, _NEVER), active=2, **options) if n > 1 else None
    for k in range(1, n):  # module k + 1, index k
        assert base is not None
        limit = ahead.time_steps + 2  # holds 0 .. limit - 1 (longer change nothing)
        mod = base.modules[k]
        taken: tuple[int, Result, Engine | None] | None = None
        first: tuple[Result, Engine | None] | None = None  # hold 0, the fallback
        while taken is None and mod.deferred < limit:
            if mod.phase == "chain" and base.could_start(mod):
                hold = mod.deferred  # it starts in this round with this hold
                at_start = base.fork(with_hold(k, hold), k + 1)
                result = at_start.fork(at_start.holds, k + 1).run()
                if hold == 0:
                    first = (result, at_start)
                if result.status != "violation":
                    taken = (hold, result, at_start)
                    break
            end = base.step()
            if end is not None:  # module k + 1 does not start again: the holds left
                hold = mod.deferred  # all give this run (module k + 1 stays)
                result = dataclasses.replace(end, holds=with_hold(k, hold))
                if hold == 0:
                    first = (result, None)
                if hold < limit and result.status != "violation":
                    taken = (hold, result, None)
                break
        if taken is None:  # no hold helps: 0, and the run reports the violation
            assert first is not None
            taken = (0, *first)
        holds[k], ahead, at_start = taken
        if at_start is None:  # module k + 1 never starts, nor do those behind it
            return tuple(holds), dataclasses.replace(ahead, holds=tuple(holds))
        base = (at_start.fork(with_hold(k + 1, _NEVER), k + 2) if k + 1 < n else None)
    return tuple(holds), ahead
