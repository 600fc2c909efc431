"""Frame codecs at their edges: the values at the ends of each range, the
bytes a decoder must refuse, and the cases the random round trips of
test_frames.py reach only by luck."""

import pytest

from hexbot.errors import FrameError
from hexbot.protocol import frames, wire
from hexbot.protocol.codes import CODES, Board, lookup, moves_the_module
from hexbot.protocol.frames import Command, LocationMessage

EXECUTABLE = [fn for fn in CODES.values() if fn.executable]
CONTROL = [fn for fn in EXECUTABLE if fn.board is Board.CONTROL]


def _with_last_required_n(fn):
    """``fn``'s arguments at their lowest, its last required one 'N' (78)."""
    required = [a for a in fn.args if "none" not in a.meaning]
    if not required or not required[-1].check(wire.UNUSED):
        return None
    return tuple(a.lo for a in required[:-1]) + (wire.UNUSED,)


N_LAST = [(fn, args) for fn in EXECUTABLE if (args := _with_last_required_n(fn)) is not None]


def test_some_function_takes_n_as_its_last_required_argument():
    assert N_LAST  # delays and counts run 0..255: 78 is a delay like any other


@pytest.mark.parametrize(("fn", "args"), N_LAST, ids=[fn.name for fn, _ in N_LAST])
def test_a_required_argument_of_value_n_is_not_taken_for_a_filler(fn, args):
    cmd = Command(fn.code, args)
    assert frames.decode_pc(frames.encode_pc(cmd)) == cmd


@pytest.mark.parametrize("ids", [[0], [5], [1, wire.MAX_SELECT_ID], list(range(1, 9))])
def test_select_with_any_number_of_ids_round_trips(ids):
    cmd = frames.select(ids)
    assert frames.decode_pc(frames.encode_pc(cmd)) == cmd


@pytest.mark.parametrize("fn", CONTROL, ids=lambda fn: fn.name)
def test_a_board_frame_with_a_wrong_end_or_start_byte_is_refused(fn):
    frame = bytearray(frames.encode_board(Command(fn.code, tuple(a.lo for a in fn.args))))
    for pos, wrong in ((-1, ord("X")), (-1, wire.UNUSED), (0, ord("#"))):
        bad = bytearray(frame)
        bad[pos] = wrong
        with pytest.raises(FrameError):
            frames.decode_board(bytes(bad))


@pytest.mark.parametrize("fn", [fn for fn in CONTROL if len(fn.args) < wire.BOARD_ARGS],
                         ids=lambda fn: fn.name)
def test_a_board_frame_with_a_filler_other_than_n_is_refused(fn):
    """The control firmware refuses it (table_args_ok), as decode_pc does a PC frame."""
    frame = bytearray(frames.encode_board(Command(fn.code, tuple(a.lo for a in fn.args))))
    frame[2 + len(fn.args)] = 0
    with pytest.raises(FrameError, match="must be 'N'"):
        frames.decode_board(bytes(frame))


def test_a_board_frame_of_a_comm_board_function_is_refused():
    irsel = lookup("IrSel")
    frame = bytes([wire.START, irsel.code, 2, wire.UNUSED, wire.UNUSED, wire.UNUSED, wire.END])
    assert len(frame) == wire.BOARD_FRAME_LEN
    with pytest.raises(FrameError, match="not a control-board function"):
        frames.decode_board(frame)


@pytest.mark.parametrize("data", [b"", b"\x15\x15", b"\x15#"])
def test_a_board_acknowledgement_is_exactly_one_byte(data):
    with pytest.raises(FrameError, match="one byte"):
        frames.decode_board_ack(data, 21)


@pytest.mark.parametrize(("x", "y", "side", "frame"), [
    (wire.LOC_COORD_LIMIT, -wire.LOC_COORD_LIMIT, 6, b"*+99-996"),
    (-wire.LOC_COORD_LIMIT, wire.LOC_COORD_LIMIT, 1, b"*-99+991"),
    (0, 0, 3, b"*+00+003"),
])
def test_location_messages_at_the_ends_of_the_coordinate_range(x, y, side, frame):
    msg = LocationMessage(x, y, side)
    assert frames.encode_location(msg) == frame
    assert frames.decode_location(frame) == msg


@pytest.mark.parametrize("x", [wire.LOC_COORD_LIMIT + 1, -wire.LOC_COORD_LIMIT - 1])
def test_a_coordinate_beyond_two_digits_is_refused(x):
    with pytest.raises(FrameError, match="within"):
        frames.encode_location(LocationMessage(x, 0, 1))


@pytest.mark.parametrize("side", [b"0", b"7", b"9", b"N"])
def test_msg1_sides_outside_1_to_6_are_refused(side):
    with pytest.raises(FrameError, match="side"):
        frames.decode_location(b"*+01-01" + side)


# --- the function table as the host uses it --------------------------------


def test_names_typed_with_blanks_around_them_are_found():
    assert lookup(" mcw\n") is lookup(lookup("MCW").code)
    assert lookup(f" {lookup('CW').code} ") is lookup("CW")


@pytest.mark.parametrize(("name", "role", "moves"), [
    ("MCW", None, True), ("MCCW", "S", True),  # a mobile half moves whoever runs it
    ("SCW", "M", False), ("SCCW", "S", False),  # a substrate half never moves it
    ("CW", "M", True), ("CCW", "M", True),  # combined: only the mobile of the pair moves
    ("CW", "S", False), ("CCW", "S", False), ("CW", None, False),
    ("JxOpen", "M", False),
])
def test_which_acknowledgements_mean_the_module_moved(name, role, moves):
    assert moves_the_module(lookup(name).code, role) is moves



@pytest.mark.parametrize("ids,words", [
    ((0, 3), "id 0 (all modules) cannot be combined with other ids"),
    ((4, 4), "duplicate module ids in [4, 4]"),
])
def test_a_select_list_that_means_two_things_is_refused_however_it_is_built(ids, words):
    # The firmware reads Select(0, 3) as "all" and gives the second 4 of
    # Select(4, 4) no rank of its own; `hexbot send Select 2 2` used to wait
    # for two replies of module 2 and fail with a time-out (exit 3).
    frame = bytes([wire.START, frames.lookup("Select").code, *ids]
                  + [wire.UNUSED] * (wire.PC_ARGS - len(ids)) + [wire.END])
    for build in (lambda: frames.make("Select", *ids), lambda: frames.select(ids),
                  lambda: frames.encode_pc(frames.Command(frames.lookup("Select").code, ids)),
                  lambda: frames.decode_pc(frame)):
        with pytest.raises(FrameError) as caught:
            build()
        assert words in str(caught.value)
    # on purpose, unchecked, it can still be sent
    assert frames.encode_pc(frames.Command(frames.lookup("Select").code, ids),
                            strict=False) == frame
