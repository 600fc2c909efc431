"""Simulated serial lines garble bytes when the two ends disagree, as real
UARTs do (issue 13, defect 7): on the hexbot-sim:// URL and on the ptys of
``hexbot sim --pty``."""

from __future__ import annotations

import serial

from hexbot.hil_sim import urlhandler
from hexbot.hil_sim.uart_line import LineSettings, resample
from hexbot.protocol import timing
from hexbot.protocol.parser import Text, parse_all

REPLY = b"\n\r\n\rM02: ACKD\n\r"
LINE = LineSettings(300)


def test_the_same_settings_pass_bytes_unchanged_and_stop_bits_do_not_matter():
    assert resample(REPLY, LINE, LINE) == REPLY
    assert resample(REPLY, LINE, LineSettings(300, stop_bits=2)) == REPLY


def test_a_fast_receiver_reads_breaks_and_a_wrong_parity_reads_other_bytes():
    fast = resample(REPLY, LINE, LineSettings(9600))
    # each run of low bits reads as a NUL (a break): at least one a byte, its start bit
    assert set(fast) == {0} and len(fast) > len(REPLY)
    assert resample(REPLY, LINE, LineSettings(300, parity="E")) != REPLY
    assert resample(REPLY, LINE, LineSettings(300, data_bits=7)) != REPLY
    # and the other way: a frame sent at 9600 is a glitch to a 300-baud module
    assert b"*F" not in resample(b"*FNNNNNNNN#", LineSettings(9600), LINE)


def test_a_low_line_is_read_once_however_fast_the_receiver():
    # (fuzz, session 37) the receiver re-armed on a line still low after a
    # framing error and read a NUL per frame time of it: a port at 4,000,000
    # baud read 13,000 per 300-baud bit, and at 10**11 the host never got
    # past the boot. A start bit is a falling edge: the 9 low bits of a NUL
    # sent at 300 are one break, and a faster port reads no more than 9600 does
    assert resample(b"\x00", LINE, LineSettings(9600)) == b"\x00"
    assert resample(b"\x00", LINE, LineSettings(4_000_000)) == b"\x00"
    fast = resample(REPLY, LINE, LineSettings(9600))
    assert resample(REPLY, LINE, LineSettings(4_000_000)) == fast


def test_a_receiver_that_comes_on_mid_line_starts_only_on_a_falling_edge():
    from hexbot.hil_sim.uart_line import levels, read_first

    wave = levels(0x5A, LINE, 0.0, 10.0)  # bits of 10: 0x5A's bit 2 falls at 30
    assert read_first(wave, LINE, 10.0) == (0x5A, False)
    assert read_first(wave, LINE, 10.0, since=25.0) == (0xEB, False)  # bit 2's edge
    assert read_first(wave, LINE, 10.0, since=30.0) == (0xEB, False)  # the edge at since counts
    assert read_first(wave, LINE, 10.0, since=30.5) == (0xFD, False)  # low there: bit 5's edge
    assert read_first(wave, LINE, 10.0, since=0.0) == read_first(wave, LINE, 10.0)
    assert read_first(wave, LINE, 10.0, since=81.0) is None  # bit 7 low, then only high


def test_bit_times_in_cycles_read_as_the_core_reads_them():
    # an off-nominal clock: bit times that are not whole cycles, one rule
    from hexbot.hil_sim.uart_line import first_byte

    tx, rx = LineSettings(300), LineSettings(600)
    assert first_byte(0x5A, tx, rx) == first_byte(0x5A, tx, rx, (3328.0, 1664.0))
    assert first_byte(0x5A, tx, rx, (3328 * 1e6 / 1_013_000, 1664 * 1e6 / 987_000)) == (0x98, False)


def _boot_texts(**settings) -> list[str]:
    urlhandler.register()
    with serial.serial_for_url("hexbot-sim://single?speed=0", timeout=timing.boot_seconds([1]),
                               **settings) as port:
        port.dtr, port.rts = False, True  # accepted as a USB adapter accepts them
        assert port.cts and port.dsr
        data = port.read(200)
    return [e.phrase for e in parse_all(data) if isinstance(e, Text)]


def test_the_url_port_reads_the_boot_only_with_the_modules_settings():
    assert "COMM. LISTENING" in _boot_texts(baudrate=300)
    assert _boot_texts(baudrate=9600) == []
    assert _boot_texts(baudrate=300, parity="E") == []


def test_a_pty_client_at_the_wrong_baud_reads_garbage():
    from hexbot.host.simproc import SimProcess

    # --wait-client: at speed 0 the boot can be over before pyserial opens the
    # port, and pyserial flushes its input on open (CI failed on that race)
    with SimProcess("single", speed=0, wait_client=True) as sim:
        with serial.Serial(sim.ports.ir, 300, timeout=30) as port:
            boot = port.read_until(b"COMM. LISTENING")
        with serial.Serial(sim.ports.ir, 9600, timeout=1.0) as port:
            port.write(b"*FNNNNNNNN#")  # Status, but at 9600: a glitch to the module
            wrong = port.read(400)
        with serial.Serial(sim.ports.ir, 300, timeout=10) as port:
            port.write(b"*FNNNNNNNN#")
            right = port.read_until(b"STA\x01")
    assert boot.endswith(b"COMM. LISTENING")
    assert b"STA" not in wrong
    assert right.endswith(b"STA\x01")


def test_the_bridge_reads_the_rate_a_pty_client_set():
    from hexbot.hil_sim.pty_bridge import _Port

    port = _Port.open(300)
    try:
        assert port.to_client(REPLY) == REPLY  # nobody set anything: the modules' rate
        with serial.Serial(port.name, 9600) as client:
            assert port.client_line() == LineSettings(9600)
            assert port.to_client(REPLY) == resample(REPLY, LINE, LineSettings(9600))
            client.baudrate = 300
            assert port.to_client(REPLY) == REPLY
    finally:
        port.close()
