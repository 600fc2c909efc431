"""Cluster API of the ATmega162 core: memories, fuses, inputs, errors."""

import subprocess
import sys
from pathlib import Path

import pytest

from hexbot.hil_sim._avr import Cluster

AVR_DIR = Path(__file__).parent / "avr"
UCSR0A = 0x2B  # data address


def build(name: str, mcu: str = "atmega162") -> str:
    target = f"build/{name}.{mcu}.elf"
    subprocess.run(["make", "-s", "-C", str(AVR_DIR), target], check=True)
    return str(AVR_DIR / target)


def test_part_identity_and_memory_sizes():
    c = Cluster()
    m = c.add_mcu(build("echo"), "echo")
    assert c.signature(m) == bytes([0x1E, 0x94, 0x04])
    assert c.fuses(m) == (0x62, 0xD9, 0xFF)
    assert len(c.read_flash(m)) == 16 * 1024
    assert len(c.read_eeprom(m)) == 512
    assert len(c.read_data(m, 0, 0x500)) == 0x500  # registers, I/O, 1 KiB SRAM at 0x100
    with pytest.raises(ValueError, match="outside"):
        c.read_data(m, 0x4FF, 2)
    assert c.frequency == 1_000_000
    assert c.name(m) == "echo"


def test_fuses_signature_and_eeprom_are_writable():
    c = Cluster()
    m = c.add_mcu(build("echo"), "echo")
    c.set_fuses(m, 0xE2, 0x99, 0xFB)
    assert c.fuses(m) == (0xE2, 0x99, 0xFB)
    c.set_signature(m, b"\x1e\x95\x02")
    assert c.signature(m) == b"\x1e\x95\x02"
    c.write_eeprom(m, 510, b"\x01\x02")
    assert c.read_eeprom(m)[510:] == b"\x01\x02"
    with pytest.raises(ValueError, match="EEPROM range"):
        c.write_eeprom(m, 511, b"\x01\x02")


def test_write_flash_and_reset_runs_the_new_program():
    other = Cluster()
    idle_image = other.read_flash(other.add_mcu(build("idle"), "idle"))
    c = Cluster()
    m = c.add_mcu(build("echo"), "echo")
    c.run(1_000)
    c.write_flash(m, idle_image.rstrip(b"\xff"))
    assert c.read_flash(m) == idle_image
    c.reset(m)
    c.run(30_000)
    assert [p for _, p, _ in c.pin_log(m)].count("A") == 2  # idle.c's 10 ms tick on PA0


def test_set_input_drives_pins_over_pull_ups():
    c = Cluster()
    m = c.add_mcu(build("dip"), "dip")
    c.run(1_000)
    assert c.port(m, "B")[1] == 0xFF  # open switches read high via pull-ups
    c.set_input(m, "C", 0xFF, 0x2A)
    c.run(2_000)
    assert c.port(m, "C") == (0x00, 0xFF, 0x2A)
    assert c.port(m, "B")[1] == 0x2A
    c.set_input(m, "C", 0x0F, 0x05)
    c.run(3_000)
    assert c.port(m, "B")[1] == 0x25


def test_dip_switches_survive_a_reset():
    # A reset (ISP, watchdog) does not unplug the switches: the firmware must
    # read the same module id after it, without set_input being repeated.
    c = Cluster()
    m = c.add_mcu(build("dip"), "dip")
    c.set_input(m, "C", 0xFF, 0x2A)
    c.run(2_000)
    c.reset(m)
    c.run(c.cycle + 2_000)
    assert c.port(m, "C")[2] == 0x2A
    assert c.port(m, "B")[1] == 0x2A


def test_external_int0_falling_edge():
    c = Cluster()
    m = c.add_mcu(build("dip"), "dip")
    c.run(1_000)
    c.set_input(m, "D", 0x04, 0x00)  # press
    c.run(2_000)
    c.set_input(m, "D", 0x04, 0x04)  # release: rising edge, ignored
    c.run(3_000)
    c.set_input(m, "D", 0x04, 0x00)
    c.run(4_000)
    assert c.port(m, "A")[1] == 2


