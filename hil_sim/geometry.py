"""Hex-lattice geometry the simulator needs, in the thesis' axial coordinates.

Cells, sides, orientations and the IR selector (Tables 4-1 and 3-5) and the
rotations of Table 4-3 are defined once in :mod:`hexbot.protocol.lattice` and
:mod:`hexbot.protocol.rotation_geometry`; this module gathers them for the
simulator.
"""

from __future__ import annotations

from hexbot.protocol.lattice import (  # noqa: F401 - re-exported for the simulator
    CENTRE,
    CHANNEL_SIDE,
    SIDE_CHANNEL,
    SIDE_OFFSETS,
    SIDES,
    Cell,
    distance,
    facing,
    neighbor,
    side_towards,
    to_body,
    to_global,
    wrap,
)
from hexbot.protocol.rotation_geometry import (  # noqa: F401 - Table 4-3
    Direction,
    Rotation,
    joint_between,
)
