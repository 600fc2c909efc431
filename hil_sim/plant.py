"""The plant: where the modules are and when their actuators move them.

Positions and orientations live on the Table 4-1 lattice. The control board's
outputs arrive as changes of joints (solenoids) and magnets; the plant turns
them into rotations or refusals following Tables 3-1 and 4-3. The model and
its tolerances are documented in docs/plant-model.md; in short:

* A magnet *pulse* is a stretch of time during which a module's six magnets
  hold one pattern. A **mobile** pulse is two adjacent sides negative and the
  rest off: its pivot is the joint between those sides. A **substrate** pulse
  is one side negative and an adjacent side positive.
* A mobile pulse of module M about pivot joint j moves M when a neighbour
  sits on the side of j that is its substrate (CW: side j, CCW: side j - 1, in
  global sides), and that neighbour's overlapping pulse repels M (negative on
  the side facing M) and attracts it into the goal (positive on the side
  facing the goal cell); onsets within ONSET_TOLERANCE, both held together
  for MIN_HOLD; at the far end of the contact edge, M's or the substrate's
  joint open from JOINT_LEAD before onset until JOINT_HOLD after it; a closed
  joint at the pivot (M's or the substrate's) to turn about; the goal and the
  three swept cells empty; M not fixed to the base.
* M then lands in the goal cell, its orientation turned by 120 degrees
  (+2 for CW, -2 for CCW). Anything missing gives a "refused" event.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

from hexbot.protocol.simulation import RefusalReason

from .geometry import (
    Cell,
    Rotation,
    facing,
    joint_between,
    neighbor,
    side_towards,
    to_body,
    to_global,
    wrap,
)

OFF, POS, NEG, SHORT = 0, 1, -1, 2
Magnets = tuple[int, int, int, int, int, int]  # body sides 1..6
Joints = tuple[bool, bool, bool, bool, bool, bool]  # body joints 1..6, True = open (energised)
ALL_OFF: Magnets = (OFF,) * 6
ALL_CLOSED: Joints = (False,) * 6


@dataclass(frozen=True)
class Timing:
    """Tolerances of the rotation model, in seconds (see docs/plant-model.md)."""

    onset_tolerance: float = 0.030
    min_hold: float = 0.100
    joint_lead: float = 0.040
    joint_hold: float = 0.030
    resolve_wait: float = 0.500  # how long a finished mobile pulse waits for its substrate's


@dataclass
class Pulse:
    module: int
    magnets: Magnets
    start: int
    end: int | None = None
    used: bool = False

    @property
    def kind(self) -> str:
        neg = [s for s in range(1, 7) if self.magnets[s - 1] == NEG]
        pos = [s for s in range(1, 7) if self.magnets[s - 1] == POS]
        other = [s for s in range(1, 7) if self.magnets[s - 1] == SHORT]
        if other:
            return "other"
        if len(neg) == 2 and not pos and _adjacent(neg[0], neg[1]):
            return "mobile"
        if len(neg) == 1 and len(pos) == 1 and _adjacent(neg[0], pos[0]):
            return "substrate"
        return "other"

    def overlap(self, other: Pulse, now: int) -> tuple[int, int]:
        return max(self.start, other.start), min(_end(self, now), _end(other, now))


def _end(pulse: Pulse, now: int) -> int:
    return now if pulse.end is None else pulse.end


def _adjacent(a: int, b: int) -> bool:
    return wrap(a + 1) == b or wrap(b + 1) == a


@dataclass
class Body:
    """One module's physical state."""

    id: int
    cell: Cell
    orientation: int
    fixed: bool = False
    magnets: Magnets = ALL_OFF
    joints: Joints = ALL_CLOSED
    joint_log: list[tuple[int, Joints]] = field(default_factory=list)
    pulses: list[Pulse] = field(default_factory=list)

    def joint_open_during(self, joint: int, t0: int, t1: int) -> bool:
        """Joint open (True) over all of [t0, t1], judged from the change log."""
        state = False
        for cycle, joints in self.joint_log:
            if cycle <= t0:
                state = joints[joint - 1]
                continue
            if cycle > t1:
                break
            if not joints[joint - 1]:
                return False
        return state

    def joint_closed_at(self, joint: int, t: int) -> bool:
        state = ALL_CLOSED
        for cycle, joints in self.joint_log:
            if cycle > t:
                break
            state = joints
        return not state[joint - 1]


