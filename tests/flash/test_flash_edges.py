"""Edges of ``hexbot flash`` a user meets: what an avrdude that hangs,
loses its port or crashes exits with, a fuse that does not verify after the
flash did, signatures of nothing, fuse and lock values worth a word, images
that are not Intel HEX or end one byte past the flash, and ``--all`` with a
failed build or a build folder of another version."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

from hexbot.errors import FlashingError
from hexbot.hil_sim.isp import Atmega162Memory
from hexbot.host.flash import avrdude as avrdude_mod
from hexbot.host.flash.fuses import FuseSet, check_fuses, fuse_notes
from hexbot.host.flash.ihex import read_hex
from tests.flash.marks import needs_avr_gcc, needs_avrdude

#: A stand-in for avrdude: answers the device read (``-U name:r:FILE:r``)
#: with an ATmega162 at Table 3-6's fuses, and does on a write (``flash:w``)
#: what ON_WRITE says.
FAKE = """#!{python}
import os, signal, sys
values = {{"signature": b"\\x1e\\x94\\x04", "lfuse": b"\\x62", "hfuse": b"\\xd9",
           "efuse": b"\\xff", "lock": b"\\xff"}}
args = sys.argv[1:]
ops = [args[i + 1] for i, a in enumerate(args) if a == "-U"]
if any(op.startswith("flash:w:") for op in ops):
{on_write}
for op in ops:
    name, mode, path, _ = op.split(":")
    open(path, "wb").write(values[name])
"""


def fake_avrdude(tmp_path: Path, on_write: str) -> Path:
    script = tmp_path / "fake-avrdude"
    body = "\n".join("    " + line for line in on_write.strip().splitlines())
    script.write_text(FAKE.format(python=sys.executable, on_write=body))
    script.chmod(0o755)
    return script


# --- avrdude's own failures ------------------------------------------------

def test_an_avrdude_that_talks_but_never_ends_is_a_failure_not_a_lost_port(
        hexbot_flash, images, tmp_path, monkeypatch):
    # it keeps writing (so the no-progress watchdog does not fire) and never
    # finishes: exit 1 with the time-out, not 4 (the port is still there)
    monkeypatch.setattr(avrdude_mod, "WRITE_TIMEOUT_S", 2.0)
    script = fake_avrdude(tmp_path, """
import time
while True:
    print("#", end="", file=sys.stderr, flush=True)
    time.sleep(0.2)
""")
    _, hexfile = images("1.2.3")
    result = hexbot_flash("--image", str(hexfile), "--port", "/dev/ttyUSB0",
                          "--avrdude", str(script))
    assert result.code == 1, result.err
    assert "avrdude gave no result within 2 s" in result.err
    assert "the chip may be erased" in result.err


@pytest.mark.parametrize("said", [
    "avrdude: ser_send(): write error: Input/output error",
    "avrdude: ser_recv(): read error: No such device",
])
def test_a_port_lost_while_avrdude_runs_exits_4(hexbot_flash, images, tmp_path, said):
    # the adapter unplugged mid-write: docs/console.md's exit 4, as a missing port
    script = fake_avrdude(tmp_path, f"""
print({said!r}, file=sys.stderr)
sys.exit(1)
""")
    _, hexfile = images("1.2.3")
    result = hexbot_flash("--image", str(hexfile), "--port", "/dev/ttyUSB0",
                          "--avrdude", str(script))
    assert result.code == 4, result.err
    assert said.split(": ", 1)[1] in result.err


def test_an_avrdude_that_crashes_while_writing_is_not_a_success(hexbot_flash, images, tmp_path):
    # killed by a signal (negative return code), not exit 1: still a failure
    script = fake_avrdude(tmp_path, """
