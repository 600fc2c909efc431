"""The PC's MAVLink framing without I/O: frames packed by the generated
dialect, read from a stream mixed with legacy replies and noise."""

from __future__ import annotations

import io

from hexbot.protocol import frames, hexbot_mavlink, parser
from hexbot.protocol.mavlink_codec import (
    FramedParser,
    MavAck,
    MavErrorReply,
    MavlinkEncoder,
    MavStatus,
    describe_mavlink_tx,
)


def module(ident: int):
    """A module's MAVLink end: pymavlink numbers what it sends."""
    return hexbot_mavlink.MAVLink(io.BytesIO(), srcSystem=ident, srcComponent=1)


def sent(mav, msg) -> bytes:
    mav.file.seek(0)
    mav.file.truncate()
    mav.send(msg)
    return mav.file.getvalue()


def ack(mav, code: int = 44, result: int = 0, error: int = 0) -> bytes:
    return sent(mav, hexbot_mavlink.MAVLink_hexbot_ack_message(code, 1, result, error))


def test_a_command_is_the_dialects_frame_with_unused_arguments_left_off():
    data = MavlinkEncoder().encode(frames.make("JxOpen", 3), target=2)
    msg = module(0).decode(bytearray(data))
    assert (msg.target_system, msg.code, list(msg.args)) == (2, 1, [3, 0, 0, 0, 0, 0, 0, 0])
    assert len(data) == 12 + 3  # target, code, one argument: trailing zeros truncated
    assert describe_mavlink_tx(data) == "MAV to 2 seq 0: JxOpen(3)"
    encoder = MavlinkEncoder()
    encoder.encode(frames.make("LOn"))
    select = encoder.encode(frames.select([4, 5]))
    assert describe_mavlink_tx(select) == "MAV to the selected seq 1: Select(4, 5)"


def test_mavlink_replies_among_legacy_ones_in_the_order_they_came():
    mav = module(3)
    stream = (b"\n\r\n\rM: ACK," + b"\n\r" + ack(mav) + ack(mav, 1, 1, 1)
              + sent(mav, hexbot_mavlink.MAVLink_hexbot_status_message(
                  0xABCD, 2, 1, -3, 2, 1, 0, 4)))
    p = FramedParser()
    events = [e for b in stream for e in p.feed(bytes([b]))]  # byte by byte, as a link does
    assert [type(e) for e in events] == [parser.Ack, MavAck, MavErrorReply, MavStatus]
    assert (events[1].code, events[1].module, events[1].role) == (44, 3, "M")
    assert (events[2].code, events[2].reason) == (1, 1)
    status = events[3]
    assert (status.module_id, status.role, status.x, status.crc_errors) == (3, "S", -3, 4)
    assert [e.mav.seq for e in events[1:]] == [0, 1, 2]


def test_half_a_legacy_text_before_a_mavlink_reply_is_garbage_reported_first():
    # a text cut off by the next module's MAVLink reply never ends: the
    # monitor must print it as garbage before that reply, not after
    stream = b"\n\r\n\rCOMM. LISTENING " + b"X" * 60 + b"\n\r" + ack(module(3))
    p = FramedParser()
    events = [e for b in stream for e in p.feed(bytes([b]))]
    assert [type(e) for e in events] == [parser.Garbage, MavAck]
    assert b"COMM. LISTENING XXXX" in events[0].raw
    assert p.flush() == []


def test_a_sequence_gap_names_the_lost_replies():
    mav = module(5)
    first = ack(mav)
    ack(mav)
    ack(mav)  # two replies lost on the way
    fourth = ack(mav)
    events = FramedParser().feed(first + fourth)
    assert [e.mav.missed for e in events] == [0, 2]


def test_a_frame_with_a_bad_crc_is_garbage_not_a_reply():
    bad = bytearray(ack(module(1)))
    bad[10] ^= 0x01
    p = FramedParser()
    events = p.feed(bytes(bad)) + p.flush()
    assert not any(isinstance(e, MavAck) for e in events)
    assert isinstance(events[-1], parser.Garbage)


def test_0xfd_inside_a_legacy_status_does_not_hold_it_back():
    reply = b"\n\r\n\rM01: STA\x01M\x01\xfd\x02\x00\x00" + b"0123abcd" + b"\n\r"
    (status,) = FramedParser().feed(reply)
    assert isinstance(status, parser.StatusReport) and status.x == -3
