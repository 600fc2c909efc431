"""Execute a plan on a cluster through a session: real modules, a pty, or the
embedded simulator, all the same way.

The executor talks to the modules only the way a PC does, through
:class:`~hexbot.host.session.Session` and the host's workflows:
localize the cluster from the reference module, check that it is the
plan's initial configuration (ids, cells, orientations), then rotate move
by move with :func:`hexbot.host.workflows.rotate`, which sets the roles,
converts joints to each module's body frame and verifies every move (the
plant's verdict on the simulator, a new localization elsewhere, see
``Verify``). The first move that is refused or not verified ends the run
with a report. At the end the cluster is localized once more and compared
with the goal: success is claimed only after that.

Moves of one parallel time step run one after the other: the IR link
carries one message at a time and each module needs its own body-frame
joint index.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from hexbot.errors import CancelledError, HexBotError, ScenarioError
from hexbot.host import workflows
from hexbot.host.session import Session
from hexbot.host.workflows import Pose, Verify
from hexbot.planning.budget import DEFAULT_BUDGET
from hexbot.planning.configuration import Configuration, Module, is_connected
from hexbot.planning.hexlattice import Cell
from hexbot.planning.moves import orientation_after
from hexbot.planning.plan import Plan


class ExecutionError(HexBotError):
    """The cluster is not the plan's initial configuration."""


@dataclass
class MoveResult:
    step: int
    module: int
    expected: Pose
    verified_by: str
    got: Pose | None
    ok: bool
    failure: str = ""


@dataclass
class ExecutionReport:
    localized: int = 0
    moves: list[MoveResult] = field(default_factory=list)
    reached: bool = False
    failure: str = ""
    seconds: float = 0.0  # session time (simulated on a simulator)
    #: the exit status of the error that stopped the run (docs/console.md:
    #: 3 a time-out, 4 a lost port, 1 a refusal), 0 when the goal was reached
    exit_status: int = 0
    #: every move ran, so the last line is the final localization's verdict
    finished: bool = False

    def line(self, total: int) -> str:
        """The CLI's last line: how far the run got, and on what evidence."""
        done = sum(m.ok for m in self.moves)
        verdict = ("goal reached (localized)" if self.reached else
                   "goal NOT reached (localized)" if self.finished else "stopped early")
        return f"executed {done}/{total} moves in {self.seconds:.1f} s; {verdict}"

    def outcome(self, total: int) -> str:
        """One line when the goal was reached (localized), else
        :class:`HexBotError` saying how far the run got and why it stopped."""
        done = sum(m.ok for m in self.moves)
        if not self.reached:
            message = f"after {done} of {total} moves: {self.failure}"
            if self.exit_status == CancelledError.exit_status:  # Ctrl-C
                raise CancelledError(message)
            error = HexBotError(message)
            error.exit_status = self.exit_status or 1  # a time-out 3, a lost port 4
            raise error
        return f"goal reached (localized): {done} of {total} moves in {self.seconds:.1f} s"

    def as_json(self) -> dict[str, Any]:
        return {
            "localized": self.localized,
            "reached": self.reached,
            "failure": self.failure,
            "seconds": round(self.seconds, 3),
            "moves": [{"step": m.step, "module": m.module, "to": list(m.expected.cell),
                       "orientation": m.expected.orientation, "ok": m.ok,
                       "verified_by": m.verified_by,
                       "got": ({"to": list(m.got.cell), "orientation": m.got.orientation}
                               if m.got else None),
                       "failure": m.failure}
                      for m in self.moves],
        }


def configuration_of(poses: dict[int, Pose]) -> Configuration:
    """Localized poses as a planner configuration."""
    return Configuration({p.cell: Module(ident, p.orientation) for ident, p in poses.items()})


@dataclass(frozen=True)
class PlanRequest:
    """``GOAL [reference ID] [verify auto|plant|localize|status]``: what the
    console's plan prompt and a script's ``plan`` step ask for."""

    goal: frozenset[Cell]
    reference: int | None  # None: :func:`default_reference`
    verify: Verify

    def reference_in(self, session: Session) -> int:
        return self.reference if self.reference is not None else default_reference(session)


PLAN_USAGE = "GOAL [reference ID] [verify auto|plant|localize|status]"


def plan_request(words: list[str], relative_to: Path | None = None) -> PlanRequest:
    """Parse a plan request; the goal file is read here (a relative path
    from ``relative_to``, e.g. a script's folder), so a bad request sends
    nothing. :class:`ScenarioError` says what is wrong."""
    from hexbot.planning.config_io import load_configuration

    if not words or len(words) % 2 != 1:
        raise ScenarioError(f"expected {PLAN_USAGE}")
    options = dict(zip(words[1::2], words[2::2], strict=True))
    unknown = set(options) - {"reference", "verify"}
    if unknown:
        raise ScenarioError(f"unexpected {sorted(unknown)[0]!r} (expected {PLAN_USAGE})")
    reference = None
    if "reference" in options:
        if not options["reference"].isdigit():
            raise ScenarioError(f"reference must be a module id, got {options['reference']!r}")
        reference = int(options["reference"])
        why = workflows.reference_problem(reference)
        if why:  # before anything is sent
            raise ScenarioError(why)
    verify = Verify.named(options.get("verify", "auto"))
    goal = Path(words[0])
    if relative_to is not None and not goal.is_absolute():
        goal = relative_to / goal
    cells = load_configuration(goal).cells
    if not is_connected(cells):  # no plan can end in it: say so before localizing
        raise ScenarioError(f"{goal}: the goal is not connected: modules must stay in one piece")
    return PlanRequest(cells, reference, verify)