print("avrdude: erasing chip", file=sys.stderr, flush=True)
os.kill(os.getpid(), signal.SIGSEGV)
""")
    _, hexfile = images("1.2.3")
    result = hexbot_flash("--image", str(hexfile), "--port", "/dev/ttyUSB0",
                          "--avrdude", str(script))
    assert result.code == 1, result.out
    assert "programmed with" not in result.out
    assert "the chip may be erased or half-written: flash it again" in result.err


@needs_avrdude
def test_a_fuse_that_does_not_verify_says_the_flash_was_written(isp_server, images,
                                                                hexbot_flash):
    # SPIEN cannot be changed over ISP: --hfuse 0xF9 --force writes and
    # verifies the flash, then the high fuse reads back 0xD9. The flash is
    # good; telling the user it may be erased would send them reflashing.
    chip = isp_server()
    _, hexfile = images("1.2.3")
    result = hexbot_flash("--image", str(hexfile), "--port", chip.port, "--hfuse", "0xF9",
                          "--force")
    assert result.code == 1
    assert "the hfuse reads back 0xd9, not 0xf9" in result.err
    assert "the flash was written and verified before" in result.err
    assert "the chip may be erased" not in result.err
    image = read_hex(hexfile).to_bytes()
    assert bytes(chip.memory.flash[:len(image)]) == image



#: avrdude 7.x to a programmer that stops answering: its timeouts no longer
#: name stk500v2_getsync() as 6.x did (seen against a silent pty)
AVRDUDE_7_TIMEOUT = ("avrdude error: timeout\n" * 7
                     + "avrdude error: timeout communicating with programmer\n"
                     "avrdude error: failed to execute command 0x11\n"
                     "avrdude error: unable to leave programming mode\n\n"
                     "avrdude done.  Thank you.\n\n")


def test_avrdude_7_timeouts_get_the_no_programmer_hint():
    text = avrdude_mod.explain(AVRDUDE_7_TIMEOUT, "/dev/ttyUSB0", "stk500v2")
    assert "no stk500v2 programmer answered on /dev/ttyUSB0" in text


#: avrdude 7.1 after 453 s on a pty that never answers (its own retries; the
#: lines repeat): "initialization failed" too, which is not the cause
AVRDUDE_7_SILENT = ((("avrdude error: timeout\n" * 7
                      + "avrdude error: timeout communicating with programmer\n\n") * 7)
                    + "avrdude error: failed to execute command 0x10\n"
                    "avrdude error: initialization failed, rc=-1\n"
                    "        - double check the connections and try again\n"
                    "        - use -B to set lower ISP clock frequency, e.g. -B 125kHz\n"
                    "        - use -F to override this check\n\n"
                    + AVRDUDE_7_TIMEOUT)


def test_a_programmer_that_never_answered_is_not_blamed_on_the_chip():
    text = avrdude_mod.explain(AVRDUDE_7_SILENT, "/dev/ttyUSB0", "stk500v2")
    assert "no stk500v2 programmer answered on /dev/ttyUSB0" in text
    assert "did not enter programming mode" not in text

# --- signatures -------------------------------------------------------------

@needs_avrdude
@pytest.mark.parametrize("signature", ["000000", "ffffff"])
def test_a_signature_of_nothing_says_no_device_answered(isp_server, images, hexbot_flash,
                                                        signature):
    # all zeros or all ones: no chip on the ISP lines, not some other AVR
    chip = isp_server(Atmega162Memory(signature=bytes.fromhex(signature)))
    _, hexfile = images("1.2.3")
    result = hexbot_flash("--image", str(hexfile), "--port", chip.port)
    assert result.code == 1
    sig = bytes.fromhex(signature).hex(" ").upper()
    assert f"no device answered on {chip.port} (signature {sig})" in result.err
    assert "not an ATmega162" not in result.err
    assert chip.memory.flash == b"\xff" * 16384


# --- fuses and lock ---------------------------------------------------------

def test_boot_lock_bits_of_the_application_section_are_named():
    # BLB01/BLB02 (lock 0xFB, 0xF7): the firmware's own reads of its
    # application section would be restricted; named, not a lock-out
    for lock in (0xFB, 0xF7):
        problems = check_fuses(FuseSet(lock=lock))
        assert [p.lockout for p in problems] == [False], f"lock 0x{lock:02X}"
        assert "boot lock bits" in problems[0].text


@needs_avr_gcc
def test_an_always_on_watchdog_is_noted(hexbot_flash, images):
    _, hexfile = images("1.2.3")
    assert fuse_notes(FuseSet(hfuse=0xC9)) == ["WDTON is programmed: the watchdog is always on"]
    result = hexbot_flash("--image", str(hexfile), "--port", "/dev/pts/0", "--hfuse", "0xC9",
                          "--dry-run")
    assert result.code == 0, result.err
    assert "note: WDTON is programmed: the watchdog is always on" in result.out


@needs_avrdude
def test_fuses_that_differ_from_table_3_6_are_noted_when_not_written(isp_server, images,
                                                                     hexbot_flash):
    _, hexfile = images("1.2.3")
    odd = isp_server(Atmega162Memory(lfuse=0xE2))
    result = hexbot_flash("--image", str(hexfile), "--port", odd.port)
    assert result.code == 0, result.err
    assert "note: the device's fuses differ from Table 3-6; add --fuses" in result.out
    usual = isp_server()
    result = hexbot_flash("--image", str(hexfile), "--port", usual.port)
    assert result.code == 0, result.err
    assert "differ from Table 3-6" not in result.out


# --- images -----------------------------------------------------------------

def test_the_last_flash_byte_is_accepted_and_the_next_is_refused(tmp_path):
    last = tmp_path / "last.hex"
    last.write_text(":013FFF00AA17\n:00000001FF\n")  # 0x3FFF, the last of 16 KiB
    assert read_hex(last, limit=16384).data == {0x3FFF: 0xAA}
    beyond = tmp_path / "beyond.hex"
    beyond.write_text(":01400000AA15\n:00000001FF\n")  # 0x4000: one past the flash
    with pytest.raises(FlashingError, match=r"beyond\.hex:1: data at 0x04000 lies beyond"):
        read_hex(beyond, limit=16384)


@needs_avr_gcc
def test_an_elf_given_as_the_image_is_refused_in_words(hexbot_flash, images):
    # the .elf next to the .hex in firmware/build: a binary, not Intel HEX
    elf, _ = images("1.2.3")
    result = hexbot_flash("--image", str(elf), "--port", "/dev/pts/0", "--dry-run")
    assert result.code == 1
    assert f"{elf}: cannot read as Intel HEX" in result.err


def test_a_folder_given_as_the_image_says_so_once(hexbot_flash, tmp_path):
    result = hexbot_flash("--image", str(tmp_path), "--port", "/dev/pts/0", "--dry-run")
    assert result.code == 1
    assert result.err.strip().splitlines()[-1] == (
        f"hexbot flash: error: {tmp_path}: cannot read as Intel HEX: Is a directory")


# --- --all ------------------------------------------------------------------

def test_a_failed_firmware_build_stops_flash_all(hexbot_flash, monkeypatch, tmp_path):
    # make fails: nothing is flashed (the old images would go on otherwise)
    make = tmp_path / "make"
    make.write_text("#!/bin/sh\necho 'comm.c:1: error: boom' >&2\nexit 2\n")
    make.chmod(0o755)
    monkeypatch.setenv("PATH", str(tmp_path))
    result = hexbot_flash("--all", "--scenario", "single", "--build-dir",
                          str(tmp_path / "build"))
    assert result.code == 1
    assert "firmware build failed (make exit 2)" in result.err and "boom" in result.err
    assert "--- module" not in result.out


@needs_avrdude
@needs_avr_gcc
def test_flash_all_expects_the_version_the_build_folder_was_built_with(
        hexbot_flash, firmware_build, monkeypatch):
    # no --firmware-version: the folder's version.stamp says what was built,
    # and the modules must boot that (not the Makefile's default)
    pytest.importorskip("hexbot.hil_sim._avr", reason="simulator extension not built")
    from hexbot.host.flash import cluster

    build = firmware_build("stamp-9")
    monkeypatch.setattr(cluster, "build_firmware", lambda *args, **kwargs: None)
    result = hexbot_flash("--all", "--scenario", "single", "--build-dir", str(build))
    assert result.code == 0, result.err
    assert "every module booted FW=stamp-9: 1" in result.out
