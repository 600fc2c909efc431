"""hexbot.hil_sim.mcu: the thin handle over the C Cluster."""

import subprocess
from pathlib import Path

import pytest

from hexbot.hil_sim.mcu import Cluster, Mcu, UartByte, cycles_to_seconds, seconds_to_cycles

AVR_DIR = Path(__file__).parent / "avr"


def build(name: str, mcu: str = "atmega162") -> str:
    target = f"build/{name}.{mcu}.elf"
    subprocess.run(["make", "-s", "-C", str(AVR_DIR), target], check=True)
    return str(AVR_DIR / target)


def test_time_conversions():
    assert seconds_to_cycles(0.0333) == 33_300
    assert cycles_to_seconds(33_280) == pytest.approx(0.03328)
    with pytest.raises(ValueError, match="negative"):
        seconds_to_cycles(-1)


def test_mcu_handle_round_trip():
    c = Cluster()
    m = Mcu.load(c, build("echo"), "echo")
    m.watch_uart(0)
    c.run(1_000)
    assert m.name == "echo" and m.state == "running"
    assert m.uart_put(0, 0x10)
    c.run(5_000)
    [byte] = m.uart_take(0)
    assert isinstance(byte, UartByte) and byte.value == 0x11
    assert byte.end - byte.start == m.uart_config(0)["frame_cycles"]
    assert m.output("B") == 0x10
    assert m.time == pytest.approx(c.cycle / 1e6, abs=1e-5)  # run() stopped after the byte