def default_reference(session: Session) -> int:
    """The module that becomes (0, 0) and never moves when the user names
    none: the session's origin if a Ref made one, else the simulator's base
    module, else the lowest id heard so far."""
    if session.reference is not None:
        return session.reference
    sim = session.host.simulator
    if sim is not None and sim.base is not None:
        return sim.base
    return min(session.learn() or {1})


def plan_from_cluster(session: Session, goal: frozenset[Cell], reference: int, *,
                      budget: float | None = DEFAULT_BUDGET,
                      progress: Callable[[str], None] | None = None
                      ) -> tuple[Plan, dict[int, Pose]]:
    """Localize the cluster from ``reference`` and plan (robust mode) from it as
    it stands to ``goal``, the reference module fixed (localization needs it
    where it is): the plan, and the poses it starts from (for :func:`execute`).
    :class:`HexBotError` with the planner's reason when there is no plan."""
    from hexbot.planning.robust import plan_robust

    poses = workflows.localize(session, reference)
    if reference not in poses:
        raise HexBotError(f"the reference module {reference} did not answer the localization")
    initial = configuration_of(poses)
    plan = plan_robust(initial, frozenset(goal), fixed=poses[reference].cell, budget=budget,
                       progress=progress)
    if not plan.reached:
        raise HexBotError(f"no plan: {plan.reason}")
    return plan, poses


def pinned_modules(session: Session, reference: int) -> dict[int, str]:
    """The modules a plan may not move, and why: the localization's origin,
    and on the simulator the module its scenario bolts to the base."""
    pinned = {reference: "the reference of the localization"}
    sim = session.host.simulator
    if sim is not None and sim.base is not None and sim.base != reference:
        pinned[sim.base] = "bolted to the base in the scenario"
    return pinned


def check_plan_fits(plan: Plan, session: Session, reference: int) -> None:
    """:class:`ExecutionError` before anything is sent when the plan moves a
    pinned module (:func:`pinned_modules`) or names a module id the link
    cannot address."""
    from hexbot.protocol.wire import MAX_SELECT_ID

    moved = {m.module for step in plan.steps for m in step.moves}
    for module, why in pinned_modules(session, reference).items():
        if module in moved:
            raise ExecutionError(
                f"the plan moves module {module}, {why}: nothing sent (the robust mode "
                "keeps the reference in place; on the simulator, make the base module "
                "the reference)")
    far = sorted(m.id for m in plan.initial.values() if m.id > MAX_SELECT_ID)
    if far:
        raise ExecutionError(f"module id {far[0]} cannot be addressed: the link's Select "
                             f"reaches ids 1..{MAX_SELECT_ID}; nothing sent")


def execute(plan: Plan, session: Session, reference: int, *, verify: Verify = Verify.AUTO,
            log: Callable[[str], None] | None = None,
            poses: dict[int, Pose] | None = None) -> ExecutionReport:
    """Run ``plan`` on the cluster behind ``session``; stop at the first move
    that is refused or not verified. ``poses``: a localization just made
    (else one is made first)."""
    say = log or (lambda _line: None)
    report = ExecutionReport()
    start = session.now()
    try:
        if poses is None:
            poses = workflows.localize(session, reference)
        report.localized = len(poses)
        actual = configuration_of(poses)
        if actual != plan.initial:
            raise ExecutionError(
                "the plan does not start from the cluster as localized: plan "
                f"{sorted(plan.initial.items())} vs cluster {sorted(actual.items())}")
        check_plan_fits(plan, session, reference)
        config = plan.initial
        for index, step in enumerate(plan.steps, start=1):
            for move in step.moves:
                orientation = orientation_after(config[move.src].orientation, move.direction)
                expected = Pose(move.dst, orientation)
                try:
                    result = workflows.rotate(session, move.direction, move.joint, move.module,
                                              move.substrate_module, verify=verify,
                                              reference=reference)
                except HexBotError as exc:
                    report.moves.append(MoveResult(index, move.module, expected,
                                                   verify.value, None, False, str(exc)))
                    raise HexBotError(
                        f"step {index}: module {move.module} {move.src}->{move.dst} "
                        f"({move.direction} about joint {move.joint}): {exc}") from exc
                report.moves.append(MoveResult(index, move.module, expected,
                                               result.verified_by.value, result.got,
                                               result.expected == expected))
                say(f"{session.now():9.3f}  step {index}: {result.describe()}")
                config = config.moved(move.src, move.dst, orientation)
        final = workflows.localize(session, reference)
        report.finished = True
        report.reached = frozenset(p.cell for p in final.values()) == plan.goal
        if not report.reached:
            report.exit_status = 1
            report.failure = (f"all moves done but the localized cluster "
                              f"{sorted(p.cell for p in final.values())} is not the goal")
    except HexBotError as exc:
        report.failure = str(exc)
        cause = exc.__cause__ if isinstance(exc.__cause__, HexBotError) else exc
        report.exit_status = cause.exit_status
    except KeyboardInterrupt:  # the report still says how far the run got
        report.failure = "interrupted (Ctrl-C)"
        report.exit_status = 130
    report.seconds = session.now() - start
    return report
