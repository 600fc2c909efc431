"""Real avrdude (``-c stk500v2 -p m162``) against the simulated programmer."""

from __future__ import annotations

import os
import select
import subprocess

import pytest

from hexbot.hil_sim.isp import Atmega162Memory
from hexbot.hil_sim.isp.avr068 import ANSWER_CKSUM_ERROR
from hexbot.hil_sim.isp.framing import FrameDecoder, encode
from hexbot.host.flash.ihex import read_hex
from tests.flash.marks import needs_avrdude

pytestmark = needs_avrdude


def avrdude(port: str, *ops: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(["avrdude", "-c", "stk500v2", "-P", port, "-p", "m162", *ops],
                          capture_output=True, text=True, timeout=120)


def test_avrdude_reads_signature_and_fuses(isp_server):
    chip = isp_server(Atmega162Memory(lfuse=0xE2, lock=0xFE))
    proc = avrdude(chip.port, "-U", "signature:r:-:h", "-U", "lfuse:r:-:h",
                   "-U", "hfuse:r:-:h", "-U", "efuse:r:-:h", "-U", "lock:r:-:h")
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout.split() == ["0x1e,0x94,0x4", "0xe2", "0xd9", "0xff", "0xfe"]
    assert "device signature = 0x1e9404" in proc.stderr


def test_hexbot_flash_writes_and_verifies_a_fresh_image(isp_server, images, hexbot_flash):
    chip = isp_server()
    chip.memory.eeprom[:4] = b"\x01\x02\x03\x04"  # chip erase without EESAVE clears it
    _, hexfile = images("1.2.3")
    result = hexbot_flash("--board", "control", "--image", str(hexfile), "--port", chip.port)
    assert result.code == 0, result.err
    image = read_hex(hexfile).to_bytes()
    assert f"{len(image)} bytes of flash written, {len(image)} verified" in result.out
    assert "found an ATmega162 (signature 1E 94 04)" in result.out
    assert bytes(chip.memory.flash[:len(image)]) == image
    assert chip.memory.flash[len(image):] == b"\xff" * (16384 - len(image))
    assert chip.memory.eeprom[:4] == b"\xff" * 4


def test_fuses_are_written_only_when_asked(isp_server, images, hexbot_flash):
    chip = isp_server(Atmega162Memory(lfuse=0xE2))
    _, hexfile = images("1.2.3")
    assert hexbot_flash("--image", str(hexfile), "--port", chip.port).code == 0
    assert chip.memory.lfuse == 0xE2
    result = hexbot_flash("--image", str(hexfile), "--port", chip.port, "--fuses")
    assert result.code == 0, result.err
    assert (chip.memory.lfuse, chip.memory.hfuse, chip.memory.efuse) == (0x62, 0xD9, 0xFF)


def test_refuses_a_device_that_is_not_an_atmega162(isp_server, images, hexbot_flash):
    chip = isp_server(Atmega162Memory(signature=bytes.fromhex("1e950f")))
    _, hexfile = images("1.2.3")
    result = hexbot_flash("--image", str(hexfile), "--port", chip.port)
    assert result.code == 1
    assert "signature 1E 95 0F (m328p), not an ATmega162 (1E 94 04)" in result.err
    assert chip.memory.flash == b"\xff" * 16384


@pytest.mark.parametrize(
    ("option", "value", "reason"),
    [("--hfuse", "0xF9", "SPIEN unprogrammed"), ("--lock", "0xFC", "lock mode 3"),
     ("--lfuse", "0x6F", "nothing on XTAL1/XTAL2")],
)
def test_refuses_dangerous_fuses_unless_forced(isp_server, images, hexbot_flash,
                                               option, value, reason):
    chip = isp_server()
    _, hexfile = images("1.2.3")
    result = hexbot_flash("--image", str(hexfile), "--port", chip.port, option, value)
    assert result.code == 1 and "refusing to write fuses" in result.err and reason in result.err
    assert chip.programmer.stats.frames == 0  # refused before talking to the device


def test_forced_lock_bits_are_written_and_cleared_by_the_next_flash(isp_server, images,
                                                                    hexbot_flash):
    chip = isp_server()
    _, hexfile = images("1.2.3")
    result = hexbot_flash("--image", str(hexfile), "--port", chip.port, "--lock", "0xFC",
                          "--force")
    assert result.code == 0, result.err
    assert "WARNING" in result.out and chip.memory.lock == 0xFC
    # locked: the next run sees it, erases (which unlocks) and verifies again
    result = hexbot_flash("--image", str(hexfile), "--port", chip.port)
    assert result.code == 0, result.err
    assert "lock 0xFC" in result.out and chip.memory.lock == 0xFF


def test_wrong_checksum_is_answered_like_the_programmer_then_avrdude_works(isp_server):
    chip = isp_server()
    fd = os.open(chip.port, os.O_RDWR | os.O_NOCTTY)
    try:
        frame = bytearray(encode(0x21, b"\x01"))
        frame[-1] ^= 0xFF
        os.write(fd, bytes(frame))
        decoder, messages = FrameDecoder(), []
        while not messages and select.select([fd], [], [], 5.0)[0]:
            messages += decoder.feed(os.read(fd, 64))
    finally:
        os.close(fd)
    assert [(m.seq, m.body) for m in messages] == [(0x21, bytes((ANSWER_CKSUM_ERROR,) * 2))]
    assert avrdude(chip.port, "-U", "signature:r:-:h").returncode == 0


def test_avrdude_errors_reach_the_user_in_words(hexbot_flash, images, tmp_path):
    _, hexfile = images("1.2.3")
    result = hexbot_flash("--image", str(hexfile), "--port", str(tmp_path / "ttyNONE"))
    assert result.code == 4  # a missing port: docs/console.md's exit table
    assert "cannot open port" in result.err and "is the programmer plugged in" in result.err


def test_a_chip_that_does_not_answer_is_reported_with_the_likely_cause(isp_server, images,
                                                                       hexbot_flash):
    chip = isp_server(Atmega162Memory(hfuse=0xF9))  # SPIEN off: silent on SPI
    _, hexfile = images("1.2.3")
    result = hexbot_flash("--image", str(hexfile), "--port", chip.port)
    assert result.code == 1
    assert "did not enter programming mode" in result.err and "jumper" in result.err