def test_receiver_buffer_overrun_and_framing_error():
    c = Cluster()
    m = c.add_mcu(build("echo"), "echo")
    c.run(1_000)
    # two-byte FIFO plus the shift register; the fourth byte overruns
    assert [c.uart_put(m, 0, b) for b in (1, 2, 3, 4)] == [True, True, True, False]
    assert c.uart_config(m, 0)["rx_dropped"] == 1
    c.run(20_000)
    c.uart_put(m, 0, 0x33, framing_error=True)
    c.run(20_010)
    assert c.read_data(m, UCSR0A, 1)[0] & 0x10  # FE0


def test_bad_arguments_are_clear_errors(tmp_path):
    c = Cluster()
    with pytest.raises(FileNotFoundError, match="nope.elf"):
        c.add_mcu(str(tmp_path / "nope.elf"), "x")
    junk = tmp_path / "junk.elf"
    junk.write_bytes(b"not an elf")
    with pytest.raises(ValueError, match="junk.elf: not an ELF file"):
        c.add_mcu(str(junk), "x")
    with pytest.raises(ValueError, match="not for the AVR"):
        c.add_mcu("/bin/sh", "x")
    with pytest.raises(ValueError, match="unknown MCU core"):
        c.add_mcu(build("echo"), "x", core="atmega999")
    m = c.add_mcu(build("echo"), "echo")
    with pytest.raises(IndexError):
        c.state(m + 1)
    with pytest.raises(ValueError, match="USART 2"):
        c.uart_put(m, 2, 0)
    with pytest.raises(ValueError, match="port 'F'"):
        c.port(m, "F")
    with pytest.raises(ValueError, match="0..255"):
        c.uart_put(m, 0, 256)
    with pytest.raises(ValueError, match="not watched"):
        c.uart_take(m, 0)
    with pytest.raises(ValueError, match="quantum"):
        Cluster(0)


def test_low_level_int0_repeats_while_the_pin_stays_low():
    c = Cluster()
    m = c.add_mcu(build("level"), "level")
    c.run(1_000)
    assert c.port(m, "A")[1] == 0 and c.state(m) == "sleeping"
    c.set_input(m, "D", 0x04, 0x00)
    c.run(2_000)
    assert c.port(m, "A")[1] == 5  # then the handler disabled INT0
    c.set_input(m, "D", 0x04, 0x04)
    c.set_input(m, "D", 0x04, 0x00)
    c.run(50_000)
    assert c.port(m, "A")[1] == 5
    # a low pin with its interrupt off does not keep the sleeping CPU awake
    assert c.state(m) == "sleeping" and c.mcu_cycle(m) == 50_000


def test_int2_and_pin_change_interrupts():
    c = Cluster()
    m = c.add_mcu(build("dip"), "dip")
    c.run(1_000)
    c.set_input(m, "C", 0xFF, 0x2A)  # several PORTC pins change at once
    c.run(2_000)
    assert c.port(m, "E")[1] & 0x06 == 0x02  # one PCINT1 request
    c.set_input(m, "C", 0xFF, 0x2A)  # no change, no interrupt
    c.run(3_000)
    assert c.port(m, "E")[1] & 0x06 == 0x02
    c.set_input(m, "E", 0x01, 0x00)  # INT2 falling edge
    c.run(4_000)
    assert c.port(m, "A")[1] == 0x10


def test_simavr_prints_nothing_even_when_firmware_crashes_or_talks():
    script = (
        "from hexbot.hil_sim._avr import Cluster\n"
        "c = Cluster()\n"
        f"for elf in {[build('badop'), build('echo'), build('peripherals')]!r}:\n"
        "    c.add_mcu(elf, 'x')\n"
        f"c.add_mcu({build('peripherals', 'atmega128')!r}, 'stock', 'atmega128')\n"
        "c.run(100_000)\n"
        "assert c.state(0) == 'crashed'\n"
    )
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert done.stdout == "" and done.stderr == ""
