"""Execute a plan on the simulated cluster, move by move, and check the plant.

The executor talks to the modules only the way a PC does: frames on the
PC's IR transceiver, replies parsed from what comes back (in the simulator's
virtual time, so a run is fast and deterministic). After each move it reads
the plant's ``moved``/``refused`` events and compares them with the plan;
the first divergence ends the run with a report.

Sequence: ``Select(base) Ref``, ``Select(0) Localize`` (one command
localizes the connected cluster), then for each move the commands of
:func:`hexbot.planning.commands.plan_to_commands` (``SetRole`` where a role
changes, ``Select(mobile, substrate)``, ``CW``/``CCW``). Moves of one
parallel time step are executed one after the other: the IR link carries
one message at a time and each module needs its own body-frame joint index.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

from hexbot.errors import HexBotError, HexBotTimeoutError
from hexbot.planning.commands import plan_to_commands
from hexbot.planning.configuration import Configuration, Module
from hexbot.planning.moves import orientation_after
from hexbot.planning.plan import Plan
from hexbot.protocol import frames, parser
from hexbot.protocol.frames import Command

REPLY_KINDS = (parser.Ack, parser.ErrorReply, parser.StatusReport)
LOCALIZE_BASE_S = 20.8  # firmware: 4 hops of 4.8 s sweeps before replies start
LOCALIZE_PER_MODULE_S = 2.4  # firmware: one report slot per module
QUIET_S = 0.8  # listen a little longer after the expected replies
MOVE_TIMEOUT_S = 3.0  # a rotation takes 220 ms; the plant reports right after


class ExecutionError(HexBotError):
    """The cluster did not do what the plan said (no ACK, an ERR, a refused or
    different motion); the message names the step, the move and what happened."""


@dataclass
class MoveResult:
    step: int
    module: int
    expected: tuple[tuple[int, int], int]  # (cell, orientation)
    got: dict[str, Any] | None
    ok: bool


@dataclass
class ExecutionReport:
    localized: int = 0
    moves: list[MoveResult] = field(default_factory=list)
    reached: bool = False
    failure: str = ""
    sim_seconds: float = 0.0

    def as_json(self) -> dict[str, Any]:
        return {
            "localized": self.localized,
            "reached": self.reached,
            "failure": self.failure,
            "sim_seconds": round(self.sim_seconds, 3),
            "moves": [{"step": m.step, "module": m.module, "to": list(m.expected[0]),
                       "orientation": m.expected[1], "ok": m.ok, "plant": m.got}
                      for m in self.moves],
        }


def configuration_of(sim: Any) -> Configuration:
    """The simulated cluster as a planner configuration (ids, cells, orientations)."""
    return Configuration({mod.position: Module(ident, mod.orientation)
                          for ident, mod in sim.modules.items()})


class SimPc:
    """The PC end of the IR link of a :class:`~hexbot.hil_sim.Simulator`."""

    def __init__(self, sim: Any, log: Callable[[str], None] | None = None) -> None:
        self.sim = sim
        self.heard = bytearray()
        self.log = log or (lambda _line: None)

    def _replies(self) -> list[parser.Event]:
        return [e for e in parser.parse_all(bytes(self.heard)) if isinstance(e, REPLY_KINDS)]

    def exchange(self, command: Command, replies: int, timeout: float) -> list[parser.Event]:
        """Send one command; wait for ``replies`` ACK/ERR/STA replies."""
        self.heard.clear()
        self.heard += self.sim.pc_read()
        self.heard.clear()
        self.sim.pc_write(frames.encode_pc(command))

        def enough(sim: Any) -> bool:
            self.heard.extend(sim.pc_read())
            return len(self._replies()) >= replies

        try:
            self.sim.run_until(enough, timeout)
        except HexBotTimeoutError as exc:
            got = [e.describe() if hasattr(e, "describe") else str(e) for e in self._replies()]
            raise ExecutionError(
                f"{command}: expected {replies} repl{'y' if replies == 1 else 'ies'} within "
                f"{timeout} s, got {got or 'none'}") from exc
        self.sim.run(QUIET_S)
        self.heard.extend(self.sim.pc_read())
        found = self._replies()
        self.log(f"{self.sim.time:9.3f}  {command}  ->  "
                 + ", ".join(e.describe() if hasattr(e, "describe") else type(e).__name__
                             for e in found))
        bad = [e for e in found if isinstance(e, parser.ErrorReply)
               or (isinstance(e, parser.Ack) and e.code != command.code)]
        if bad:
            raise ExecutionError(f"{command}: {bad[0].describe()}")
        return found


def _selected_count(command: Command, total: int) -> int:
    return total if command.args[:1] == (0,) else len(command.args)


def localize(pc: SimPc, base: int) -> int:
    """Make ``base`` the reference and localize the cluster; return the number
    of modules that reported."""
    n = len(pc.sim.modules)
    pc.exchange(frames.select([base]), 1, 8.0)
    pc.exchange(frames.make("Ref"), 1, 8.0)
    pc.exchange(frames.select([0]), n, 8.0 + 0.6 * n)
    found = pc.exchange(frames.make("Localize"), n,
                        LOCALIZE_BASE_S + LOCALIZE_PER_MODULE_S * n + 2.0)
    return len(found)


def execute(plan: Plan, sim: Any, log: Callable[[str], None] | None = None) -> ExecutionReport:
    """Run ``plan`` on ``sim`` (booted); stop at the first divergence."""
    report = ExecutionReport()
    actual = configuration_of(sim)
    if actual != plan.initial:
        raise ExecutionError("the plan does not start from the simulated cluster: "
                             f"plan {sorted(plan.initial.items())} vs "
                             f"cluster {sorted(actual.items())}")
    pc = SimPc(sim, log)
    start = sim.time
    try:
        report.localized = localize(pc, sim.scenario.base or min(sim.modules))
        config = plan.initial
        for index, step_cmds in enumerate(plan_to_commands(plan), start=1):
            for move_cmds in step_cmds:
                move = move_cmds.move
                orientation = orientation_after(config[move.src].orientation, move.direction)
                seen = len(sim.events)
                for command in move_cmds.commands:
                    expect = (_selected_count(command, len(sim.modules))
                              if command.function.name == "Select"
                              else 2 if command.function.name in ("CW", "CCW") else 1)
                    pc.exchange(command, expect, 4.0 + 0.6 * expect)
                got = _motion_of(sim, seen, move.module)
                ok = bool(got and got["event"] == "moved" and tuple(got["to"]) == move.dst
                          and got["orientation"] == orientation)
                report.moves.append(MoveResult(index, move.module, (move.dst, orientation),
                                               got, ok))
                if not ok:
                    raise ExecutionError(
                        f"step {index}: module {move.module} {move.src}->{move.dst} "
                        f"({move.direction} about joint {move.joint}): plant says "
                        f"{_describe(got)}")
                config = config.moved(move.src, move.dst, orientation)
        report.reached = frozenset(configuration_of(sim)) == plan.goal
        if not report.reached:
            report.failure = "all moves done but the cluster is not in the goal shape"
    except ExecutionError as exc:
        report.failure = str(exc)
    report.sim_seconds = sim.time - start
    return report


def _motion_of(sim: Any, seen: int, module: int) -> dict[str, Any] | None:
    """The plant's verdict on the module's rotation (moved or refused)."""
    def verdict(s: Any) -> dict[str, Any] | None:
        for event in s.events[seen:]:
            if event.get("module") == module and event["event"] in ("moved", "refused"):
                return event
        return None

    try:
        sim.run_until(lambda s: verdict(s) is not None, MOVE_TIMEOUT_S)
    except HexBotTimeoutError:
        return None
    return verdict(sim)


def _describe(event: dict[str, Any] | None) -> str:
    if event is None:
        return f"no motion within {MOVE_TIMEOUT_S} s"
    if event["event"] == "refused":
        return f"refused ({event.get('reason', 'no reason given')})"
    return f"moved to {tuple(event['to'])} facing {event['orientation']}"
