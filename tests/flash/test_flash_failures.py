"""How ``hexbot flash`` fails: exit statuses (docs/console.md), a port lost
mid-write, avrdude 6.x's wording, bad option values, options --all ignores."""

from __future__ import annotations

import threading
import time
from pathlib import Path

import pytest
from conftest import needs_avrdude

from hexbot.hil_sim.isp import Atmega162Isp, IspPtyServer, MemoryBackend, Stk500v2Programmer
from hexbot.host.flash import avrdude as avrdude_mod
from hexbot.host.flash.avrdude import explain
from hexbot.host.flash.cluster import not_booted

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


@pytest.mark.parametrize("baud", ["0", "-5", "fast"])
def test_a_baud_rate_must_be_a_positive_whole_number(hexbot_flash, baud, capsys):
    with pytest.raises(SystemExit) as exit_:
        hexbot_flash("--image", "x.hex", "--port", "/dev/pts/0", "--baud", baud, "--dry-run")
    assert exit_.value.code == 2
    assert "--baud" in capsys.readouterr().err


@pytest.mark.parametrize(("option", "value"), [("--image", "x.hex"), ("--programmer", "avrisp2"),
                                               ("--baud", "115200"), ("--bitclock", "10")])
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