@dataclass
class Plant:
    hz: float
    timing: Timing = field(default_factory=Timing)
    emit: Callable[[int, dict], None] = lambda cycle, event: None
    bodies: dict[int, Body] = field(default_factory=dict)
    cells: dict[Cell, int] = field(default_factory=dict)
    _pending: list[Pulse] = field(default_factory=list)
    geometry_version: int = 0  # bumped by every move: the core's IR routes follow it

    def add(self, module: int, cell: Cell, orientation: int, fixed: bool = False) -> None:
        if cell in self.cells:
            raise ValueError(f"cell {cell} already holds module {self.cells[cell]}")
        self.bodies[module] = Body(module, cell, orientation % 6, fixed)
        self.cells[cell] = module

    def module_at(self, cell: Cell) -> int | None:
        return self.cells.get(cell)

    def next_deadline(self, now: int) -> int | None:
        """The earliest cycle after ``now`` at which step() may decide something
        without a new output change: a finished pulse's resolve_wait running out."""
        wait = self._cycles(self.timing.resolve_wait)
        ends = [p.end + wait for p in self._pending if p.end is not None]
        ends += [p.end + wait for body in self.bodies.values() for p in body.pulses
                 if not p.used and p.end is not None]
        return min((t for t in ends if t > now), default=None)

    def _cycles(self, seconds: float) -> int:
        return round(seconds * self.hz)

    # --- inputs ------------------------------------------------------------

    def set_outputs(self, module: int, cycle: int, joints: Joints, magnets: Magnets) -> None:
        """The control board's actuator outputs changed at ``cycle``."""
        body = self.bodies[module]
        if joints != body.joints:
            body.joints = joints
            body.joint_log.append((cycle, joints))
            horizon = cycle - self._cycles(5.0)  # keep a few seconds of history
            while len(body.joint_log) > 2 and body.joint_log[1][0] < horizon:
                body.joint_log.pop(0)
        if magnets != body.magnets:
            if body.pulses and body.pulses[-1].end is None:
                finished = body.pulses[-1]
                finished.end = cycle
                if finished.kind == "mobile":
                    self._pending.append(finished)
            body.magnets = magnets
            if magnets != ALL_OFF:
                body.pulses.append(Pulse(module, magnets, cycle))
                del body.pulses[:-16]

    def step(self, now: int) -> None:
        """Resolve finished mobile pulses whose substrate side is settled too."""
        wait = self._cycles(self.timing.resolve_wait)
        still: list[Pulse] = []
        for pulse in sorted(self._pending, key=lambda p: (p.end or 0, p.module)):
            partners = self._overlapping(pulse, now)
            if any(p.end is None for p in partners) and now < (pulse.end or now) + wait:
                still.append(pulse)
                continue
            self._resolve(pulse, now)
        self._pending = still
        self._report_lonely_substrates(now)

    # --- the rotation model -------------------------------------------------

    def _neighbours(self, module: int) -> list[int]:
        cell = self.bodies[module].cell
        found = (self.cells.get(neighbor(cell, s)) for s in range(1, 7))
        return [m for m in found if m is not None]

    def _overlapping(self, pulse: Pulse, now: int) -> list[Pulse]:
        result = []
        for other in self._neighbours(pulse.module):
            for candidate in self.bodies[other].pulses:
                start, end = pulse.overlap(candidate, now)
                if start < end:
                    result.append(candidate)
        return result

    def _resolve(self, pulse: Pulse, now: int) -> None:
        body = self.bodies[pulse.module]
        neg = [s for s in range(1, 7) if pulse.magnets[s - 1] == NEG]
        body_joint = joint_between(neg[0], neg[1])
        global_joint = to_global(body_joint, body.orientation)
        t = _end(pulse, now)
        refusals: list[tuple[str, str, dict]] = []
        for direction in ("CW", "CCW"):
            pivot = Rotation(global_joint, direction)  # type: ignore[arg-type]
            verdict = self._judge(body, pulse, pivot, body_joint, now)
            if verdict is None:
                continue
            if verdict[0] == "moved":
                self._move(body, pivot, verdict[2], t, body_joint)
                return
            refusals.append(verdict)
        # Report the most telling reason: a partner that tried beats nobody there.
        refusals.sort(key=lambda r: RefusalReason(r[0]).rank)
        reason, detail, extra = refusals[0] if refusals else (
            "no substrate", f"no module on either side of joint {body_joint}", {})
        self.emit(t, {"event": "refused", "module": body.id, "reason": reason,
                      "detail": detail, "joint": body_joint, **extra})

    def _judge(
        self, body: Body, pulse: Pulse, pivot: Rotation, body_joint: int, now: int
    ) -> tuple[str, str, dict] | None:
        """("moved", "", info) if the rotation happens, else (reason, detail, info)."""
        substrate_id = self.cells.get(pivot.substrate_cell(body.cell))
        name = pivot.direction
        if substrate_id is None:
            return ("no substrate", f"{name}: no module on side {pivot.substrate_side}", {})
        sub = self.bodies[substrate_id]
        goal = pivot.goal_cell(body.cell)
        face_m = to_body(facing(pivot.substrate_side), sub.orientation)
        face_goal_global = side_towards(sub.cell, goal)
        assert face_goal_global is not None
        face_g = to_body(face_goal_global, sub.orientation)
        partners = [
            p for p in sub.pulses if p.start < _end(pulse, now) and pulse.start < _end(p, now)
        ]
        if not partners:
            return ("no substrate", f"{name}: substrate {sub.id} did not actuate", {})
        matching = [
            p
            for p in partners
            if p.kind == "substrate" and p.magnets[face_m - 1] == NEG
            and p.magnets[face_g - 1] == POS
        ]
        info = {"substrate": sub.id, "direction": name}
        if not matching:
            return ("wrong polarity",
                    f"{name}: substrate {sub.id} must drive side {face_m} negative and "
                    f"side {face_g} positive", info)
        partner = matching[0]
        partner.used = True
        tol = self._cycles(self.timing.onset_tolerance)
        hold = self._cycles(self.timing.min_hold)
        start, end = pulse.overlap(partner, now)
        if abs(pulse.start - partner.start) > tol:
            return ("timing", f"{name}: magnet onsets {self._ms(pulse.start - partner.start)} ms "
                    f"apart (tolerance {self.timing.onset_tolerance * 1000:.0f} ms)", info)
        if end - start < hold:
            return ("timing", f"{name}: magnets held together {self._ms(end - start)} ms "
                    f"(at least {self.timing.min_hold * 1000:.0f} ms needed)", info)
        if body.fixed:
            return ("fixed to base", f"module {body.id} is fixed to the base", info)
        # The far vertex of the contact edge must let go (one of its two pins
        # out); the pivot vertex must hold (one of its two pins in).
        contact = to_body(pivot.substrate_side, body.orientation)
        far_m = wrap(contact + 1) if name == "CW" else contact
        far_s = wrap(face_m) if face_g == wrap(face_m + 1) else wrap(face_m + 1)
        lead = self._cycles(self.timing.joint_lead)
        keep = self._cycles(self.timing.joint_hold)
        if not (body.joint_open_during(far_m, pulse.start, pulse.start + keep)
                or sub.joint_open_during(far_s, pulse.start, pulse.start + keep)):
            return ("latched joint", f"{name}: joint J{far_m} of module {body.id} and joint "
                    f"J{far_s} of module {sub.id} hold the far end of the contact edge "
                    "while the magnets act", info)
        if not (body.joint_open_during(far_m, pulse.start - lead, pulse.start + keep)
                or sub.joint_open_during(far_s, pulse.start - lead, pulse.start + keep)):
            return ("timing", f"{name}: the far joint opened less than "
                    f"{self.timing.joint_lead * 1000:.0f} ms before the magnets", info)
        sub_pivot = joint_between(face_m, face_g)
        if not (body.joint_closed_at(body_joint, pulse.start)
                or sub.joint_closed_at(sub_pivot, pulse.start)):
            return ("no axle", f"{name}: both pivot joints (J{body_joint} of {body.id}, "
                    f"J{sub_pivot} of {sub.id}) are open", info)
        blocked = [c for c in (goal, *pivot.swept_cells(body.cell)) if c in self.cells]
        if blocked:
            return ("occupied cell",
                    f"{name}: cells {[list(c) for c in blocked]} must be empty",
                    {**info, "cells": [list(c) for c in blocked]})
        return ("moved", "", info)

    def _move(self, body: Body, pivot: Rotation, info: dict, t: int, body_joint: int) -> None:
        source = body.cell
        target = pivot.goal_cell(source)
        groups_before = len(self._groups())
        del self.cells[source]
        self.cells[target] = body.id
        body.cell = target
        body.orientation = (body.orientation + pivot.turn) % 6
        self.geometry_version += 1
        # The mechanics allow a cut vertex to rotate away; the cluster then
        # lies in pieces on the table, which the trace must say.
        groups = self._groups()
        if len(groups) > groups_before:
            info = {**info, "split": sorted(m for g in groups if body.id not in g for m in g)}
        self.emit(t, {"event": "moved", "module": body.id, "from": list(source),
                      "to": list(target), "orientation": body.orientation,
                      "joint": body_joint, **info})

    def _groups(self) -> list[set[int]]:
        """The modules in touching groups (connected components of the cells)."""
        seen: set[Cell] = set()
        groups = []
        for start in self.cells:
            if start in seen:
                continue
            seen.add(start)
            stack, group = [start], set()
            while stack:
                cell = stack.pop()
                group.add(self.cells[cell])
                for side in range(1, 7):
                    nb = neighbor(cell, side)
                    if nb in self.cells and nb not in seen:
                        seen.add(nb)
                        stack.append(nb)
            groups.append(group)
        return groups

    def _report_lonely_substrates(self, now: int) -> None:
        """A substrate pulse nobody used: say so once, after its mobile had time to finish."""
        wait = self._cycles(self.timing.resolve_wait)
        for body in self.bodies.values():
            for pulse in body.pulses:
                if pulse.used or pulse.end is None or now < pulse.end + wait:
                    continue
                if any(p.end is None or p in self._pending for p in self._overlapping(pulse, now)):
                    continue  # a mobile pulse that may still claim it
                pulse.used = True
                if pulse.kind != "substrate":
                    continue
                neg = next(s for s in range(1, 7) if pulse.magnets[s - 1] == NEG)
                faced = self.cells.get(neighbor(body.cell, to_global(neg, body.orientation)))
                self.emit(pulse.end, {
                    "event": "refused", "module": faced, "substrate": body.id,
                    "reason": "wrong polarity" if faced is not None else "no substrate",
                    "detail": f"substrate {body.id} pushed on side {neg} but no mobile pulse "
                              "of the module there matched it"
                              if faced is not None else
                              f"substrate {body.id} pushed on side {neg}, where nobody is",
                })

    def _ms(self, cycles: int) -> int:
        return round(cycles * 1000 / self.hz)
