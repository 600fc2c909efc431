"""A scripted stand-in for ``hexbot.hil_sim._avr.Cluster`` in unit tests.

It runs no firmware: tests script what the MCUs would do (pin changes,
transmitted bytes, USART settings) and read back what the simulator delivered.
The end-to-end tests use the real extension and the real firmware.
"""

from __future__ import annotations

from collections import defaultdict


def uart_settings(baud: float, rxen: bool = True) -> dict:
    return {"baud": baud, "data_bits": 8, "parity": "N", "stop_bits": 1,
            "rxen": rxen, "txen": True, "frame_cycles": round(10e6 / baud)}


class ClusterDouble:
    def __init__(self, quantum_cycles: int = 1000) -> None:
        self.cycle = 0
        self.names: list[str] = []
        self.wires: list[tuple[int, int, int, int]] = []
        self.watched: set[tuple[int, int]] = set()
        self.inputs: dict[tuple[int, str], int] = {}
        self.config: dict[tuple[int, int], dict] = {}
        self.pins: dict[int, list[tuple[int, str, int]]] = defaultdict(list)
        self.tx: dict[tuple[int, int], list[tuple[int, int, int]]] = defaultdict(list)
        self.received: dict[tuple[int, int], list[tuple[int, int, bool]]] = defaultdict(list)

    # --- scripting ---------------------------------------------------------
    def script_pin(self, mcu: int, cycle: int, port: str, value: int) -> None:
        self.pins[mcu].append((cycle, port, value))
        self.pins[mcu].sort()

    def script_tx(self, mcu: int, uart: int, start: int, value: int, baud: float = 300.0) -> None:
        end = start + round(10e6 / baud)
        self.tx[(mcu, uart)].append((start, end, value))
        self.tx[(mcu, uart)].sort()

    # --- the Cluster API -------------------------------------------------------
    def add_mcu(self, elf_path: str, name: str) -> int:
        self.names.append(name)
        index = len(self.names) - 1
        self.config[(index, 0)] = uart_settings(4807.7)
        self.config[(index, 1)] = uart_settings(300.5 if name.startswith("comm") else 4807.7)
        return index

    def connect_uart(self, a: int, uart_a: int, b: int, uart_b: int) -> None:
        self.wires.append((a, uart_a, b, uart_b))

    def watch_uart(self, mcu: int, uart: int) -> None:
        self.watched.add((mcu, uart))

    def set_input(self, mcu: int, name: str, mask: int, value: int) -> None:
        self.inputs[(mcu, name)] = value & mask

    def run(self, until_cycle: int) -> int:
        # Stop early after a watched byte ends, as the real core does (quantum 1).
        ends = [e for (key, items) in self.tx.items() if key in self.watched
                for _, e, _ in items if self.cycle < e <= until_cycle]
        self.cycle = min([until_cycle, *ends])
        return self.cycle

    def uart_take(self, mcu: int, uart: int) -> list[tuple[int, int, int]]:
        done = [t for t in self.tx[(mcu, uart)] if t[1] <= self.cycle]
        self.tx[(mcu, uart)] = [t for t in self.tx[(mcu, uart)] if t[1] > self.cycle]
        return done

    def uart_put(self, mcu: int, uart: int, byte: int, framing_error: bool = False) -> bool:
        if not self.config[(mcu, uart)]["rxen"]:
            return False
        self.received[(mcu, uart)].append((self.cycle, byte, framing_error))
        return True

    def changed(self) -> list[int]:
        # Every MCU may have news: a superset of what the core reports is correct.
        return list(range(len(self.names)))

    def set_clock(self, mcu: int, hz: float) -> None:
        for uart in (0, 1):
            self.config[(mcu, uart)]["baud"] *= hz / 1e6

    def uart_config(self, mcu: int, uart: int) -> dict:
        return dict(self.config[(mcu, uart)])

    def pin_log(self, mcu: int) -> list[tuple[int, str, int]]:
        done = [p for p in self.pins[mcu] if p[0] <= self.cycle]
        self.pins[mcu] = [p for p in self.pins[mcu] if p[0] > self.cycle]
        return done

    def port(self, mcu: int, name: str) -> tuple[int, int, int]:
        return (0, 0, self.inputs.get((mcu, name), 0))

    def state(self, mcu: int) -> str:
        return "running"


def pair_on_dummy_images(tmp_path):
    """The pair scenario with stand-in image files (the double loads no
    firmware): for Simulator(..., cluster=ClusterDouble())."""
    from hexbot.hil_sim import load_scenario
    from hexbot.hil_sim.scenario import Firmware

    for name in ("comm.elf", "control.elf"):
        (tmp_path / name).write_bytes(b"\x7fELF")
    scenario = load_scenario("pair")
    fw = Firmware(tmp_path / "comm.elf", tmp_path / "control.elf")
    scenario.modules = [type(m)(m.id, m.position, m.orientation, fw, m.line)
                        for m in scenario.modules]
    return scenario


class RadiosDouble:
    """What RadioMedium reads of the core's RF12 parts (radio_take,
    radio_carrier, radio_state, radio_deliver), for a few radios: ``cells``
    start receiving on ``channel``."""

    def __init__(self, cells=(), channel=None) -> None:
        self.logs: dict[int, list] = {i: [] for i in cells}
        self.carrier: dict[int, tuple | None] = {}
        self.state: dict[int, dict] = {i: {"receiving": True, "channel": channel} for i in cells}
        self.delivered: list[tuple[int, int, int]] = []

    def radio_take(self, index):
        taken, self.logs[index] = self.logs.get(index, []), []
        return taken

    def radio_carrier(self, index):
        return self.carrier.get(index)

    def radio_state(self, index):
        return self.state[index]

    def radio_deliver(self, index, due, value):
        self.delivered.append((index, due, value))
