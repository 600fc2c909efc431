"""The thesis' workflows, written once: localize, set roles, rotate and verify.

The console, ``hexbot run`` scripts and plan execution call these; each
step goes through the :class:`~hexbot.host.session.Session` and a step that
is not acknowledged stops the workflow with its typed error.

Rotation (codes 67/68) moves a *mobile* module 120 degrees about a joint it
shares with a *substrate*: both must have their role (SetRole), both must
be selected, and each needs the pivot joint in its own body frame, which
needs its orientation. So a rotation refuses to start when either
orientation is unknown, or stale (the module moved since it last reported
it); and it is not "done" when the modules acknowledge, only when it is
verified:

- ``plant``: on the embedded simulator, the plant's verdict (moved where,
  facing where; or refused, and why);
- ``localize``: on any port, localize the cluster again and compare where
  the mobile module says it is with where the rotation takes it; the only
  check a PC has on real modules (costs one localization window);
- ``status``: on any port, a status query of the mobile module: it must say
  it moved (unlocalized, no error). Quick, but blind to a rotation the
  mechanics refused; a later localization catches that.
"""

from __future__ import annotations

import enum
from dataclasses import dataclass

from hexbot.errors import CommandRefusedError, HexBotTimeoutError, ScenarioError
from hexbot.host.session import OutcomeKind, Session, select
from hexbot.protocol import frames, lattice, wire
from hexbot.protocol.codes import ErrorCode, Role
from hexbot.protocol.parser import StatusReport
from hexbot.protocol.rotation import combined_rotation, direction_of
from hexbot.protocol.rotation_geometry import Rotation
from hexbot.protocol.simulation import Moved, Placement, Refused

Cell = tuple[int, int]
#: The plant resolves a rotation once both halves' magnets are off:
#: Table 3-1's 220 ms plus the comm board's reply; this bounds the wait.
VERDICT_WAIT_S = 3.0


@dataclass(frozen=True)
class Pose:
    cell: Cell
    orientation: int  # Yref 0..5


class Verify(enum.Enum):
    AUTO = "auto"  # plant on a simulator, localize elsewhere
    PLANT = "plant"
    LOCALIZE = "localize"
    STATUS = "status"

    @classmethod
    def named(cls, word: str) -> Verify:
        """The check a user named (any case); ScenarioError lists the others."""
        try:
            return cls(word.lower())
        except ValueError:
            raise ScenarioError("verify must be one of "
                                f"{', '.join(v.value for v in cls)}") from None


@dataclass(frozen=True)
class RotationResult:
    mobile: int
    substrate: int
    expected: Pose
    verified_by: Verify
    got: Pose | None  # where the check found the module (None: status check)

    def describe(self) -> str:
        where = (f" at {self.got.cell} facing {self.got.orientation}" if self.got else "")
        return f"module {self.mobile} moved{where} (verified by {self.verified_by.value})"


# --- localization -----------------------------------------------------------


def reference_problem(reference: int) -> str:
    """Why ``reference`` cannot be a localization's origin ("" if it can):
    it is addressed with Select(reference), and Select(0) would make every
    module (0, 0)."""
    if 1 <= reference <= wire.MAX_SELECT_ID:
        return ""
    return f"the reference must be a module id 1..{wire.MAX_SELECT_ID}, got {reference}"


def localize(session: Session, reference: int) -> dict[int, Pose]:
    """Make ``reference`` the origin, localize the whole cluster with code 66,
    read everyone's status; returns every module's pose. One 66 reaches 4
    hops (docs/firmware.md); while some modules answer only NOT_HEARD and
    the last wave localized more of them, another 66 spreads the
    localization further (the localized ones keep theirs). Fails when a
    wave adds nobody or a module is not localized afterwards."""
    why = reference_problem(reference)
    if why:
        raise CommandRefusedError(why)
    if session.reference is not None and session.reference != reference:
        # the firmware keeps a reference localized at (0, 0): a second one
        # would give the cluster two origins, and nothing sent can undo it
        raise CommandRefusedError(
            f"module {session.reference} is this cluster's origin (its Ref): localize from "
            f"it, or restart the modules to choose another (ctrl+r on the simulator)")
    session.request(select(reference))
    session.request(frames.make("Ref"))
    session.reference = reference  # the origin of every pose from here on
    unheard: set[int | None] | None = None
    while True:
        session.request(select(0))
        out = session.exchange(frames.make("Localize"))
        refusals = out.refusals if out.kind is OutcomeKind.REFUSED else ()
        still = {r.module for r in refusals}
        if not refusals or any(r.error is not ErrorCode.NOT_HEARD for r in refusals) or (
                unheard is not None and len(still) >= len(unheard)):
            out.raise_for_status()
            break
        unheard = still
    return poses(session)


