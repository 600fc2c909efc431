"""Fuse safety rules and Intel HEX checks, without a device."""

from __future__ import annotations

import pytest

from hexbot.errors import FlashingError
from hexbot.host.flash.fuses import TABLE_3_6, FuseSet, check_fuses, fuse_notes
from hexbot.host.flash.ihex import read_hex


def test_table_3_6_is_safe_and_unremarkable():
    assert (TABLE_3_6.lfuse, TABLE_3_6.hfuse, TABLE_3_6.efuse) == (0x62, 0xD9, 0xFF)
    assert check_fuses(TABLE_3_6) == [] and fuse_notes(TABLE_3_6) == []


@pytest.mark.parametrize(
    ("fuses", "words", "lockout"),
    [
        (FuseSet(hfuse=0xF9), "SPIEN unprogrammed", True),
        (FuseSet(lfuse=0x6F), "external crystal", True),
        (FuseSet(lfuse=0x60), "external clock", True),
        (FuseSet(lock=0xFC), "lock mode 3", True),
        (FuseSet(lock=0xFE), "lock mode 2", True),
        (FuseSet(lock=0xEF), "boot lock bits", False),
        (FuseSet(hfuse=0x99), "enables JTAG", False),
        (FuseSet(efuse=0xEF), "M161C", False),
    ],
)
def test_each_danger_is_named(fuses, words, lockout):
    problems = check_fuses(fuses)
    assert len(problems) == 1
    assert words in problems[0].text and problems[0].lockout is lockout


def test_other_internal_rc_speed_is_only_a_note():
    assert check_fuses(FuseSet(lfuse=0xE2)) == []
    assert "the clock would not be 1 MHz" in fuse_notes(FuseSet(lfuse=0xE2))[0]  # CKDIV8


def test_start_up_time_and_clock_output_keep_the_clock():
    (sut,) = fuse_notes(FuseSet(lfuse=0x42))
    assert "the clock stays 1 MHz" in sut and "PB0" not in sut
    (ckout,) = fuse_notes(FuseSet(lfuse=0x22))
    assert ckout.endswith("CKOUT puts the clock on PB0, the control board's electromagnet 1 "
                          "(+) pin")


def write(tmp_path, text: str):
    path = tmp_path / "image.hex"
    path.write_text(text)
    return path


def test_hex_reads_data_and_extended_addresses(tmp_path):
    path = write(tmp_path, ":020000021000EC\n:020000000102FB\n:00000001FF\n")
    image = read_hex(path)
    assert image.data == {0x10000: 1, 0x10001: 2}


@pytest.mark.parametrize(
    ("text", "where", "problem"),
    [
        (":0200000001020C\n:00000001FF\n", ":1:", "checksum error"),
        (":020000000102\n", ":1:", "length"),
        ("0200000001020B\n", ":1:", "start with ':'"),
        (":020000000102FB\n", "", "no end-of-file"),
        (":020000000102FB\n:00000001FF\n:020000000102FB\n", ":3:", "after the end-of-file"),
        (":024000000102BB\n:00000001FF\n", ":1:", "beyond the 16384-byte flash"),
        (":0100100007E8\n:020000040001F9\n:020000000102FB\n:00000001FF\n", ":3:",
         "0x10000 lies beyond the 16384-byte flash"),
        (":020000000102FB\n\n:020000000102FB\n:00000001FF\n", ":3:", "written twice"),
        (":020000060102F5\n:00000001FF\n", ":1:", "unsupported record type"),
        (":0200000001ZZFB\n:00000001FF\n", ":1:", "hexadecimal digits"),
        ("", "", "no end-of-file"),
        (":00000001FF\n", "", "holds no data"),
    ],
)
def test_bad_hex_names_file_line_and_problem(tmp_path, text, where, problem):
    path = write(tmp_path, text)
    with pytest.raises(FlashingError) as err:
        read_hex(path, limit=16384)
    assert f"{path}{where}" in str(err.value) and problem in str(err.value)
