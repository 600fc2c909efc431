"""hil_sim/core/tools/m162run: the core without Python gives the same trace."""

import subprocess
from pathlib import Path

from hexbot.hil_sim._avr import Cluster

ROOT = Path(__file__).resolve().parents[2]
AVR_DIR = Path(__file__).parent / "avr"
TOOLS = ROOT / "hil_sim" / "core" / "tools"


def build(name: str, mcu: str = "atmega162") -> str:
    target = f"build/{name}.{mcu}.elf"
    subprocess.run(["make", "-s", "-C", str(AVR_DIR), target], check=True)
    return str(AVR_DIR / target)


def test_runner_matches_the_extension():
    subprocess.run(["make", "-s", "-C", str(TOOLS)], check=True)
    echo, pinger = build("echo"), build("pinger")
    out = subprocess.run([str(TOOLS / "m162run"), "-c", "60000", "-w", echo, pinger],
                         check=True, capture_output=True, text=True).stdout.splitlines()
    sent = [tuple(int(x, 0) for x in line.split()[2:5])
            for line in out if line.startswith("1 uart0 ")]

    c = Cluster()
    e = c.add_mcu(echo, "echo")
    p = c.add_mcu(pinger, "pinger")
    c.connect_uart(e, 0, p, 0)
    c.watch_uart(p, 0)
    expected = []
    while c.run(60_000) < 60_000:
        expected += c.uart_take(p, 0)
    expected += c.uart_take(p, 0)
    assert sent == expected and len(sent) == 10
    assert out[-2:] == ["0 state running ", "1 state running "]
