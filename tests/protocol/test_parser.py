"""The streaming reply parser: golden replies, byte-at-a-time, noise."""

from hypothesis import given, settings
from hypothesis import strategies as st

from hexbot.protocol import parser as p
from hexbot.protocol.parser import ReplyParser, parse_all

THESIS_SUBSTRATE_ACK = b"\n\r\n\rS: ACK\x15\n\r"  # PRE(); 'S',':',' '; 'A','C','K',21; 10,13


def test_thesis_ack_with_role():
    (ev,) = parse_all(THESIS_SUBSTRATE_ACK)
    assert isinstance(ev, p.Ack)
    assert (ev.code, ev.role, ev.module) == (21, "S", None)


def test_addressed_prefix_carries_module_id():
    (ev,) = parse_all(b"\n\r\n\rM07: ACK\x19\n\r")
    assert (ev.role, ev.module, ev.code) == ("M", 7, 25)


def test_ids_from_100_take_three_digits_byte_by_byte():
    parser = ReplyParser()
    data = (p.reply_ack(20, "M", 255) + p.reply_status(200, "S", False, 0, 0, 0, 0, "S", 0)
            + p.reply_ack(20, "S", 9))
    assert p.reply_ack(20, "M", 255).startswith(b"\n\r\n\rM255: ")
    events = [e for b in data for e in parser.feed(bytes([b]))] + parser.flush()
    assert [(type(e), getattr(e, "module", None)) for e in events] == [
        (p.Ack, 255), (p.StatusReport, None), (p.Ack, 9)]
    assert events[1].module_id == 200 and events[1].prefix_role == "S"


def test_timeout_and_nothing_acks():
    a, b = parse_all(b"\n\r\n\rM: ACK~\n\r\n\r\n\rM: ACKN\n\r")
    assert a.timed_out and not a.did_nothing
    assert b.did_nothing


def test_control_debug_port_ack_and_msg():
    data = b"\n\r\n\rACK\x15\n\rMSG\x15\x04\x08\x04\x09\n\r"
    ack, msg = parse_all(data)
    assert ack.code == 21 and ack.role is None
    assert isinstance(msg, p.ControlMessage)
    assert (msg.code, msg.args) == (21, (4, 8, 4, 9))


def test_boot_texts_with_tail():
    data = (b"\n\r\n\rCOMM. BOARD READY\n\rCTR. BOARD READY ID=03 FW=0.1.0\n\r"
            b"CTR. LISTENING\n\rCOMM. LISTENING\n\r")
    events = parse_all(data)
    assert [e.phrase for e in events] == [
        "COMM. BOARD READY", "CTR. BOARD READY", "CTR. LISTENING", "COMM. LISTENING"]
    assert events[1].tail == "ID=03 FW=0.1.0"


def test_localization_report():
    data = b"\n\r\n\rLOCALIZED\n\rSide: 4\n\rYref: 2\n\rPos: -01+01\n\r"
    loc, side, yref, pos = parse_all(data)
    assert loc.phrase == "LOCALIZED"
    assert side.side == 4 and yref.yref == 2 and (pos.x, pos.y) == (-1, 1)


def test_status_and_error_replies():
    data = p.reply_status(5, "M", True, -2, 3, 4, 0, prefix_role="M") + p.reply_error(1, 1, "S")
    sta, err = parse_all(data)
    assert (sta.module_id, sta.role, sta.localized, sta.x, sta.y, sta.yref) == (5, "M", True, -2,
                                                                                3, 4)
    assert (err.code, err.reason, err.role) == (1, 1, "S")
    assert "ARG_RANGE" in err.describe()


