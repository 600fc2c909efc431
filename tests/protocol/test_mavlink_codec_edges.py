"""MAVLink framing at its edges: the highest module id, the results that
stand for the legacy ACK N and ACK ~, the sequence number's wrap, Select(0)."""

from __future__ import annotations

import pytest

from hexbot.errors import FrameError
from hexbot.protocol import frames, hexbot_mavlink, wire
from hexbot.protocol.mavlink_codec import FramedParser, MavAck, MavlinkEncoder, describe_mavlink_tx
from tests.protocol.test_mavlink_codec import module, sent


@pytest.mark.parametrize("target", [0, 1, wire.MAX_MODULE_ID])
def test_every_module_id_can_be_addressed(target):
    data = MavlinkEncoder().encode(frames.make("LOn"), target=target)
    msg = module(0).decode(bytearray(data))
    assert (msg.target_system, msg.code) == (target, frames.make("LOn").code)


@pytest.mark.parametrize("target", [-1, wire.MAX_MODULE_ID + 1])
def test_a_target_beyond_the_module_ids_is_refused(target):
    with pytest.raises(FrameError, match="target module"):
        MavlinkEncoder().encode(frames.make("LOn"), target=target)


@pytest.mark.parametrize(("result", "did_nothing", "timed_out"), [
    (hexbot_mavlink.HEXBOT_RESULT_DONE, False, False),
    (hexbot_mavlink.HEXBOT_RESULT_UNUSED_CODE, True, False),  # legacy ACK N
    (hexbot_mavlink.HEXBOT_RESULT_CONTROL_TIMEOUT, False, True),  # legacy ACK ~
])
def test_ack_results_read_as_their_legacy_acks(result, did_nothing, timed_out):
    code = frames.make("SxOffAll").code
    (ev,) = FramedParser().feed(sent(module(4), hexbot_mavlink.MAVLink_hexbot_ack_message(
        code, 1, result, 0)))
    assert isinstance(ev, MavAck)
    assert (ev.did_nothing, ev.timed_out, ev.module) == (did_nothing, timed_out, 4)


def test_the_sequence_number_wrapping_from_255_to_0_loses_nothing():
    mav = module(6)
    mav.seq = 254
    stream = b"".join(sent(mav, hexbot_mavlink.MAVLink_hexbot_ack_message(44, 1, 0, 0))
                      for _ in range(4))  # seq 254, 255, 0, 1
    events = FramedParser().feed(stream)
    assert [e.mav.seq for e in events] == [254, 255, 0, 1]
    assert [e.mav.missed for e in events] == [0, 0, 0, 0]


def test_a_gap_across_the_wrap_counts_the_lost_replies():
    mav = module(6)
    mav.seq = 255
    first = sent(mav, hexbot_mavlink.MAVLink_hexbot_ack_message(44, 1, 0, 0))
    sent(mav, hexbot_mavlink.MAVLink_hexbot_ack_message(44, 1, 0, 0))  # seq 0, lost
    third = sent(mav, hexbot_mavlink.MAVLink_hexbot_ack_message(44, 1, 0, 0))
    assert [e.mav.missed for e in FramedParser().feed(first + third)] == [0, 1]


def test_select_all_is_described_with_its_id_0():
    data = MavlinkEncoder().encode(frames.select([0]))
    assert describe_mavlink_tx(data) == "MAV to the selected seq 0: Select(0)"