def poses(session: Session) -> dict[int, Pose]:
    """Status of every selected module (Select(0) first); their poses."""
    out = session.request(frames.make("Status"))
    found: dict[int, Pose] = {}
    lost: list[int] = []
    for obs in out.replies:
        ev = obs.event
        assert isinstance(ev, StatusReport)
        if ev.localized:
            found[ev.module_id] = Pose((ev.x, ev.y), ev.yref)
        else:
            lost.append(ev.module_id)
    if lost:
        raise CommandRefusedError(f"not localized after Localize: module(s) "
                                  f"{', '.join(map(str, sorted(lost)))}")
    by_cell: dict[Cell, list[int]] = {}
    for module, pose in sorted(found.items()):
        by_cell.setdefault(pose.cell, []).append(module)
    crowded = {cell: ids for cell, ids in by_cell.items() if len(ids) > 1}
    if crowded:  # e.g. two modules took Ref: two origins
        cell, ids = min(crowded.items())
        raise CommandRefusedError(
            f"modules {', '.join(map(str, ids))} all report {cell}: the localization is "
            "inconsistent (more than one reference?); localize again from one module")
    return found


# --- roles and rotation ----------------------------------------------------------


def all_off(session: Session) -> None:
    """Every actuator of every module off, whatever runs and whoever is
    selected. ``TurnOffAll`` goes first: a rotation that runs keeps every
    other frame (a ``Select`` too) waiting in its module's inbox until it
    ends, but a control frame stops it on any module that hears it
    (docs/firmware.md). Then ``Select(0)`` and ``TurnOffAll`` again, for the
    modules the first one did not address."""
    turn_off_all = frames.make("TurnOffAll")
    problems = []
    for command in (turn_off_all, select(0), turn_off_all):
        # every frame goes out whatever the replies to the one before: a
        # rotation's garbled or missing answer must not keep magnets on
        outcome = session.exchange(command)
        if outcome.kind in (OutcomeKind.PORT_LOST, OutcomeKind.CANCELLED):
            outcome.raise_for_status()
        if not outcome.ok:
            problems.append(f"{command}: {outcome.reason}")
    if problems:
        raise CommandRefusedError("all frames sent, but not every module confirmed: "
                                  + "; ".join(problems))


def set_role(session: Session, module: int, role: Role) -> None:
    """Give ``module`` a role (code 71), unless its last reply showed it."""
    row = session.host.model.module(module)
    if row is not None and row.role == role.letter:
        return
    session.request(select(module))
    session.request(frames.make("SetRole", int(role)))


def known_pose(session: Session, module: int) -> Pose:
    """The module's pose as the replies last showed it; refuses when it is
    unknown or stale (moved since)."""
    row = session.host.model.module(module)
    if row is None or row.position is None or row.orientation is None:
        raise CommandRefusedError(f"orientation of module {module} unknown: localize first")
    if not row.localized and not row.assumed:
        raise CommandRefusedError(f"orientation of module {module} is stale (it moved since "
                                  "it was localized): localize again first")
    return Pose(row.position, row.orientation)


