"""The RF12 wireless board image: power-on LEDs, the radio's configuration
words on the bit-banged SPI, and the packet format of the transmit test.

Here the image runs as a module's control MCU with no radio on its pins: we
decode the SPI words from the pin log and play the radio's nIRQ line
ourselves. tests/hil_sim/test_radio.py runs it on wireless boards with the
simulated RF12 and the air between them."""

from __future__ import annotations

import pytest
from fwsim import BUILD, scenario_file

from hexbot.hil_sim import Simulator, load_scenario
from hexbot.protocol.pins import RF12_SPI_PINS

INIT_WORDS = [0x80D7, 0x8239, 0xA640, 0xC647, 0x94A0, 0xC2AC, 0xCA81, 0xCED4,
              0xC483, 0x9850, 0xCC67, 0xE000, 0xC800, 0xC400,
              0x0000]  # status read: clears the power-on interrupt
SEL, SDI, _SDO, SCK = (1 << bit for _port, bit in RF12_SPI_PINS)


@pytest.fixture
def radio(images, tmp_path):
    sim = Simulator(load_scenario(scenario_file(tmp_path, [(1, (0, 0), 0)],
                                                control=BUILD / "rf12.elf")))
    changes: list = []
    sim.pin_sinks.append(changes.extend)
    return sim, changes


def port_values(changes, port: str) -> list[tuple[int, int]]:
    return [(c, v) for c, _m, board, p, v in changes if board == "control" and p == port]


def spi_words(changes) -> list[int]:
    words, word, bits, prev = [], 0, 0, SEL
    for _cycle, value in port_values(changes, "B"):
        if prev & SEL and not value & SEL:
            word, bits = 0, 0
        if not value & SEL and value & SCK and not prev & SCK:
            word, bits = (word << 1) | bool(value & SDI), bits + 1
        if value & SEL and not prev & SEL and bits == 16:
            words.append(word)
        prev = value
    return words


def test_power_on_leds_then_ready_and_configuration(radio):
    sim, changes = radio
    sim.run(2.0)
    raw = [(c, v & 0xC0) for c, v in port_values(changes, "D")]
    # Two writes microseconds apart (one LED off, the other on) are one step.
    leds = [(c, v) for i, (c, v) in enumerate(raw)
            if i + 1 == len(raw) or raw[i + 1][0] - c > 1000]
    leds = [x for i, x in enumerate(leds) if i == 0 or x[1] != leds[i - 1][1]]
    while leds and leds[0][1] == 0:  # port initialisation, LEDs off
        leds.pop(0)
    pattern = [v for _c, v in leds]
    green, red = 0x40, 0x80
    assert pattern[:7] == [green, red, green, red, green, red, 0]
    steps = [b[0] - a[0] for a, b in zip(leds, leds[1:], strict=False) if a[1] != b[1]][:6]
    assert all(abs(s / 1e6 - 0.2) < 0.011 for s in steps), steps
    assert spi_words(changes)[: len(INIT_WORDS)] == INIT_WORDS
    assert sim.debug_read(1) == b"\n\r\n\rRF12 READY MODE=TX FW=0.1.0\n\r"


def test_transmit_test_sends_preamble_sync_payload_and_sum(radio):
    sim, changes = radio
    control = sim.modules[1].control.index
    # nIRQ low from the start: the radio takes every byte of the first packet
    # (with nIRQ high each byte waits out its time-out, so a packet attempt
    # runs ~2 s and where a late nIRQ lands in it depends on the exact tick)
    sim.cluster.set_input(control, "D", 1 << 5, 0)
    sim.run(2.5)
    words = spi_words(changes)[len(INIT_WORDS):]
    sent = [w & 0xFF for w in words if w & 0xFF00 == 0xB800]
    payload = [1, 2, 3, 4, 5, 6, 7, 8, 9] + [0] * 7
    packet = [0xAA, 0xAA, 0xAA, 0x2D, 0xD4, *payload, sum(payload) & 0xFF, 0xAA, 0xAA, 0xAA]
    assert sent[: len(packet)] == packet
    assert words[:2] == [0x0000, 0x8239]  # status read, transmitter on


def test_receive_mode_by_jumper(radio):
    sim, _changes = radio
    control = sim.modules[1].control.index
    sim.cluster.set_input(control, "A", 1, 0)  # jumper closed: receive test
    sim.run(2.0)
    assert sim.debug_read(1).endswith(b"RF12 READY MODE=RX FW=0.1.0\n\r")
    assert sim.modules[1].control.state in ("running", "sleeping")


def test_a_radio_that_takes_no_byte_ends_the_packet_and_never_the_board(radio):
    # nIRQ stays high: no byte is ever taken. The packet ends at its first
    # byte's time-out (transmitter off at once); it used to wait out all 25
    # and the watchdog rebooted the board in the middle of the second packet.
    sim, changes = radio
    sim.run(8.0)
    assert sim.debug_read(1).count(b"RF12 READY") == 1
    words = spi_words(changes)[len(INIT_WORDS):]
    assert words[:3] == [0x0000, 0x8239, 0x8201]  # status, transmitter on, off
    assert not [w for w in words if w & 0xFF00 == 0xB800]


def test_receive_mode_waits_for_packets_without_rebooting(radio):
    sim, _changes = radio
    control = sim.modules[1].control.index
    sim.cluster.set_input(control, "A", 1, 0)  # jumper closed: receive test
    sim.run(10.0)
    assert sim.debug_read(1).count(b"RF12 READY") == 1


def test_after_a_watchdog_reset_the_open_mode_jumper_still_reads_open(radio):
    # Simulator fidelity: PORTA0's pull-up holds the open jumper high. After
    # a watchdog reset the pin read 0 for good (simavr dropped the pull-up's
    # rise as "no change"), and the board came back in receive mode.
    import subprocess

    sim, _changes = radio
    control = sim.modules[1].control.index
    sim.run(2.0)
    assert sim.debug_read(1).endswith(b"MODE=TX FW=0.1.0\n\r")
    nm = subprocess.run(["avr-nm", str(BUILD / "rf12.elf")], check=True,
                        capture_output=True, text=True).stdout
    at = next(int(line.split()[0], 16) for line in nm.splitlines()
              if line.split()[-1] == "rf12_send_packet")
    flash = bytearray(sim.cluster.read_flash(control))
    original = bytes(flash[at:at + 2])
    flash[at:at + 2] = (0xCFFF).to_bytes(2, "little")  # rjmp .-2: hang, the watchdog bites
    sim.cluster.write_flash(control, bytes(flash))
    sim.run(3.0)
    flash[at:at + 2] = original
    sim.cluster.write_flash(control, bytes(flash))
    sim.run(2.5)
    assert sim.debug_read(1).endswith(b"RF12 READY MODE=TX FW=0.1.0\n\r")
    assert sim.modules[1].control.port("A")[2] & 1  # PINA0: jumper open
