"""A half reply is flushed as garbage after a quiet second on the line, and
only then: a reader that ran late must not cut a reply in two."""

from __future__ import annotations

from hexbot.host.host import QUIET_FLUSH_S, PortDecoder
from hexbot.protocol import parser

REPLY = parser.reply_ack(69, "S", 1)  # b"\n\r\n\rS01: ACKE\n\r"
HALF = len(REPLY) // 2 + 1


def kinds(events):
    return [type(ev).__name__ for _, ev in events]


def whole(events) -> bool:
    """Module 1's ACK came whole (a cut one reads without its id)."""
    return any(type(ev).__name__ == "Ack" and ev.module == 1 for _, ev in events)


def test_a_reply_read_in_two_halves_far_apart_is_one_reply_live():
    # the reader got the first half, then ran 5 s late (no read in between
    # found the port empty): the line had no gap, so the reply is whole
    dec = PortDecoder(live=True)
    assert dec.feed(10.0, REPLY[:HALF]) == []
    events = dec.feed(15.0, REPLY[HALF:])
    assert kinds(events) == ["Ack"]
    assert events[0][1].module == 1 and events[0][1].code == 69


def test_a_half_reply_is_garbage_after_a_quiet_second_seen_by_empty_reads():
    dec = PortDecoder(live=True)
    dec.feed(10.0, REPLY[:HALF])
    assert dec.quiet(10.05) == []  # the first read that found nothing
    assert dec.quiet(10.05 + QUIET_FLUSH_S) == []  # quiet for exactly the limit
    held = dec.quiet(10.1 + QUIET_FLUSH_S)
    assert kinds(held) == ["Garbage"]
    assert held[0][0] == 10.05 + QUIET_FLUSH_S
    # the rest, when it comes, is garbage too: the reply was cut on the line
    assert not whole(dec.feed(20.0, REPLY[HALF:]))


def test_a_late_empty_read_alone_does_not_flush():
    # one empty read long after the bytes (the reader was late to look):
    # quiet is counted from it, not from the bytes' read time
    dec = PortDecoder(live=True)
    dec.feed(10.0, REPLY[:HALF])
    assert dec.quiet(30.0) == []
    assert whole(dec.feed(30.2, REPLY[HALF:]))


def test_a_replay_flushes_on_the_records_times():
    # a capture's records carry their times: a gap longer than the quiet
    # second between two records cuts the reply, as it did live
    dec = PortDecoder()
    dec.feed(10.0, REPLY[:HALF])
    events = dec.feed(10.0 + QUIET_FLUSH_S + 0.5, REPLY[HALF:])
    assert kinds(events)[0] == "Garbage" and not whole(events)
    dec = PortDecoder()
    dec.feed(10.0, REPLY[:HALF])
    assert whole(dec.feed(10.5, REPLY[HALF:]))
