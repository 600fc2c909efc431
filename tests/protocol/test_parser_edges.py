"""Reply parser at its edges: every field of a reply read from its own byte,
out-of-range fields refused, a prefix that lost its reply forgotten."""

import pytest

from hexbot.protocol import parser as p
from hexbot.protocol import wire
from hexbot.protocol.codes import ErrorCode
from hexbot.protocol.parser import parse_all


def test_an_error_reply_reads_code_and_reason_from_their_own_bytes():
    (err,) = parse_all(p.reply_error(25, ErrorCode.NOT_LOCALIZED, "M", 3))
    assert isinstance(err, p.ErrorReply)
    assert (err.code, err.reason, err.role, err.module) == (25, ErrorCode.NOT_LOCALIZED, "M", 3)
    assert "NOT_LOCALIZED" in err.describe()


@pytest.mark.parametrize(("x", "y"), [(-128, 127), (127, -128), (-1, 0)])
def test_status_coordinates_are_signed_bytes_over_their_whole_range(x, y):
    (sta,) = parse_all(p.reply_status(7, "M", True, x, y, 0, 0, prefix_role="M"))
    assert (sta.x, sta.y) == (x, y)


@pytest.mark.parametrize("yref", range(6))
def test_a_status_with_any_orientation_0_to_5_is_read(yref):
    (sta,) = parse_all(p.reply_status(4, "S", True, 1, 1, yref, 0, prefix_role="S"))
    assert isinstance(sta, p.StatusReport) and sta.yref == yref


@pytest.mark.parametrize(("yref", "localized"), [(6, 1), (255, 1), (0, 2)])
def test_a_status_with_an_impossible_field_is_not_a_status(yref, localized):
    data = p.reply_status(4, "S", bool(localized), 1, 1, yref, 0, prefix_role="S")
    data = data.replace(b"STA\x04S\x01", b"STA\x04S" + bytes([localized]))
    assert not any(isinstance(e, p.StatusReport) for e in parse_all(data))


@pytest.mark.parametrize(("line", "kind"), [(wire.LOC_SIDE + b"0", p.SideReport),
                                            (wire.LOC_SIDE + b"7", p.SideReport),
                                            (wire.LOC_YREF + b"6", p.YrefReport)])
def test_localization_lines_out_of_range_are_not_reports(line, kind):
    events = parse_all(wire.PREAMBLE + line + wire.EOL)
    assert not any(isinstance(e, kind) for e in events)


@pytest.mark.parametrize("side", range(1, 7))
def test_every_side_1_to_6_is_a_side_report(side):
    (ev,) = parse_all(wire.PREAMBLE + wire.LOC_SIDE + str(side).encode() + wire.EOL)
    assert isinstance(ev, p.SideReport) and ev.side == side


def test_a_prefix_cut_off_by_the_next_preamble_does_not_name_the_next_reply():
    # "M03: " and then a new reply: its ACK is not module 3's
    events = parse_all(wire.PREAMBLE + b"M03: " + p.reply_ack(21))
    (ack,) = [e for e in events if isinstance(e, p.Ack)]
    assert (ack.code, ack.role, ack.module) == (21, None, None)


def test_a_cut_off_msg_does_not_take_the_next_preamble_for_its_arguments():
    # "MSG" and then a new reply: its five argument bytes would hold the
    # preamble, so it was noise, not a control message of code 10 ('\n')
    stream = wire.REPLY_MSG + wire.PREAMBLE + b"N" + wire.EOL + p.reply_ack(21, "S")
    events = [e for e in parse_all(stream) if not isinstance(e, p.Garbage)]
    assert [(type(e), e.code) for e in events] == [(p.Ack, 21)]
