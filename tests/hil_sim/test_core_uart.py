"""USART behaviour of the ATmega162 core: URSEL, exact frame timing, echo, drops."""

import subprocess
from pathlib import Path

import pytest

from hexbot.hil_sim._avr import Cluster

AVR_DIR = Path(__file__).parent / "avr"


def build(name: str, mcu: str = "atmega162") -> str:
    """Compile one test program (make is a no-op when it is up to date)."""
    target = f"build/{name}.{mcu}.elf"
    subprocess.run(["make", "-s", "-C", str(AVR_DIR), target], check=True)
    return str(AVR_DIR / target)


@pytest.fixture
def echo():
    c = Cluster()
    m = c.add_mcu(build("echo"), "echo")
    c.watch_uart(m, 0)
    c.watch_uart(m, 1)
    return c, m


def test_ursel_writes_reach_ucsrc_and_ubrrh(echo):
    c, m = echo
    c.run(5_000)
    cfg0 = c.uart_config(m, 0)
    assert (cfg0["data_bits"], cfg0["parity"], cfg0["stop_bits"]) == (8, "N", 1)
    assert cfg0["baud"] == pytest.approx(1e6 / (16 * 13))
    assert cfg0["rxen"] and cfg0["txen"]
    cfg1 = c.uart_config(m, 1)
    assert cfg1["baud"] == pytest.approx(1e6 / (16 * 208))
    assert not cfg1["rxen"]


def test_300_baud_8n1_byte_takes_33_3_ms(echo):
    c, m = echo
    reached = c.run(100_000)
    # run() stops at the first quantum boundary after the watched byte ends
    assert reached == 34_000
    [(start, end, byte)] = c.uart_take(m, 1)
    assert byte == ord("H")
    # 10 bit times; 33 333 cycles at exactly 300 baud, UBRR=207 gives 300.48 baud:
    # allow one UBRR step (16 cycles per bit) of rounding
    assert abs((end - start) - 33_333) <= 10 * 16
    assert end - start == 10 * 16 * 208
    assert c.uart_config(m, 1)["frame_cycles"] == end - start


def test_echo_replies_after_one_frame_and_shows_byte_on_portb(echo):
    c, m = echo
    c.run(40_000)
    c.uart_take(m, 1)
    assert c.uart_put(m, 0, 0x41) is True
    put_at = c.cycle
    c.run(50_000)
    [(start, end, byte)] = c.uart_take(m, 0)
    assert byte == 0x42
    assert put_at <= start < put_at + 100  # the firmware polls RXC
    assert end - start == 10 * 16 * 13
    ddr, port, pin = c.port(m, "B")
    assert (ddr, port, pin) == (0xFF, 0x41, 0x41)
    [(when, name, value)] = c.pin_log(m)
    assert (name, value) == ("B", 0x41)
    assert put_at <= when <= start


def test_receiver_with_rxen_off_drops_the_byte(echo):
    c, m = echo
    c.run(1_000)
    assert c.uart_put(m, 1, 0x55) is False
    assert c.uart_config(m, 1)["rx_dropped"] == 1


def test_same_inputs_give_the_same_trace():
    def trace():
        c = Cluster()
        m = c.add_mcu(build("echo"), "echo")
        c.watch_uart(m, 0)
        out = []
        for i, b in enumerate(b"hello world"):
            c.run(10_000 * (i + 1))
            c.uart_put(m, 0, b)
        c.run(200_000)
        out += c.uart_take(m, 0)
        return out, c.pin_log(m)

    first = trace()
    assert len(first[0]) == 11
    assert first == trace()
