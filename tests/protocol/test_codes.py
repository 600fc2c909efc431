"""The function-code table against Table 3-7 of the thesis."""

import pytest

from hexbot.protocol.codes import CODES, Board, Status, lookup


def test_every_code_of_table_3_7_is_present():
    assert set(CODES) == set(range(1, 76)) | {126}


@pytest.mark.parametrize(
    "code,name,board,nargs",
    [
        (1, "JxOpen", Board.CONTROL, 1),
        (5, "JTest", Board.CONTROL, 2),
        (16, "SNTest", Board.CONTROL, 2),
        (20, "TurnOffAll", Board.CONTROL, 0),
        (21, "MCW", Board.CONTROL, 4),
        (24, "SCCW", Board.CONTROL, 4),
        (25, "IrSel", Board.COMM, 1),
        (43, "JointTest", Board.COMM, 2),
        (50, "LYref", Board.COMM, 1),
        (59, "LSCCW", Board.COMM, 4),
        (65, "Ref", Board.COMM, 0),
        (66, "Localize", Board.COMM, 0),
        (67, "CW", Board.COMM, 8),
        (68, "CCW", Board.COMM, 8),
    ],
)
def test_thesis_functions(code, name, board, nargs):
    fn = CODES[code]
    assert (fn.name, fn.board, len(fn.args), fn.status) == (name, board, nargs, Status.USED)


@pytest.mark.parametrize("code", [6, 7, 8, 9, 10, 17, 18, 19, 26, 27, 51, 55, 60, 64, 73, 75])
def test_not_used_codes(code):
    assert CODES[code].status is Status.UNUSED
    assert not CODES[code].executable


def test_reserved_framing_bytes():
    assert CODES[42].status is Status.RESERVED  # '*'
    assert CODES[126].status is Status.RESERVED  # '~'


def test_extensions_live_in_unused_codes():
    ext = {fn.code for fn in CODES.values() if fn.status is Status.EXTENSION}
    assert ext == {69, 70, 71, 72}


def test_argument_ranges():
    assert (CODES[1].args[0].lo, CODES[1].args[0].hi) == (1, 6)  # joint
    assert (CODES[25].args[0].lo, CODES[25].args[0].hi) == (0, 6)  # channel, 0 = centre
    assert all(a.unit == "tick" for a in CODES[21].args[1:])


def test_lookup_by_name_and_number():
    assert lookup("mcw").code == 21
    assert lookup("21").name == "MCW"
    with pytest.raises(KeyError):
        lookup("NoSuchFunction")


def test_c_names_are_unique():
    names = [fn.c_name for fn in CODES.values() if fn.executable]
    assert len(names) == len(set(names))
    assert CODES[1].c_name == "HB_FN_JX_OPEN"
