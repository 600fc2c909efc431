"""The firmware header is generated from the table and checked in fresh."""

import re
import shutil
import subprocess

import pytest

from hexbot.protocol import header
from hexbot.protocol.codes import CODES


def test_checked_in_header_is_current():
    assert not header.is_stale(), "run `hexbot gen-header` and commit the header"


def test_header_defines_every_executable_code():
    text = header.render()
    for fn in CODES.values():
        if fn.executable:
            assert re.search(rf"#define {fn.c_name}\s+{fn.code}\b", text)


def test_stale_header_detected(tmp_path):
    stale = tmp_path / "hexbot_codes.h"
    stale.write_text(header.render().replace("#define HB_FN_MCW               21",
                                             "#define HB_FN_MCW               22"))
    assert header.is_stale(stale)


@pytest.mark.skipif(shutil.which("avr-gcc") is None, reason="avr-gcc not installed")
def test_header_compiles_for_the_atmega162(tmp_path):
    src = tmp_path / "t.c"
    src.write_text(
        '#include "hexbot_codes.h"\n'
        "#define ENTRY(code, board, nargs) {code, board, nargs},\n"
        "const unsigned char table[][3] = { HB_FUNCTIONS(ENTRY) };\n"
        "int main(void) { return table[0][0] + HB_FN_CW; }\n"
    )
    subprocess.run(
        ["avr-gcc", "-mmcu=atmega162", "-Wall", "-Werror", "-I", str(header.HEADER_PATH.parent),
         "-c", str(src), "-o", str(tmp_path / "t.o")],
        check=True,
    )


def test_docs_function_table_is_current():
    from hexbot.protocol import docs_table

    assert not docs_table.is_stale(), "run `hexbot gen-header` and commit docs/protocol.md"
    table = docs_table.render_table()
    assert "| 21 | `MCW(i, t1, t2, t3)` | control |" in table
