"""Edges of the ptys of ``hexbot sim --pty``: the count of bytes a slow
client missed is a count of bytes, bytes a client wrote as it opened the
port are not lost, and a client at a wrong baud rate sends garbled bytes
on the IR port and on a debug port."""

from __future__ import annotations

import os
import time

import pytest
import serial

from hexbot.hil_sim.pty_bridge import PtyBridge, _Port
from hexbot.hil_sim.uart_line import LineSettings, resample
from hexbot.protocol import wire


class _Chatty:
    """Double of the simulator's output side: 100 bytes for the PC at every pump."""

    modules: dict = {}

    def pc_read(self) -> bytes:
        return b"A" * 100


def test_the_bytes_dropped_are_counted_in_bytes():
    # what the client can still read plus what was counted as dropped is
    # everything the simulator sent: the note's "N bytes dropped" is true
    bridge = PtyBridge(_Chatty())  # type: ignore[arg-type]
    try:
        for _ in range(3000):
            bridge.pump_out()
        os.set_blocking(bridge.ir.slave, False)
        waiting = 0
        while True:
            try:
                chunk = os.read(bridge.ir.slave, 65536)
            except BlockingIOError:
                break
            if not chunk:
                break
            waiting += len(chunk)
        assert bridge.ir.dropped > 0
        assert waiting + bridge.ir.dropped == 3000 * 100
    finally:
        bridge.close()


def test_bytes_a_client_writes_as_it_opens_the_port_are_kept():
    # --wait-client: the client opens the IR port and writes at once; the
    # bridge notices it by reading those bytes, and must pass them on
    port = _Port.open(wire.BAUD_IR)
    client: list[int] = []

    def keep_waiting() -> bool:
        if not client:
            fd = os.open(port.name, os.O_RDWR | os.O_NOCTTY)
            client.append(fd)
            os.write(fd, b"*FNNNNNNNN#")
            time.sleep(0.2)  # in the pty before the bridge looks
        return True

    try:
        assert port.wait_for_client(keep_waiting)
        assert port.read() == b"*FNNNNNNNN#"
    finally:
        for fd in client:
            os.close(fd)
        port.close()


class _Debug:
    """Double of the simulator's input side with one module."""

    def __init__(self) -> None:
        self.modules = {1: None}
        self.written: dict[int, bytes] = {}

    def pc_write(self, data: bytes) -> None:
        self.written["pc"] = self.written.get("pc", b"") + data

    def debug_write(self, module_id: int, data: bytes) -> None:
        self.written[module_id] = self.written.get(module_id, b"") + data


@pytest.mark.parametrize(("port", "baud"), [("ir", wire.BAUD_IR), (1, wire.BAUD_DEBUG)])
def test_a_client_at_the_wrong_baud_rate_sends_garbage(port, baud):
    # a client at 9600 on the IR port (300) or a debug port (4800): what it
    # writes reaches the simulator as the modules' UART samples it, not as
    # written (a reply that comes back garbled alone does not show this)
    sim = _Debug()
    bridge = PtyBridge(sim)  # type: ignore[arg-type]
    name = bridge.ir.name if port == "ir" else bridge.debug[port].name
    key = "pc" if port == "ir" else port
    try:
        with serial.Serial(name, 9600) as client:
            client.write(b"hello")
            client.flush()
            deadline = time.monotonic() + 5
            while key not in sim.written and time.monotonic() < deadline:
                bridge.pump_in()
                time.sleep(0.01)
    finally:
        bridge.close()
    expected = resample(b"hello", LineSettings(9600), LineSettings(baud))
    assert expected != b"hello"
    assert sim.written.get(key, b"") == expected
