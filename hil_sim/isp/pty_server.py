"""Pseudo-terminals that speak STK500v2, one per simulated board.

Each port is an ``os.openpty`` pair in raw mode; the path of the slave side
(``/dev/pts/N``) is what avrdude opens with ``-P``. The server keeps the
slave open itself so the port survives avrdude closing and reopening it.

Two ways to run it: call :meth:`IspPtyServer.poll` from a loop you already
have (the simulator's, so that all memory access stays on one thread), or
:meth:`IspPtyServer.start` a background thread for a standalone chip.
"""

from __future__ import annotations

import os
import select
import threading
import time
import tty
from dataclasses import dataclass, field

from hexbot.errors import LinkUnavailableError
from hexbot.hil_sim.isp.stk500v2 import Stk500v2Programmer

# A frame left half-sent this long is dropped, like the STK500's receive
# time-out; real hosts send a whole frame in one go.
RX_TIMEOUT_S = 0.5


@dataclass
class IspPort:
    name: str
    path: str
    programmer: Stk500v2Programmer
    master: int
    slave: int
    last_rx: float = field(default=0.0)


class IspPtyServer:
    def __init__(self) -> None:
        self.ports: dict[str, IspPort] = {}
        self._thread: threading.Thread | None = None
        self._stop = threading.Event()
        self._closed = False

    def add(self, name: str, programmer: Stk500v2Programmer) -> str:
        """Open a new pty served by ``programmer``; return its path."""
        if name in self.ports:
            raise ValueError(f"ISP port {name!r} already exists")
        try:
            master, slave = os.openpty()
        except OSError as exc:
            raise LinkUnavailableError(f"cannot open a pseudo-terminal: {exc}") from exc
        tty.setraw(slave)
        os.set_blocking(master, False)
        port = IspPort(name, os.ttyname(slave), programmer, master, slave)
        self.ports[name] = port
        return port.path

    def paths(self) -> dict[str, str]:
        return {name: port.path for name, port in self.ports.items()}

    def fds(self) -> list[int]:
        return [port.master for port in self.ports.values()]

    def poll(self, timeout: float = 0.0) -> int:
        """Answer whatever the hosts have sent; return the bytes handled."""
        by_fd = {port.master: port for port in self.ports.values()}
        if not by_fd:
            return 0
        ready, _, _ = select.select(list(by_fd), [], [], timeout)
        handled = 0
        now = time.monotonic()
        for fd in ready:
            port = by_fd[fd]
            try:
                data = os.read(fd, 4096)
            except (BlockingIOError, InterruptedError):
                continue
            except OSError:  # EIO: no slave open at this instant
                continue
            handled += len(data)
            port.last_rx = now
            answer = port.programmer.feed(data)
            if answer:
                self._write_all(port, answer)
        for port in self.ports.values():
            decoder = port.programmer.decoder
            if decoder.in_frame and now - port.last_rx > RX_TIMEOUT_S:
                port.programmer.receive_timeout()
        return handled

    @staticmethod
    def _write_all(port: IspPort, data: bytes) -> None:
        view = memoryview(data)
        while view:
            try:
                view = view[os.write(port.master, view):]
            except BlockingIOError:
                select.select([], [port.master], [], 1.0)

    # -- background thread ----------------------------------------------------
    def start(self) -> IspPtyServer:
        if self._thread is None:
            self._stop.clear()
            self._thread = threading.Thread(target=self._run, name="isp-pty", daemon=True)
            self._thread.start()
        return self

    def _run(self) -> None:
        while not self._stop.is_set():
            self.poll(0.05)

    def stop(self) -> None:
        if self._thread is not None:
            self._stop.set()
            self._thread.join()
            self._thread = None

    def close(self) -> None:
        """Stop serving and close every pty; safe to call twice."""
        self.stop()
        if self._closed:
            return
        self._closed = True
        for port in self.ports.values():
            for fd in (port.master, port.slave):
                try:
                    os.close(fd)
                except OSError:
                    pass

    def __enter__(self) -> IspPtyServer:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()
