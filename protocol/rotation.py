"""Rotation commands: Table 3-1's timings and body-frame joint indices.

The PC thinks in lattice (global) joints; a module's firmware takes joint
numbers in its own body frame, turned by its orientation (Yref). Both the
console and the planner build their rotation frames here.

Table 3-1 in 10 ms ticks. 45 ms and 95 ms are not whole ticks: rounded half
up (5 and 10), so each step lasts at least as long as the thesis measured
and both halves still take 220 ms, the thesis' rotation time.
"""

from __future__ import annotations

from typing import Literal

from hexbot.errors import FrameError
from hexbot.protocol.frames import Command, make
from hexbot.protocol.lattice import to_body
from hexbot.protocol.rotation_geometry import Direction

RoleName = Literal["mobile", "substrate"]
Timing = tuple[int, int, int]  # t1, t2, t3 in ticks

THESIS_TIMINGS: dict[tuple[Direction, RoleName], Timing] = {
    ("CW", "mobile"): (8, 5, 9),  # 80, 45, 90 ms
    ("CW", "substrate"): (8, 4, 10),  # 80, 40, 95 ms
    ("CCW", "mobile"): (8, 4, 10),  # 80, 40, 95 ms
    ("CCW", "substrate"): (8, 5, 9),  # 80, 45, 90 ms
}


def direction_of(text: str) -> Direction:
    upper = text.upper()
    if upper not in ("CW", "CCW"):
        raise FrameError(f"direction must be cw or ccw, got {text!r}")
    return upper  # type: ignore[return-value]


def body_index(global_index: int, orientation: int) -> int:
    """A joint or side number of the lattice frame in a module's body frame."""
    if not 1 <= global_index <= 6:
        raise FrameError(f"joint must be 1..6, got {global_index}")
    if not 0 <= orientation <= 5:
        raise FrameError(f"orientation (Yref) must be 0..5, got {orientation}")
    return to_body(global_index, orientation)


def combined_rotation(direction: str, global_joint: int, mobile_orientation: int,
                      substrate_orientation: int, substrate: Timing | None = None,
                      mobile: Timing | None = None) -> Command:
    """Code 67 (CW) or 68 (CCW): both halves of a rotation of the mobile module
    about ``global_joint`` (numbered as a joint of the mobile, Table 4-3); each
    half carries that joint in its own module's body frame."""
    d = direction_of(direction)
    st = substrate or THESIS_TIMINGS[(d, "substrate")]
    mt = mobile or THESIS_TIMINGS[(d, "mobile")]
    si = body_index(global_joint, substrate_orientation)
    mi = body_index(global_joint, mobile_orientation)
    return make(d, si, *st, mi, *mt)


def single_rotation(direction: str, role: RoleName, global_joint: int, orientation: int,
                    timing: Timing | None = None) -> Command:
    """One half alone: MCW/MCCW for the mobile, SCW/SCCW for the substrate."""
    d = direction_of(direction)
    name = ("M" if role == "mobile" else "S") + d
    return make(name, body_index(global_joint, orientation), *(timing or THESIS_TIMINGS[(d, role)]))
