"""From planned moves to firmware commands (layer 5 on the wire).

Frame convention (see docs/planning.md, "Firmware commands"):

* Joint numbers in commands are in the receiving module's **body frame**;
  :func:`body_index` is the only conversion. A module's orientation is the
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
from hexbot.planning.hexlattice import Direction
from hexbot.planning.moves import Move
from hexbot.planning.plan import Plan, apply_step
from hexbot.protocol.frames import Command, encode_pc, make, select

Style = Literal["combined", "single"]

ROLE_MOBILE = 1
ROLE_SUBSTRATE = 2

#: Table 3-1 delays (t1, t2, t3) in 10 ms ticks, per direction and role.
TIMINGS: dict[tuple[Direction, str], tuple[int, int, int]] = {
    ("CW", "mobile"): (8, 5, 9),  # 80, 45, 90 ms
    ("CW", "substrate"): (8, 4, 10),  # 80, 40, 95 ms
    ("CCW", "mobile"): (8, 4, 10),  # 80, 40, 95 ms
    ("CCW", "substrate"): (8, 5, 9),  # 80, 45, 90 ms
}


def body_index(global_index: int, orientation: int) -> int:
    """A joint or side number of the global frame in a module's body frame."""
    return (global_index - 1 - orientation) % 6 + 1


def global_index(body: int, orientation: int) -> int:
    """Inverse of :func:`body_index`."""
    return (body - 1 + orientation) % 6 + 1


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
    mi = body_index(move.joint, mobile_orientation)
    si = body_index(move.joint, substrate_orientation)
    mt = TIMINGS[(move.direction, "mobile")]
    st = TIMINGS[(move.direction, "substrate")]
    m, s = move.module, move.substrate_module
    if style == "single":
        sub_name = "SCW" if move.direction == "CW" else "SCCW"
        mob_name = "MCW" if move.direction == "CW" else "MCCW"
        return [select([s]), make(sub_name, si, *st), select([m]), make(mob_name, mi, *mt)]
    roles = {} if roles is None else roles
    out: list[Command] = []
    for module_id, role in ((m, ROLE_MOBILE), (s, ROLE_SUBSTRATE)):
        if roles.get(module_id) != role:
            out += [select([module_id]), make("SetRole", role)]
            roles[module_id] = role
    out += [select([m, s]), make(move.direction, si, *st, mi, *mt)]
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