def rotate(session: Session, direction: str, joint: int, mobile: int, substrate: int, *,
           verify: Verify = Verify.AUTO, reference: int | None = None) -> RotationResult:
    """Rotate ``mobile`` about global ``joint`` on ``substrate`` and verify it.

    Raises CommandRefusedError before sending anything when an orientation
    is unknown or stale or the substrate is not where the rotation needs
    it; and after, when the plant refused or the check disagrees."""
    d = direction_of(direction)
    mob, sub = known_pose(session, mobile), known_pose(session, substrate)
    rotation = Rotation(joint, d)
    if rotation.substrate_cell(mob.cell) != sub.cell:
        raise CommandRefusedError(
            f"{d} about joint {joint}: module {mobile} at {mob.cell} needs its substrate at "
            f"{rotation.substrate_cell(mob.cell)}, module {substrate} is at {sub.cell}")
    expected = Pose(rotation.goal_cell(mob.cell), (mob.orientation + rotation.turn) % 6)
    command = combined_rotation(d, joint, mob.orientation, sub.orientation)
    how = verify
    simulator = session.host.simulator
    if how is Verify.AUTO:
        how = Verify.PLANT if simulator is not None else Verify.LOCALIZE
    if how is Verify.PLANT and simulator is None:
        raise CommandRefusedError("verify=plant needs the embedded simulator's port "
                                  "(hexbot-sim://)")
    set_role(session, mobile, Role.MOBILE)
    set_role(session, substrate, Role.SUBSTRATE)
    session.request(select(substrate, mobile))
    verdicts_before = len(simulator.verdicts()) if simulator is not None else 0
    # stale before the frame goes out: a wait abandoned (Escape, a time-out)
    # must not leave the old place and Yref to aim the next rotation from
    with session.host.lock:  # the reader thread and the views use the model too
        session.host.model.moved(mobile)
    session.request(command)
    if how is Verify.PLANT:
        got = _plant_verdict(session, mobile, verdicts_before)
    elif how is Verify.LOCALIZE:
        # the origin of the poses the rotation was planned from: a second
        # Ref elsewhere would give the cluster two origins
        origin = next(r for r in (reference, session.reference, substrate) if r is not None)
        got = localize(session, origin).get(mobile)
        if got is None:
            raise CommandRefusedError(f"module {mobile} reported no place after {d} about "
                                      f"joint {joint}: the rotation is not verified")
    else:
        _status_after_move(session, mobile)
        got = None
    if got is not None and got != expected:
        raise CommandRefusedError(
            f"module {mobile} should be at {expected.cell} facing {expected.orientation} "
            f"after {d} about joint {joint}, {how.value} check finds it at {got.cell} "
            f"facing {got.orientation}")
    with session.host.lock:
        if how is Verify.PLANT:  # the plant saw it
            session.host.model.placed(mobile, expected.cell, expected.orientation)
        elif how is Verify.STATUS:
            # a status check cannot see a place: the next moves take the
            # planned one as given, not as localized, until a localization
            session.host.model.assume(mobile, expected.cell, expected.orientation)
    return RotationResult(mobile, substrate, expected, how, got)


def in_localization_frame(pose: Pose, origin: Placement | None) -> Pose:
    """A pose of the plant's frame (the scenario's) in the localization's,
    whose origin is the reference module's cell, facing 0 (``origin``: the
    plant's placement of the reference; None: no localization yet)."""
    if origin is None:
        return pose
    (ox, oy), oo = origin.cell, origin.orientation
    cell = lattice.turn((pose.cell[0] - ox, pose.cell[1] - oy), -oo)
    return Pose(cell, (pose.orientation - oo) % 6)


def plant_placements(session: Session) -> dict[int, Placement]:
    """The simulator's truth in the localization's frame (empty on hardware):
    what the console draws beside the replies' placements."""
    simulator = session.host.simulator
    if simulator is None:
        return {}
    truth = simulator.placements()
    origin = truth.get(session.reference) if session.reference is not None else None
    return {ident: Placement(pose.cell, pose.orientation)
            for ident, p in truth.items()
            for pose in (in_localization_frame(Pose(p.cell, p.orientation), origin),)}


def _plant_verdict(session: Session, mobile: int, since: int) -> Pose:
    simulator = session.host.simulator
    assert simulator is not None
    found: list[Moved | Refused] = []
    origin = (simulator.placements().get(session.reference)
              if session.reference is not None else None)

    def ready() -> bool:
        found[:] = [v for v in simulator.verdicts(since) if v.module == mobile]
        return bool(found)

    if not session.host.clock.wait(ready, VERDICT_WAIT_S):
        raise HexBotTimeoutError(f"the plant reported no motion of module {mobile} within "
                                 f"{VERDICT_WAIT_S:g} s")
    verdict = found[0]
    if isinstance(verdict, Refused):
        raise CommandRefusedError(f"the plant refused: module {mobile} "
                                  f"{verdict.reason.value} ({verdict.detail})")
    if verdict.split:  # it moved, and the cluster is in pieces: not a success
        raise CommandRefusedError(f"the cluster split: {verdict.describe()}")
    return in_localization_frame(Pose(verdict.dst, verdict.orientation), origin)


def _status_after_move(session: Session, mobile: int) -> None:
    session.request(select(mobile))
    (obs,) = session.request(frames.make("Status")).replies
    ev = obs.event
    assert isinstance(ev, StatusReport)
    if ev.localized or ev.error != ErrorCode.NONE:
        raise CommandRefusedError(
            f"module {mobile} does not report a move (status: "
            f"{'localized' if ev.localized else 'unlocalized'}, last error {ev.error})")
