"""What a firmware image says about itself, readable without running it.

Every image (comm, control, rf12, rflink) carries one NUL-terminated line in
its flash, built by the generated macro ``HB_IMAGE_MARK(board)``::

    hexbot-image board=comm version=0.1.0 schema=a7f566bc

so whoever holds the file, ELF or Intel HEX, can tell which board it is for,
its version, and the protocol schema it was built from (``header.schema_hash``)
before it runs: the simulator refuses a board's image loaded as another
board's and warns about one built from another protocol; ``hexbot flash``
refuses both unless forced. An image without a mark (a test program, a build
older than the mark) is taken as it is.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

TAG = "hexbot-image"
#: the fields in their order, each ``name=value``, separated by one space
FIELDS = ("board", "version", "schema")

_MARK = re.compile(re.escape(TAG.encode())
                   + rb" board=([a-z0-9]+) version=([!-~]{1,32}) schema=([0-9a-f]{8})\x00")


@dataclass(frozen=True)
class ImageMark:
    board: str
    version: str
    schema: int

    def describe(self) -> str:
        return f"{self.board} board firmware {self.version}, protocol schema {self.schema:08x}"


def c_macro() -> str:
    """The header's ``HB_IMAGE_MARK(board)``: string literals the C compiler
    joins into the mark (``HB_FW_VERSION`` comes from the Makefile)."""
    values = {"board": "board", "version": "HB_FW_VERSION", "schema": "HB_SCHEMA_HASH_TEXT"}
    parts = [f'"{TAG} {FIELDS[0]}=" {values[FIELDS[0]]}']
    parts += [f'" {name}=" {values[name]}' for name in FIELDS[1:]]
    return "#define HB_IMAGE_MARK(board) " + " ".join(parts)


def read_mark(data: bytes) -> ImageMark | None:
    """The mark in an image's bytes (a whole ELF file, or the flash bytes of
    an Intel HEX image); None when it has none."""
    m = _MARK.search(data)
    if m is None:
        return None
    return ImageMark(m.group(1).decode(), m.group(2).decode(), int(m.group(3), 16))


def mismatch(mark: ImageMark | None, boards: tuple[str, ...],
             schema: int) -> tuple[str | None, str | None]:
    """(wrong board, other schema): one-line reasons, None where the image
    is one of ``boards``' firmware and built from this host's ``schema``; an
    image without a mark fits."""
    if mark is None:
        return None, None
    wrong = (f"it is the {mark.board} board's firmware, not the {' or '.join(boards)} "
             "board's" if mark.board not in boards else None)
    other = (f"it was built from protocol schema {mark.schema:08x}, this host speaks "
             f"{schema:08x}: rebuild it (make -C firmware)" if mark.schema != schema else None)
    return wrong, other
