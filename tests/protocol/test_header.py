"""The generated files (firmware headers, doc tables) come from protocol/ and
are checked in fresh; the schema hash tells firmware of another protocol."""

import re
import subprocess

import pytest

from hexbot.protocol import generated, header, pins_header, timing
from hexbot.protocol.codes import CODES


def test_every_generated_file_is_current():
    stale = [f"{a.path.name} ({a.block or 'file'})" for a in generated.stale()]
    assert not stale, f"run `hexbot gen-header` and commit: {stale}"


@pytest.mark.parametrize("artifact", generated.ARTIFACTS,
                         ids=lambda a: f"{a.path.name}-{a.block or 'file'}")
def test_a_stale_copy_is_detected(tmp_path, artifact):
    current = artifact.path.read_text()
    copy = tmp_path / artifact.path.name
    copy.write_text(current)
    assert not artifact.is_stale(copy)
    # Change one value inside the generated part: a digit of its last line.
    generated_part = artifact.render()
    line = [ln for ln in generated_part.splitlines() if re.search(r"\d", ln)][-1]
    changed = re.sub(r"\d", lambda m: str((int(m.group()) + 1) % 10), line, count=1)
    copy.write_text(current.replace(line, changed))
    assert artifact.is_stale(copy)


def test_a_file_mavgen_no_longer_writes_is_found():
    from hexbot.protocol import mavlink_gen

    assert generated.leftovers() == []  # the checked-in folder holds only mavgen's files
    real = mavlink_gen.C_DIR / "hexbot" / "mavlink_msg_hexbot_removed.h"
    try:
        real.write_text("/* a message removed from the dialect */\n")
        assert generated.leftovers() == [real]
    finally:
        real.unlink(missing_ok=True)


def test_a_document_without_markers_is_an_error(tmp_path):
    doc = next(a for a in generated.ARTIFACTS if a.block)
    copy = tmp_path / "doc.md"
    copy.write_text("no markers\n")
    with pytest.raises(ValueError, match="markers"):
        doc.is_stale(copy)


def test_header_defines_every_executable_code():
    text = header.render()
    for fn in CODES.values():
        if fn.executable:
            assert re.search(rf"#define {fn.c_name}\s+{fn.code}\b", text)


def test_schema_hash_follows_the_values_not_the_layout(monkeypatch):
    before = header.schema_hash()
    assert header.SCHEMA_HASH == int(before, 16)
    assert f'#define HB_SCHEMA_HASH_TEXT "{before}"' in header.render()
    monkeypatch.setattr(timing, "ACK_SLOT_TICKS", timing.ACK_SLOT_TICKS + 1)
    assert header.schema_hash() != before
    monkeypatch.undo()
    assert header._values("#define A 1 /* why */\n") == header._values("#define  A 1\n")


def test_schema_mismatch_warns_in_one_line():
    assert header.schema_mismatch(header.SCHEMA_HASH) is None
    for reported in (header.SCHEMA_HASH ^ 1, None):
        warning = header.schema_mismatch(reported)
        assert warning and "\n" not in warning
        assert f"{header.SCHEMA_HASH:08x}" in warning
    assert f"{header.SCHEMA_HASH ^ 1:08x}" in header.schema_mismatch(header.SCHEMA_HASH ^ 1)


def test_headers_compile_for_the_atmega162(tmp_path):
    src = tmp_path / "t.c"
    src.write_text(
        '#include "hexbot_codes.h"\n'
        '#include "hexbot_pins.h"\n'
        "#define ENTRY(code, board, nargs) {code, board, nargs},\n"
        "const unsigned char table[][3] = { HB_FUNCTIONS(ENTRY) };\n"
        "const unsigned char joints[6] = HB_JOINT_PINS;\n"
        "const signed char dx[6] = HB_SIDE_DX;\n"
        "int main(void) { return table[0][0] + HB_FN_CW + joints[0] + dx[0]; }\n"
    )
    subprocess.run(
        ["avr-gcc", "-mmcu=atmega162", "-Wall", "-Werror", "-I", str(header.HEADER_PATH.parent),
         "-c", str(src), "-o", str(tmp_path / "t.o")],
        check=True,
    )


def test_c_macros_compute_what_timing_py_computes(tmp_path):
    # The formulas the firmware evaluates at compile time (byte ticks, boot
    # slots) against their Python twins, for every length that occurs.
    lengths = range(0, 120)
    src = tmp_path / "t.c"
    src.write_text(
        '#include <stdio.h>\n#include "hexbot_codes.h"\n'
        "int main(void) { for (unsigned n = 0; n < 120; n++)"
        ' printf("%u %u\\n", HB_IR_TICKS(n), HB_BOOT_SLOT_TICKS(n)); return 0; }\n'
    )
    exe = tmp_path / "t"
    subprocess.run(["cc", "-I", str(header.HEADER_PATH.parent), str(src), "-o", str(exe)],
                   check=True)
    out = subprocess.run([str(exe)], check=True, capture_output=True, text=True).stdout
    got = [tuple(map(int, line.split())) for line in out.splitlines()]
    want = [(timing.ir_ticks(n), timing.ir_ticks(n) + timing.BOOT_GUARD_TICKS) for n in lengths]
    assert got == want
    assert timing.boot_slot_ticks("0.1.0") == want[timing.BOOT_TEXT_FIXED_BYTES + 5][1]


def test_pins_header_is_for_the_board_files_only():
    from pathlib import Path

    firmware = Path(pins_header.PATH).parents[1]
    users = sorted(p.relative_to(firmware).as_posix() for p in firmware.rglob("*.[ch]")
                   if '#include "hexbot_pins.h"' in p.read_text())
    assert users == ["board/pins.h"]


def test_docs_function_table_lists_the_codes():
    from hexbot.protocol import docs_table

    assert "| 21 | `MCW(i, t1, t2, t3)` | control |" in docs_table.render_table()
