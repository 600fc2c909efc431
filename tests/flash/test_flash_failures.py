"""How ``hexbot flash`` fails: exit statuses (docs/console.md), a port lost
mid-write, avrdude 6.x's wording, bad option values, options --all ignores."""

from __future__ import annotations

import threading
import time
from pathlib import Path

import pytest

from hexbot.hil_sim.isp import Atmega162Isp, IspPtyServer, MemoryBackend, Stk500v2Programmer
from hexbot.host.flash import avrdude as avrdude_mod
from hexbot.host.flash.avrdude import explain
from hexbot.host.flash.cluster import not_booted
from tests.flash.marks import needs_avrdude

AUDIT_63 = (  # avrdude 6.3 (Ubuntu 22.04, Debian 11) on a port that is not there
    'avrdude: ser_open(): can\'t open device "/dev/ttyUSB0": No such file or directory\n'
    "\n"
    "avrdude done.  Thank you.\n"
    "\n"
)


def fake_avrdude(tmp_path: Path, stderr: str, status: int = 1) -> Path:
    script = tmp_path / "fake-avrdude"
    script.write_text(f"#!/bin/sh\ncat >&2 <<'T'\n{stderr}T\nexit {status}\n")
    script.chmod(0o755)
    return script


def test_avrdude_6_errors_have_a_reason_and_a_missing_port_exits_4(hexbot_flash, images,
                                                                   tmp_path):
    _, hexfile = images("1.2.3")
    result = hexbot_flash("--image", str(hexfile), "--port", "/dev/ttyUSB0",
                          "--avrdude", str(fake_avrdude(tmp_path, AUDIT_63)))
    assert result.code == 4, result.err
    assert ('avrdude failed: ser_open(): can\'t open device "/dev/ttyUSB0": '
            "No such file or directory") in result.err
    assert "is the programmer plugged in at /dev/ttyUSB0" in result.err


def test_avrdude_6_reason_is_the_last_line_that_says_something():
    stderr = ("avrdude: stk500v2_ReceiveMessage(): timeout\n"
              "avrdude: stk500v2_getsync(): timeout communicating with programmer\n\n"
              "avrdude done.  Thank you.\n\n")
    text = explain(stderr, "/dev/ttyUSB0", "stk500v2")
    assert text.startswith(
        "avrdude failed: stk500v2_getsync(): timeout communicating with programmer")
    assert "no stk500v2 programmer answered on /dev/ttyUSB0" in text


@needs_avrdude
def test_a_port_lost_mid_write_is_stopped_and_exits_4(images, hexbot_flash, monkeypatch):
    monkeypatch.setattr(avrdude_mod, "NO_PROGRESS_S", 2.0)
    monkeypatch.setattr(avrdude_mod, "WRITE_TIMEOUT_S", 20.0)  # without the watchdog: 20 s
    backend = MemoryBackend()
    programmer = Stk500v2Programmer(Atmega162Isp(backend))
    server = IspPtyServer()
    port = server.add("chip", programmer)
    written = threading.Event()
    feed = programmer.feed

    def feed_until_a_page_is_written(data: bytes) -> bytes:
        answer = feed(data)
        if backend.memory.flash != b"\xff" * len(backend.memory.flash):
            written.set()  # erased and one page written: unplug, no answer
            return b""
        return answer

    programmer.feed = feed_until_a_page_is_written
    server.start()
    unplug = threading.Thread(target=lambda: written.wait(60) and server.close(), daemon=True)
    unplug.start()
    _, hexfile = images("1.2.3")
    try:
        start = time.monotonic()
        result = hexbot_flash("--image", str(hexfile), "--port", port)
        elapsed = time.monotonic() - start
    finally:
        written.set()
        server.close()
    assert result.code == 4, result.err
    assert "no output for 2 s" in result.err and port in result.err
    assert "the chip may be erased" in result.err and "flash it again" in result.err
    assert elapsed < 15


@pytest.mark.parametrize(("option", "value"), [
    ("--baud", "0"), ("--baud", "-5"), ("--baud", "fast"),
    # a fuse value must fit in a byte (session 33's audit)
    ("--lfuse", "0x100"), ("--lfuse", "256"), ("--lfuse", "-1"),
])
def test_a_bad_number_is_a_usage_error(hexbot_flash, option, value, capsys):
    with pytest.raises(SystemExit) as exit_:
        hexbot_flash("--image", "x.hex", "--port", "/dev/pts/0", option, value, "--dry-run")
    assert exit_.value.code == 2
    assert option in capsys.readouterr().err


