"""Bytes that start other frames are arguments inside a frame (firmware
mutation audit, session 32): 0xFD inside a legacy PC frame, the board
link's restart bytes inside a board frame."""

from __future__ import annotations

import pytest
from fwsim import Bench, pc_frame, single_ack

from hexbot.protocol import parser


@pytest.mark.parametrize("frame, code", [
    pytest.param(pc_frame(21, 1, 0xFD, 0, 0), 21, id="MCW-t1-253"),
    pytest.param(pc_frame(67, 1, 0xFD, 0, 0, 1, 0, 0, 0), 67, id="CW-st1-253"),
])
def test_an_argument_byte_0xfd_inside_a_legacy_frame_is_an_argument(single: Bench, frame, code):
    # 0xFD starts a MAVLink frame only between frames (docs/protocol.md: "while
    # neither is under way the comm board routes a byte by that value"); a
    # delay of 253 ticks is a legacy argument like any other.
    single_ack(single.frame(frame, timeout=60.0), code)


@pytest.mark.parametrize("args", [(1, 82, 10, 10), (2, 10, 76, 82)], ids=["t1-R", "t2-L-t3-R"])
def test_link_bytes_inside_a_board_frame_are_arguments(single: Bench, args):
    # 'R' (82) and 'L' (76) are the boards' link bytes only between frames;
    # as a delay of a rotation they must reach the control board as such.
    (ack,) = single.command("MCW", *args)
    assert isinstance(ack, parser.Ack) and ack.code == 21 and not ack.timed_out, ack
    msgs = [e for e in parser.parse_all(single.debug_read(1))
            if isinstance(e, parser.ControlMessage)]
    assert [(m.code, m.args) for m in msgs] == [(21, args)]
