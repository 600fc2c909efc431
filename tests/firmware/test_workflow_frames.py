"""Rotations in a cluster localized from a module that is not the plant's
origin: the poses are in the localization's frame (the reference at (0, 0)
facing 0), the plant's verdict in the scenario's; a check must compare like
with like, and never make a second origin."""

from __future__ import annotations

import pytest
from fwsim import Bench, scenario_file

from hexbot.host import workflows
from hexbot.protocol.rotation_geometry import Rotation

# reference 3 turned by two sides, away from the scenario's origin
TRIO = [(1, (0, 0), 0), (2, (-1, 1), 0), (3, (1, 0), 2)]


def a_legal_rotation(poses, mobile: int, substrate: int) -> tuple[str, int]:
    taken = {p.cell for p in poses.values()}
    for direction in ("CW", "CCW"):
        for joint in range(1, 7):
            r = Rotation(joint, direction)
            if (r.substrate_cell(poses[mobile].cell) == poses[substrate].cell
                    and r.goal_cell(poses[mobile].cell) not in taken):
                return direction, joint
    raise AssertionError("no rotation of module 2 about module 1")


@pytest.mark.parametrize("verify", [workflows.Verify.PLANT, workflows.Verify.LOCALIZE])
def test_a_rotation_is_verified_in_the_frame_of_the_localization(images, tmp_path, verify):
    bench = Bench.boot(scenario_file(tmp_path, TRIO, base=3))
    poses = workflows.localize(bench.session, 3)
    assert poses[3].cell == (0, 0) and poses[3].orientation == 0
    assert poses[1].cell != (0, 0)  # the frames differ
    direction, joint = a_legal_rotation(poses, 2, 1)
    result = workflows.rotate(bench.session, direction, joint, 2, 1, verify=verify)
    assert result.got == result.expected
    model = bench.host.model
    assert model.module(3).position == (0, 0)  # still the only origin
    assert model.module(1).position == poses[1].cell