def test_status_carries_the_schema_and_older_firmware_none():
    new = p.reply_status(5, "S", True, 1, -1, 2, 0, prefix_role="S", schema=0x0123ABCD)
    old = p.reply_status(6, "M", False, 0, 0, 0, 0, prefix_role="M")
    assert len(new) == len(old) + 8
    first, second = parse_all(new + old)
    assert (first.module_id, first.schema) == (5, 0x0123ABCD)
    assert first.raw == new[new.index(b"STA"):]
    assert (second.module_id, second.schema) == (6, None)
    for data in (new, old):  # either format, a byte at a time
        parser = ReplyParser()
        events = [e for b in data for e in parser.feed(bytes([b]))] + parser.flush()
        assert events == parse_all(data)


def test_status_with_a_damaged_schema_is_not_a_status():
    bad = p.reply_status(5, "S", True, 1, -1, 2, 0, schema=0x0123ABCD).replace(b"0123", b"01\x0023")
    assert not any(isinstance(e, p.StatusReport) for e in parse_all(bad))


def test_byte_at_a_time_equals_whole():
    data = THESIS_SUBSTRATE_ACK + b"\n\r\n\rLOCALIZED\n\rSide: 1\n\r"
    parser = ReplyParser()
    one = []
    for b in data:
        one += parser.feed(bytes([b]))
    one += parser.flush()
    assert one == parse_all(data)


def test_junk_becomes_garbage_before_the_next_event():
    events = parse_all(b"\x00\xffAC" + THESIS_SUBSTRATE_ACK)
    assert isinstance(events[0], p.Garbage) and events[0].raw == b"\x00\xffAC"
    assert isinstance(events[1], p.Ack) and events[1].code == 21


def test_truncated_reply_then_valid():
    events = parse_all(b"\n\r\n\rM: AC" + THESIS_SUBSTRATE_ACK)
    assert [type(e) for e in events] == [p.Garbage, p.Ack]


def test_half_reply_is_held_until_flush():
    parser = ReplyParser()
    assert parser.feed(b"\n\r\n\rM: ACK") == []
    (g,) = parser.flush()
    assert isinstance(g, p.Garbage)


VALID_REPLIES = [
    THESIS_SUBSTRATE_ACK,
    b"\n\r\n\rM: ACKN\n\r",
    b"\n\r\n\rM12: ACK\x42\n\r",
    b"\n\r\n\rCOMM. BOARD READY\n\r",
    b"\n\r\n\rLOCALIZED\n\rSide: 3\n\rYref: 0\n\rPos: +02-01\n\r",
    p.reply_status(9, "S", False, 0, 0, 0, 2, prefix_role="S"),
    p.reply_status(4, "M", True, -3, 2, 5, 0, prefix_role="M", schema=0xD39FC01B),
    p.reply_error(25, 1, "M", 3),
    b"\n\r\n\rACK\x05\n\rMSG\x05\x03\x0aNN\n\r",
]


def _signature(ev):
    return (type(ev).__name__, {k: v for k, v in vars(ev).items() if k != "raw"})


@settings(max_examples=300)
@given(st.lists(st.tuples(st.binary(max_size=12), st.sampled_from(VALID_REPLIES)), max_size=8),
       st.binary(max_size=12))
def test_noise_never_hides_a_valid_reply(pairs, trailing):
    stream = b"".join(noise + reply for noise, reply in pairs) + trailing
    got = [_signature(e) for e in parse_all(stream) if not isinstance(e, p.Garbage)]
    expected = [_signature(e) for _, reply in pairs for e in parse_all(reply)]
    # Every valid reply is found, in order (noise may add events of its own).
    it = iter(got)
    assert all(any(g == want for g in it) for want in expected), (stream, got)


@given(st.binary(max_size=200))
def test_parser_never_raises_and_keeps_every_byte(data):
    events = parse_all(data)
    assert b"".join(e.raw for e in events) == _without_silent(data, events)


def _without_silent(data, events):
    # Preambles, prefixes and stray LF/CR produce no event; every other byte
    # is in exactly one event's raw bytes, in order.
    raw = b"".join(e.raw for e in events)
    it = iter(data)
    assert all(b in it for b in raw)
    return raw
