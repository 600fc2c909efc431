"""Rotation frames: Table 3-1 timings and body-frame joints, built once."""

import pytest

from hexbot.errors import FrameError
from hexbot.protocol import frames
from hexbot.protocol.rotation import body_index, combined_rotation, single_rotation


def test_thesis_pair_rotation_frame():
    # pair scenario: mobile and substrate both at Yref 0, CW about joint 4
    cmd = combined_rotation("cw", 4, 0, 0)
    assert cmd == frames.make("CW", 4, 8, 4, 10, 4, 8, 5, 9)


def test_each_half_in_its_own_body_frame():
    cmd = combined_rotation("CCW", 1, mobile_orientation=2, substrate_orientation=5)
    si, mi = cmd.args[0], cmd.args[4]
    assert (si, mi) == (2, 5)
    assert cmd.args[1:4] == (8, 5, 9) and cmd.args[5:8] == (8, 4, 10)


def test_single_halves():
    assert single_rotation("cw", "mobile", 4, 1) == frames.make("MCW", 3, 8, 5, 9)
    assert single_rotation("ccw", "substrate", 4, 0) == frames.make("SCCW", 4, 8, 5, 9)


@pytest.mark.parametrize("args", [(0, 0), (7, 0), (3, 6), (3, -1)])
def test_bad_joint_or_orientation(args):
    with pytest.raises(FrameError):
        body_index(*args)


def test_bad_direction():
    with pytest.raises(FrameError, match="cw or ccw"):
        combined_rotation("left", 1, 0, 0)
