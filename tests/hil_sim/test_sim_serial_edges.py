"""Edges of the ``hexbot-sim://`` port a user meets: bad speeds and baud
rates refused when the port opens, bytes written at a wrong baud rate
garbled on the way to the module (not only on the way back), the input
buffer really emptied, and a simulator fault raised by the first
``advance`` that meets it."""

from __future__ import annotations

import pytest
import serial

from hexbot.hil_sim import urlhandler
from hexbot.protocol import timing

pytest.importorskip("hexbot.hil_sim._avr")
urlhandler.register()

STATUS = b"*FNNNNNNNN#"  # Status (70), legacy mode


@pytest.mark.parametrize("speed", ["-1", "nan", "inf"])
def test_a_speed_that_cannot_run_is_refused(speed):
    # a negative or nan speed would give a port on a cluster that never
    # advances: reads would time out in silence
    with pytest.raises(serial.SerialException, match="speed must be a number 0 or more"):
        serial.serial_for_url(f"hexbot-sim://single?speed={speed}")


def test_a_baud_rate_of_zero_is_refused_when_the_port_opens():
    # pyserial accepts 0; the simulated line cannot sample at it
    with pytest.raises(serial.SerialException, match="baud must be positive"):
        serial.serial_for_url("hexbot-sim://single?speed=0", baudrate=0)


def test_a_frame_written_at_the_wrong_baud_rate_does_not_reach_the_module():
    with serial.serial_for_url("hexbot-sim://single?speed=0", 300, timeout=10) as port:
        port.read_until(b"ID=01 FW=0.1.0\n\r")
        port.baudrate = 9600
        port.write(STATUS)  # at 9600: a glitch to the 300-baud module
        port.baudrate = 300
        port.timeout = 3
        assert b"STA" not in port.read(200)
        port.write(STATUS)  # the same frame at the modules' rate is answered
        assert b"STA\x01M" in port.read(200)


def test_reset_input_buffer_discards_what_was_received():
    with serial.serial_for_url("hexbot-sim://single?speed=0", 300, timeout=0) as port:
        port.hexbot_sim.advance(timing.boot_seconds([1]))
        assert port.in_waiting > 0  # the boot texts
        port.reset_input_buffer()
        assert port.in_waiting == 0
        assert port.read(100) == b""


def test_advance_raises_when_the_simulator_stops():
    # the first advance that meets the fault says so; it must not return as
    # if simulated time had passed
    def broken(seconds):
        raise RuntimeError("injected fault")

    with serial.serial_for_url("hexbot-sim://single?speed=0", 300, timeout=1) as port:
        access = port.hexbot_sim
        access.simulator.run = broken
        before = access.now()
        with pytest.raises(serial.SerialException,
                           match="the simulator stopped: RuntimeError: injected fault"):
            access.advance(0.5)
        assert access.now() == before