@pytest.mark.parametrize(("option", "value"), [("--image", "x.hex"), ("--programmer", "avrisp2"),
                                               ("--baud", "115200"), ("--bitclock", "10"),
                                               ("--port", "/dev/ttyUSB0"), ("--board", "comm")])
def test_all_refuses_options_it_would_ignore(hexbot_flash, option, value):
    result = hexbot_flash("--all", "--scenario", "pair", "--dry-run", option, value)
    assert result.code == 2
    assert f"{option} cannot be used with --all" in result.err
    assert "---" not in result.out  # refused before any board


def test_boards_that_do_not_boot_the_flashed_version_are_named():
    heard = ("COMM. BOARD READY FW=audit-1\n\n\nCOMM. LISTENING ID=00 FW=audit-1\n"
             "COMM. LISTENING ID=02 FW=audit-1\nCOMM. LISTENING ID=03 FW=old\n")
    assert not_booted([1, 2, 3], heard, "audit-1") == [
        "1 (no COMM. LISTENING with its id)", "3 (booted FW=old)"]
    assert not_booted([1, 2], "COMM. LISTENING ID=01 FW=v COMM. LISTENING ID=02 FW=v",
                      "v") == []


@pytest.mark.parametrize(("argv", "words"), [
    ((), "give --board comm|control"),
    (("--board", "control"), "give --port"),
    (("--all",), "--all needs --scenario"),
    (("--board", "control", "--port", "/dev/pts/0", "--scenario", "pair", "--dry-run"),
     "--scenario only go with --all"),
    (("--board", "control", "--port", "/dev/pts/0", "--firmware-version", "9.9.9",
      "--dry-run"), "--firmware-version only go with --all"),
])
def test_missing_or_misplaced_options_are_usage_errors(hexbot_flash, argv, words):
    """Exit 2 before any work, as docs/console.md says; options a board flash
    does not read are refused, not dropped (the user would think 9.9.9 went on)."""
    result = hexbot_flash(*argv)
    assert result.code == 2, result.err
    assert words in result.err


def test_a_version_the_boot_text_cannot_carry_is_a_usage_error(hexbot_flash, capsys):
    with pytest.raises(SystemExit) as exit_:
        hexbot_flash("--all", "--scenario", "single", "--firmware-version", "1.0 beta")
    assert exit_.value.code == 2
    assert "no spaces or quotes" in capsys.readouterr().err


def test_an_unknown_scenario_is_refused_before_the_firmware_is_rebuilt(hexbot_flash):
    result = hexbot_flash("--all", "--scenario", "nosuch")
    assert result.code == 4 and "unknown scenario 'nosuch'" in result.err
    assert "building:" not in result.out


def test_a_missing_make_is_named_not_a_traceback(hexbot_flash, monkeypatch, tmp_path):
    monkeypatch.setenv("PATH", str(tmp_path))  # nothing to run here
    result = hexbot_flash("--all", "--scenario", "single")
    assert result.code == 1
    assert "cannot run make" in result.err and "apt-get install make" in result.err


def test_an_avrdude_that_reads_nothing_back_is_a_reason_not_a_traceback(hexbot_flash, images,
                                                                        tmp_path):
    _, hexfile = images("1.2.3")
    result = hexbot_flash("--image", str(hexfile), "--port", "/dev/ttyUSB0",
                          "--avrdude", str(fake_avrdude(tmp_path, "", status=0)))
    assert result.code == 1
    assert "ended without reading the device: no signature came back" in result.err


AVRDUDE_71_FUSE_MISMATCH = (
    "avrdude: verifying hfuse memory against 0xF9\n"
    "avrdude warning: verification mismatch\n"
    "        device 0xd9 != input 0xf9 at addr 0x0000 (error)\n"
    "avrdude error: verification mismatch\n\navrdude done.  Thank you.\n")


def test_a_fuse_that_does_not_read_back_is_named_with_both_values():
    text = explain("avrdude: 4118 bytes of flash verified\n" + AVRDUDE_71_FUSE_MISMATCH,
                   "/dev/pts/0", "stk500v2")
    assert text == ("avrdude failed: verification mismatch (the hfuse reads back 0xd9, not "
                    "0xf9: some fuse bits cannot be changed over ISP (SPIEN), or lock bits "
                    "block the write)")
    flash = explain("avrdude: verifying flash memory against x.hex\n"
                    "avrdude error: verification mismatch\n"
                    "        device 0xff != input 0x0c at addr 0x0000 (error)\n",
                    "/dev/pts/0", "stk500v2")
    assert "the flash reads back 0xff, not 0x0c (lock bits set? worn flash?)" in flash
