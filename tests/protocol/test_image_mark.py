"""The mark every firmware image carries (protocol/image_mark.py): the
generated macro and the reader agree, and the built images carry it."""

from __future__ import annotations

import re

import pytest

from hexbot.protocol import image_mark
from hexbot.protocol.header import SCHEMA_HASH, render
from hexbot.protocol.wire import FW_VERSION


def test_the_header_macro_spells_what_the_reader_reads():
    """Expand HB_IMAGE_MARK the way the C compiler joins string literals,
    and read it back."""
    macro = image_mark.c_macro()
    assert macro in render()
    body = macro.split(" ", 2)[2]
    values = {"board": "control", "HB_FW_VERSION": "0.2.0-rc1",
              "HB_SCHEMA_HASH_TEXT": f"{SCHEMA_HASH:08x}"}
    tokens = re.findall(r'"[^"]*"|\w+', body)
    text = "".join(t[1:-1] if t.startswith('"') else values[t] for t in tokens).encode()
    mark = image_mark.read_mark(b"\xff\x00junk" + text + b"\x00\x0c\x94")
    assert mark == image_mark.ImageMark("control", "0.2.0-rc1", SCHEMA_HASH)


def test_a_mark_needs_all_its_fields_and_its_end():
    good = b"hexbot-image board=comm version=0.1.0 schema=0123abcd\x00"
    assert image_mark.read_mark(good).schema == 0x0123ABCD
    for broken in (good[:-1],  # no NUL: a cut image
                   good.replace(b"schema=0123abcd", b"schema=0123abc"),
                   good.replace(b"board=comm ", b""),
                   good.replace(b"0.1.0", b"")):
        assert image_mark.read_mark(broken) is None


@pytest.mark.parametrize("board", ["comm", "control", "rf12", "rflink"])
def test_every_built_image_says_its_board_version_and_schema(board, built_images):
    """ELF and Intel HEX alike: the mark is in flash (.text), so the .hex
    that avrdude writes carries it too."""
    from intelhex import IntelHex

    elf = built_images / f"{board}.elf"
    expected = image_mark.ImageMark(board, FW_VERSION, SCHEMA_HASH)
    assert image_mark.read_mark(elf.read_bytes()) == expected
    flash = IntelHex(str(built_images / f"{board}.hex")).tobinstr()
    assert image_mark.read_mark(flash) == expected


def test_mismatch_names_the_board_and_the_fix():
    mark = image_mark.ImageMark("comm", "0.1.0", 0x11111111)
    wrong, other = image_mark.mismatch(mark, ("control",), 0x22222222)
    assert wrong == "it is the comm board's firmware, not the control board's"
    assert other == ("it was built from protocol schema 11111111, this host speaks 22222222: "
                     "rebuild it (make -C firmware)")
    assert image_mark.mismatch(mark, ("rf12", "comm"), 0x11111111) == (None, None)
    assert image_mark.mismatch(None, ("control",), 0x22222222) == (None, None)
