"""`hexbot sim --rfc2217`: the simulated IR port over RFC 2217, so that a
pyserial client can set modem lines and parity as on a USB adapter (a pty
cannot), and the host drives the cluster through it unchanged."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest
import serial

HEXBOT = Path(sys.executable).with_name("hexbot")


@pytest.fixture
def rfc2217_url():
    proc = subprocess.Popen([str(HEXBOT), "sim", "pair", "--rfc2217", "0", "--speed", "20"],
                            stdout=subprocess.PIPE, text=True)
    try:
        yield json.loads(proc.stdout.readline())["rfc2217"]
    finally:
        proc.terminate()
        assert proc.wait(timeout=30) == 0  # SIGTERM ends the server cleanly


def send_status(url: str, *extra: str) -> subprocess.CompletedProcess:
    return subprocess.run([str(HEXBOT), "send", "Status", "--module", "2", "--port", url,
                           *extra], capture_output=True, text=True, timeout=120)


def until_booted(url: str) -> subprocess.CompletedProcess:
    """The cluster boots in its first simulated seconds; ask until it answers."""
    for _ in range(5):
        done = send_status(url)
        if done.returncode == 0:
            break
    return done


def test_modem_lines_and_parity_are_accepted_as_by_an_adapter(rfc2217_url):
    with serial.serial_for_url(rfc2217_url, baudrate=300, timeout=1) as port:
        port.dtr = False
        port.rts = True
        assert port.cts and port.dsr  # not wired on HexBot's converter: read high
        port.parity = serial.PARITY_EVEN
        port.bytesize = serial.SEVENBITS
        port.parity = serial.PARITY_NONE
        port.bytesize = serial.EIGHTBITS


def test_the_host_commands_a_module_through_rfc2217(rfc2217_url):
    done = until_booted(rfc2217_url)
    assert done.returncode == 0, done.stderr
    assert "STA id 2 role M" in done.stdout


def test_a_wrong_baud_rate_garbles_the_link_as_on_hardware(rfc2217_url):
    assert until_booted(rfc2217_url).returncode == 0
    done = send_status(rfc2217_url, "--baud", "9600")
    assert done.returncode != 0
    assert "no reply from module 2" in done.stderr or "garbled" in done.stderr.lower()
