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

from dataclasses import dataclass, field
from typing import Any

from hexbot.planning.traversal.bridges import BridgeMap, Group
from hexbot.planning.traversal.motion import (
    Rolled,
    body_cells,
    next_rotation,
    required_empty,
)
from hexbot.protocol.lattice import SIDES, Cell, distance, neighbor

STATUSES = ("reached", "deadlock", "violation")


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
            holds = start_holds(bmap) if self.model == "hexbot" else (0,) * self.n
        self.holds = holds
        self.deferring = False

    # -- what a module senses -------------------------------------------------
    def occupied(self, cell: Cell) -> bool:
        return cell in self.surface or cell in self.at

    def quiet(self, m: Module) -> bool:
        """None of the module's neighbour cells changed in the last round (the last
        two under the hexbot model)."""
        return not any(neighbor(m.cell, s) in self.changed for s in SIDES)

    def sensing(self, m: Module):
        """Occupancy as module ``m`` knows it: its neighbours by contact, farther
        cells only from the map of the surface and the Fill cells the modules
        ahead of it hold (module k passes after the first k - 1 are held)."""
        held = set(self.fills[: m.ident - 1])

        def occupied(cell: Cell) -> bool:
            if distance(cell, m.cell) == 1:
                return self.occupied(cell)
            return cell in self.surface or cell in held
        return occupied

    # -- MOVEMODULE ---------------------------------------------------------------
    def decide(self, m: Module) -> Rolled | None:
        """The module's move this round, or None (it waits)."""
        rule = "roll"
        if m.phase == "done":
            return None
        if m.phase == "chain":
            k = m.ident - 1
            if m.ident > self.active:
                return None
            if k > 0 and (self.chain_cells[k - 1] in self.at or not self.quiet(m)):
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
                if distance(rolled.src, orolled.src) == 1 or \
                        distance(rolled.dst, orolled.dst) == 1:
                    return fail("moving modules never adjacent", [m, other],
                                f"{list(rolled.src)}->{list(rolled.dst)} and "
                                f"{list(orolled.src)}->{list(orolled.dst)}")
        return None

    def connected(self) -> list[int]:
        """Modules not connected to the surface through other modules."""
        reached = {c for c in self.at if any(neighbor(c, s) in self.surface for s in SIDES)}
        frontier = list(reached)
        while frontier:
            cell = frontier.pop()
            for s in SIDES:
                nb = neighbor(cell, s)
                if nb in self.at and nb not in reached:
                    reached.add(nb)
                    frontier.append(nb)
        return sorted(self.at[c].ident for c in self.at if c not in reached)

    # -- the rounds ---------------------------------------------------------------
    def run(self) -> Result:
        initial = {m.ident: m.cell for m in self.modules}
        rounds: list[list[MoveRecord]] = []
        idle = 0
        for rnd in range(1, self.max_rounds + 1):
            if all(m.phase in self._settled(m) for m in self.modules):
                return self._result("reached", rounds, initial)
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
            idle = 0 if records or self.deferring else idle + 1
            if idle >= self.stall_rounds:
                waiting = [f"{m.ident}:{m.phase}@{list(m.cell)}" for m in self.modules
                           if m.phase != "done"]
                return self._result("deadlock", rounds[: len(rounds) - idle], initial,
                                    reason=f"no module moved for {idle} rounds; waiting: "
                                           + ", ".join(waiting))
        return self._result("deadlock", rounds, initial,
                            reason=f"not done after {self.max_rounds} rounds")

    def _settled(self, m: Module) -> tuple[str, ...]:
        """Phases in which module ``m`` counts as finished: "done"; in a run of the
        first ``active`` modules only (:func:`start_holds`) also waiting on a
        bridge (the passes it waits for are the later modules'), and any phase
        for the modules that never start."""
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
    return Engine(bmap, **options).run()


def start_holds(bmap: BridgeMap) -> tuple[int, ...]:
    """How many rounds each module defers its start (hexbot model): the fewest
    for which its way, with the modules ahead of it moving as they will, makes
    no move that crosses one of theirs. A module computes this from the map
    alone, in preprocessing like the bridge map: the modules ahead start by the
    same rule and then follow the map's wall-following way, so where each of
    them is in every round is known to it (no messages, no sensing beyond its
    neighbours). Module by module: module ``k`` is run with the first ``k - 1``
    and their holds (the later ones stay in the chain) until all of them are
    done or wait on a bridge. Holding longer than the modules ahead take to
    settle changes nothing; when no hold up to that helps, the hold is 0 and
    the run reports the conflict (docs/traversal.md, "Rigid modules whose ways
    fold back")."""
    n = bmap.surface.n
    holds = [0] * n
    for k in range(1, n):
        ahead = Engine(bmap, holds=tuple(holds), active=k).run()
        for hold in range(ahead.time_steps + 2):
            holds[k] = hold
            if Engine(bmap, holds=tuple(holds), active=k + 1).run().status != "violation":
                break
        else:
            holds[k] = 0
    return tuple(holds)
