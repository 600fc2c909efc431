"""Pseudo-terminals in front of the simulator: the PC's IR port and the debug ports.

Each port is a pty pair. A serial client opens the slave (``/dev/pts/N``)
exactly as it would open the RS232 converter; the bridge reads and writes
the master side. The bridge keeps its own handle on every slave open, so a
client may come and go without the port hanging up, and bytes that arrived
while no client was attached wait in the pty (up to the kernel's buffer;
beyond that they are dropped and counted). Most clients (pyserial among them)
flush their input when they open a port, as on real hardware, so a client
that must see the boot texts asks for ``wait_for_client`` (``--wait-client``):
the simulation starts only once the IR port is open.
Bytes from the IR port enter the simulator through ``pc_write``, which paces
them at 300 baud of simulated time. A pty keeps the baud rate a client sets
(the bridge reads it from the master side): a client at another rate than
the modules' (300 on IR, 4800 on a debug port) reads and sends garbled
bytes, as on hardware (:mod:`hexbot.hil_sim.uart_line`). Linux forces a
pty to 8 data bits without parity whatever the client asks, so parity and
word size cannot be checked here (the ``hexbot-sim://`` URL checks them),
and a pty has no modem lines (setting DTR fails with "Inappropriate ioctl";
the URL accepts them, and ``hexbot sim --rfc2217`` serves the URL port to
other processes with modem lines and parity).
"""

from __future__ import annotations

import errno
import os
import sys
import termios
import time
import tty
from collections.abc import Callable
from dataclasses import dataclass, field

from hexbot.errors import LinkUnavailableError
from hexbot.protocol import wire
from hexbot.protocol.wire import BAUD_IR

from .simulator import Simulator
from .uart_line import LineSettings, resample

#: termios speed constants -> bits per second
_SPEEDS = {getattr(termios, f"B{n}"): n for n in (
    50, 75, 110, 134, 150, 200, 300, 600, 1200, 1800, 2400, 4800, 9600, 19200, 38400,
    57600, 115200, 230400) if hasattr(termios, f"B{n}")}


#: Drops are said on stderr at most this often (wall-clock seconds).
DROP_NOTE_S = 10.0


@dataclass
class _Port:
    master: int
    slave: int
    name: str
    wire: LineSettings = LineSettings(BAUD_IR)  # what the modules' UART speaks
    dropped: int = 0
    noted: float = float("-inf")  # time.monotonic() of the last note of drops
    early: bytes = b""  # read while waiting for a client, not yet passed on

    def client_line(self) -> LineSettings:
        """The baud rate the client set on its end (8N1: a pty has no other)."""
        try:
            speed = termios.tcgetattr(self.master)[5]  # ospeed of the slave side
        except termios.error:
            return self.wire
        return LineSettings(_SPEEDS.get(speed, self.wire.baud))

    def from_client(self, data: bytes) -> bytes:
        return resample(data, self.client_line(), self.wire)

    def to_client(self, data: bytes) -> bytes:
        return resample(data, self.wire, self.client_line())

    @classmethod
    def open(cls, baud: int = BAUD_IR) -> _Port:
        try:
            master, slave = os.openpty()
        except OSError as exc:
            raise LinkUnavailableError(f"cannot create a pseudo-terminal: {exc}") from exc
        tty.setraw(slave)  # no echo, no line editing, no CR/LF translation
        attrs = termios.tcgetattr(slave)  # the modules' rate until a client sets its own
        attrs[4] = attrs[5] = getattr(termios, f"B{baud}")
        termios.tcsetattr(slave, termios.TCSANOW, attrs)
        os.set_blocking(master, False)
        return cls(master, slave, os.ttyname(slave), LineSettings(baud))

    def read(self) -> bytes:
        chunks = [self.early]
        self.early = b""
        while True:
            try:
                chunk = os.read(self.master, 4096)
            except BlockingIOError:
                break
            except OSError as exc:
                if exc.errno == errno.EIO:  # no client right now
                    break
                raise
            if not chunk:
                break
            chunks.append(chunk)
        return b"".join(chunks)

    def write(self, data: bytes) -> None:
        while data:
            try:
                n = os.write(self.master, data)
            except BlockingIOError:
                self.dropped += len(data)
                return
            data = data[n:]

    def wait_for_client(
        self, keep_waiting: Callable[[], bool], poll_s: float = 0.02, grace_s: float = 0.3
    ) -> bool:
        """Block until a client has the slave open; False if ``keep_waiting`` says stop.

        With no slave open anywhere, reading the master fails with EIO; once a
        client opens the slave it would block instead. So the bridge lets go
        of its own slave handle, waits for that change, and takes it back.
        """
        os.close(self.slave)
        self.slave = -1
        try:
            while keep_waiting():
                try:
                    early = os.read(self.master, 4096)
                except BlockingIOError:
                    # Let the client finish opening (pyserial flushes its input
                    # after configuring the port) before the first byte comes.
                    time.sleep(grace_s)
                    return True
                except OSError as exc:
                    if exc.errno != errno.EIO:
                        raise
                    time.sleep(poll_s)
                    continue
                self.early += early  # the client already wrote: it is there
                return True
            return False
        finally:
            self.slave = os.open(self.name, os.O_RDWR | os.O_NOCTTY)

    def close(self) -> None:
        for fd in (self.master, self.slave):
            try:
                os.close(fd)
            except OSError:
                pass


@dataclass
class PtyBridge:
    sim: Simulator
    ir: _Port = field(init=False)
    debug: dict[int, _Port] = field(init=False)
    closed: bool = False

    def __post_init__(self) -> None:
        self.ir = _Port.open(wire.BAUD_IR)
        self.debug = {m: _Port.open(wire.BAUD_DEBUG) for m in sorted(self.sim.modules)}

    def names(self) -> dict:
        """The first line ``hexbot sim --pty`` prints (other tools may add keys)."""
        return {"ir": self.ir.name, "uart1": {str(m): p.name for m, p in self.debug.items()}}

    def fds(self) -> list[int]:
        return [self.ir.master, *(p.master for p in self.debug.values())]

    def pump_in(self) -> None:
        """Client -> simulator."""
        data = self.ir.read()
        if data:
            self.sim.pc_write(self.ir.from_client(data))
        for module_id, port in self.debug.items():
            data = port.read()
            if data:
                self.sim.debug_write(module_id, port.from_client(data))

    def pump_out(self) -> None:
        """Simulator -> client; bytes a full pty had no room for are said on
        stderr, at most every DROP_NOTE_S (a client that stopped reading)."""
        data = self.sim.pc_read()
        if data:
            self._write(self.ir, data)
        for module_id, port in self.debug.items():
            data = self.sim.debug_read(module_id)
            if data:
                self._write(port, data)

    def _write(self, port: _Port, data: bytes) -> None:
        before = port.dropped
        port.write(port.to_client(data))
        now = time.monotonic()
        # (the kernel frees pty room in its own time: a drop, a write that
        # fits, a drop again is one slow client, said once)
        if port.dropped > before and now - port.noted >= DROP_NOTE_S:
            port.noted = now
            print(f"hexbot sim: {port.name}: the client does not read fast enough: "
                  f"{port.dropped} bytes dropped so far", file=sys.stderr, flush=True)

    def wait_for_client(self, keep_waiting: Callable[[], bool]) -> bool:
        """Block until a client opened the IR port (see ``_Port.wait_for_client``)."""
        return self.ir.wait_for_client(keep_waiting)

    def close(self) -> None:
        if self.closed:
            return
        self.closed = True
        self.ir.close()
        for port in self.debug.values():
            port.close()

    def __enter__(self) -> PtyBridge:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()
