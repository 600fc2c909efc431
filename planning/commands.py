"""From planned moves to firmware commands (layer 5 on the wire).

Frame convention (see docs/planning.md, "Firmware commands"):

* Joint numbers in commands are in the receiving module's **body frame**;
  :func:`hexbot.protocol.rotation.body_index` is the only conversion. A module's orientation is the
  firmware's ``Yref`` (clockwise sixth-turns of its body from the global
  frame): ``body = ((global - 1 - Yref) mod 6) + 1``.
* Both halves of a rotation carry the pivot joint as Table 4-3 numbers it,
  i.e. as a joint of the **mobile** module (``mi``), and as the thesis'
  substrate routines expect (``SCW(i)`` drives ``S(i-3)`` and ``S(i-2)``
  relative to that same ``i``), each converted to its own body frame.
* Timings are Table 3-1's in 10 ms ticks, rounded half up (45 ms -> 5,
  95 ms -> 10), which keeps both halves at 220 ms, the thesis' rotation time.

Styles:

* ``combined`` (default, the thesis' one-message rotation, codes 67/68):
  ``Select(m) SetRole(mobile)``, ``Select(s) SetRole(substrate)`` (each only
  when the role changes), then ``Select(m, s)`` and ``CW``/``CCW``.
* ``single``: ``Select(s) SCW/SCCW`` then ``Select(m) MCW/MCCW`` (codes 21-24);
  the two halves are not simultaneous, so this is for bench tests only.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

from hexbot.planning.configuration import Configuration
from hexbot.planning.moves import Move
from hexbot.planning.plan import Plan, apply_step
from hexbot.protocol.codes import Role
from hexbot.protocol.frames import Command, encode_pc, make, select
from hexbot.protocol.lattice import to_global
from hexbot.protocol.rotation import (  # noqa: F401 - body_index is part of this module's API
    THESIS_TIMINGS,
    body_index,
    combined_rotation,
    single_rotation,
)

Style = Literal["combined", "single"]

#: Table 3-1 delays (t1, t2, t3) in 10 ms ticks, per direction and role.
TIMINGS = THESIS_TIMINGS


def global_index(body: int, orientation: int) -> int:
    """Inverse of :func:`body_index`."""
    return to_global(body, orientation)


@dataclass(frozen=True)
class MoveCommands:
    """The frames that perform one move, and the move they perform."""

    move: Move
    commands: tuple[Command, ...]

    def frames(self) -> list[bytes]:
        return [encode_pc(c) for c in self.commands]


def move_commands(
    move: Move,
    mobile_orientation: int,
    substrate_orientation: int,
    style: Style = "combined",
    roles: dict[int, int] | None = None,
) -> list[Command]:
    """Commands for one move. ``roles`` (module id -> role last set) is updated
    so that ``SetRole`` is only sent when a module's role changes."""
    m, s = move.module, move.substrate_module
    if style == "single":
        return [select([s]),
                single_rotation(move.direction, "substrate", move.joint, substrate_orientation),
                select([m]),
                single_rotation(move.direction, "mobile", move.joint, mobile_orientation)]
    roles = {} if roles is None else roles
    out: list[Command] = []
    for module_id, role in ((m, int(Role.MOBILE)), (s, int(Role.SUBSTRATE))):
        if roles.get(module_id) != role:
            out += [select([module_id]), make("SetRole", role)]
            roles[module_id] = role
    out += [select([m, s]), combined_rotation(move.direction, move.joint, mobile_orientation,
                                              substrate_orientation)]
    return out


def plan_to_commands(plan: Plan, style: Style = "combined") -> list[list[MoveCommands]]:
    """Per time step, per move: the commands that execute the plan.

    Orientations are replayed from ``plan.initial`` (each rotation turns the
    mobile module by two sides), so every joint number is in the body frame
    the module has when the command reaches it.
    """
    config: Configuration = plan.initial
    roles: dict[int, int] = {}
    out: list[list[MoveCommands]] = []
    for step in plan.steps:
        step_out = []
        for move in step.moves:
            mob = config[move.src].orientation
            sub = config[move.substrate].orientation
            cmds = move_commands(move, mob, sub, style, roles)
            step_out.append(MoveCommands(move, tuple(cmds)))
        out.append(step_out)
        config = apply_step(config, step)
    return out


def command_json(command: Command) -> dict[str, object]:
    return {"code": command.code, "args": list(command.args)}
