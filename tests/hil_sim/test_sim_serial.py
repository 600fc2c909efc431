"""The simulator as a pyserial URL: opened by serial_for_url like any port,
virtual time when stepped, the same bytes for the same seed, clear errors."""

from __future__ import annotations

import pytest
import serial

from hexbot.hil_sim import urlhandler
from hexbot.protocol import timing
from hexbot.protocol.simulation import Moved, Placement, SimulatorAccess

pytest.importorskip("hexbot.hil_sim._avr")
urlhandler.register()


def _boot_text(url: str) -> tuple[bytes, float]:
    with serial.serial_for_url(url, 300, timeout=timing.boot_seconds([1, 2])) as port:
        data = port.read(10_000)  # a time-out in simulated seconds
        return data, port.hexbot_sim.now()


def test_a_stepped_port_reads_the_boot_texts_in_virtual_time():
    data, now = _boot_text("hexbot-sim://pair?speed=0&seed=3")
    assert b"COMM. LISTENING ID=01" in data and b"COMM. LISTENING ID=02" in data
    assert now == pytest.approx(timing.boot_seconds([1, 2]), abs=0.02)


def test_the_same_seed_gives_the_same_bytes():
    assert _boot_text("hexbot-sim://pair?speed=0&seed=3") == \
        _boot_text("hexbot-sim://pair?speed=0&seed=3")


def test_a_frame_gets_its_reply_and_the_access_is_typed():
    with serial.serial_for_url("hexbot-sim://single?speed=0", 300, timeout=10) as port:
        port.read_until(b"ID=01 FW=0.1.0\n\r")
        port.write(b"*FNNNNNNNN#")  # Status (70), legacy mode
        port.timeout = 3
        assert b"STA\x01M" in port.read(200)
        access = port.hexbot_sim
        assert isinstance(access, SimulatorAccess) and access.stepped
        assert access.placements() == {1: Placement((0, 0), 0)}
        assert access.actuators(1) == {"joints": [0] * 6, "magnets": [0] * 6, "led_joints": [0] * 6,
                                       "led_pos": [0] * 6, "led_neg": [0] * 6}


def test_a_paced_port_runs_on_its_own():
    with serial.serial_for_url("hexbot-sim://single?speed=50", 300, timeout=5) as port:
        assert port.read_until(b"COMM. BOARD READY").endswith(b"COMM. BOARD READY")
        assert not port.hexbot_sim.stepped


def test_the_debug_port_of_a_module_opens_on_the_same_cluster():
    with serial.serial_for_url("hexbot-sim://pair?speed=0", 300, timeout=3) as ir:
        url = ir.hexbot_sim.uart1_url(2)
        with serial.serial_for_url(url, 4800, timeout=0) as debug:
            assert debug.hexbot_sim is ir.hexbot_sim
            ir.read(10_000)  # three simulated seconds of boot
            assert debug.in_waiting > 0  # the control board's boot text on UART1
        with pytest.raises(serial.SerialException, match="no module 9"):
            serial.serial_for_url(url.replace("/2", "/9"))


def test_plant_verdicts_are_typed():
    with serial.serial_for_url("hexbot-sim://pair?speed=0", 300, timeout=timing.boot_seconds([2])
                               ) as port:
        port.read(10_000)
        # Table 3-1's example: module 2 CW about its joint 4, module 1 supports
        for frame in (b"*E\x02NNNNNNN#", b"*G\x01NNNNNNN#", b"*E\x01NNNNNNN#",
                      b"*G\x02NNNNNNN#", b"*E\x01\x02NNNNNN#",
                      bytes([42, 67, 4, 8, 4, 10, 4, 8, 5, 9, 35])):
            port.write(frame)
            port.timeout = 3
            port.read(10_000)
        (verdict,) = port.hexbot_sim.verdicts()
        assert isinstance(verdict, Moved)
        assert (verdict.module, verdict.dst, verdict.orientation) == (2, (0, 1), 2)


@pytest.mark.parametrize("url, why", [
    ("hexbot-sim://pair?sped=0", "unknown option"),
    ("hexbot-sim://pair?speed=fast", "speed a number"),
    ("hexbot-sim://nowhere?speed=0", "nowhere"),
    ("hexbot-sim://?speed=0", "name a scenario"),
    ("hexbot-sim://@999/uart1/1", "no such simulated port"),
])
def test_bad_urls_say_why(url, why):
    with pytest.raises(serial.SerialException, match=why):
        serial.serial_for_url(url)
