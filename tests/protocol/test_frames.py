"""Frame codecs: round trips (hypothesis), specific errors, golden vectors."""

import pytest
from hypothesis import example, given
from hypothesis import strategies as st

from hexbot.errors import FrameError
from hexbot.protocol import frames, wire
from hexbot.protocol.codes import CODES, Board
from hexbot.protocol.frames import Command, LocationMessage

EXECUTABLE = [fn for fn in CODES.values() if fn.executable]


@st.composite
def valid_commands(draw, board=None):
    fns = [fn for fn in EXECUTABLE if board is None or fn.board is board]
    fn = draw(st.sampled_from(fns))
    args = [draw(st.integers(a.lo, a.hi)) for a in fn.args]
    if fn.name == "Select":
        # 0 (all) stands alone; further ids are optional and distinct.
        first = draw(st.integers(0, wire.MAX_SELECT_ID))
        more = [] if first == 0 else draw(
            st.lists(st.integers(1, wire.MAX_SELECT_ID), max_size=7, unique=True)
            .filter(lambda ids, f=first: f not in ids)
        )
        args = [first, *more]
    return Command(fn.code, tuple(args))


@given(valid_commands())
def test_pc_frame_round_trip(cmd):
    frame = frames.encode_pc(cmd)
    assert len(frame) == 11 and frame[0] == ord("*") and frame[-1] == ord("#")
    assert frames.decode_pc(frame) == cmd


@given(valid_commands(board=Board.CONTROL))
def test_board_frame_round_trip(cmd):
    frame = frames.encode_board(cmd)
    assert len(frame) == 7
    assert frames.decode_board(frame) == cmd


@given(st.integers(-99, 99), st.integers(-99, 99), st.integers(1, 6))
def test_location_round_trip(x, y, side):
    msg = LocationMessage(x, y, side)
    frame = frames.encode_location(msg)
    assert len(frame) == 8
    assert frames.decode_location(frame) == msg


@given(st.binary(min_size=11, max_size=11))
def test_random_pc_frames_decode_or_raise_frame_error(data):
    try:
        cmd = frames.decode_pc(data)
    except FrameError:
        return
    assert frames.encode_pc(cmd) == data


@given(valid_commands(), st.integers(0, 10), st.integers(0, 255))
@example(Command(44, ()), 10, ord("X"))  # the end byte, every run
@example(Command(44, ()), 0, ord("#"))
def test_any_corrupted_delimiter_is_rejected(cmd, pos, value):
    frame = bytearray(frames.encode_pc(cmd))
    if pos not in (0, 10) or frame[pos] == value:
        return
    frame[pos] = value
    with pytest.raises(FrameError):
        frames.decode_pc(bytes(frame))


@pytest.mark.parametrize(
    "key,args,message",
    [
        ("JxOpen", (7,), "1..6"),
        ("JxOpen", (0,), "1..6"),
        ("IrSel", (7,), "0..6"),
        ("MCW", (1, 8, 4), "takes 4"),
        (6, (), "unused"),
        (42, (), "reserved"),
        ("SxP", (300,), "one byte"),
        ("Select", (64,), "0..63"),
    ],
)
def test_invalid_commands_raise_specific_errors(key, args, message):
    with pytest.raises(FrameError, match=message):
        frames.encode_pc(Command(key if isinstance(key, int) else CODES_BY(key), args))


def CODES_BY(name):  # noqa: N802 - reads like a table lookup in the parametrize list
    return next(fn.code for fn in CODES.values() if fn.name == name)


def test_select_rules():
    assert frames.select([0]).args == (0,)
    assert frames.select([3, 5]).args == (3, 5)
    for bad in ([], [0, 3], [4, 4]):
        with pytest.raises(FrameError):
            frames.select(bad)


@pytest.mark.parametrize("slot", range(1, 8))  # JxOpen's 7 fillers, the first one too
def test_non_n_bytes_beyond_arity_rejected(slot):
    frame = bytearray(frames.encode_pc(frames.make("JxOpen", 3)))
    frame[2 + slot] = 0
    with pytest.raises(FrameError, match="must be 'N'"):
        frames.decode_pc(bytes(frame))


def test_a_decoded_frame_is_checked_like_an_encoded_one():
    # the wire form of JxOpen(7): well framed, but joint 7 does not exist
    frame = b"*\x01\x07" + b"N" * 7 + b"#"
    with pytest.raises(FrameError, match="1..6"):
        frames.decode_pc(frame)


def test_board_ack():
    assert frames.encode_board_ack(21) == b"\x15"
    assert frames.decode_board_ack(b"\x15", 21) == 21
    with pytest.raises(FrameError, match="time-out"):
        frames.decode_board_ack(b"~", 21)
    with pytest.raises(FrameError, match="echoed"):
        frames.decode_board_ack(b"\x16", 21)


def test_board_frame_refuses_comm_functions():
    with pytest.raises(FrameError, match="comm board"):
        frames.encode_board(frames.make("IrSel", 2))


# --- golden vectors, written out by hand from the thesis listings ---------


def test_golden_pc_frame_jxopen_3():
    # VB GUI: '*', Chr(1), Chr(3), then unused bytes, '#'
    assert frames.encode_pc(frames.make("JxOpen", 3)) == b"*\x01\x03NNNNNNN#"


def test_golden_pc_frame_combined_cw():
    frame = frames.encode_pc(frames.make("CW", 4, 8, 4, 9, 3, 8, 4, 9))
    assert frame == bytes([42, 67, 4, 8, 4, 9, 3, 8, 4, 9, 35])


def test_golden_board_frames_from_comm_listing():
    # MSG(14,'N','N','N','N') and MSG(21,i,t1,t2,t3) of the comm board listing
    assert frames.encode_board(frames.make("SxOffAll")) == b"*\x0eNNNN#"
    assert frames.encode_board(frames.make("MCW", 4, 8, 4, 9)) == b"*\x15\x04\x08\x04\x09#"
    assert frames.encode_board(frames.make("JTest", 3, 10)) == b"*\x05\x03\x0aNN#"


def test_golden_location_messages_of_figure_4_13():
    # The reference at (0,0) sends on side 1: "* -01 +01 4", side 3: "+01 +00 6",
    # side 6: "-01 +00 3" (thesis section 4.2, Table 4-1).
    assert frames.encode_location(LocationMessage(-1, 1, 4)) == b"*-01+014"
    assert frames.encode_location(LocationMessage(1, 0, 6)) == b"*+01+006"
    assert frames.encode_location(LocationMessage(-1, 0, 3)) == b"*-01+003"


@pytest.mark.parametrize("bad", [b"*-01+01", b"*-0a+014", b"#-01+014", b"*-01+017", b"*x01+014"])
def test_bad_location_messages(bad):
    with pytest.raises(FrameError):
        frames.decode_location(bad)
