"""The simulated IR port served over TCP with RFC 2217 (Telnet COM port control).

    hexbot sim flower7 --rfc2217 2217      # then: rfc2217://localhost:2217

A pty cannot carry modem lines or parity (Linux forces 8N1 and has no modem
ioctls on a pty), so a client that sets DTR or parity E on ``hexbot sim
--pty`` fails where a USB adapter would not. RFC 2217 carries those settings
in band: pyserial's ``rfc2217://`` client (miniterm, the host, any pyserial
tool) sets baud, parity, word size and modem lines, and pyserial's own
``PortManager`` applies them to the port behind it. Behind it is the
embedded simulator's URL port (:mod:`hexbot.hil_sim.sim_serial`), which
accepts every setting as an adapter does and garbles bytes when the line
settings differ from the modules' 300 8N1, as on hardware.

One client at a time, as one program holds a serial port; a second
connection waits until the first one closes.
"""

from __future__ import annotations

import socket
import threading
from collections.abc import Callable

import serial
import serial.rfc2217

MODEM_POLL_S = 0.1  # how often modem line changes are reported to the client


class Rfc2217Server:
    """Serve ``port`` (an open pyserial port) to RFC 2217 clients on ``host:tcp_port``."""

    def __init__(self, port: serial.SerialBase, tcp_port: int = 0,
                 host: str = "localhost") -> None:
        self.port = port
        self.listener = socket.create_server((host, tcp_port))
        self.url = f"rfc2217://{host}:{self.listener.getsockname()[1]}"

    def serve(self, running: Callable[[], bool]) -> None:
        """Accept clients one after another until ``running()`` is false."""
        self.listener.settimeout(0.2)
        while running():
            try:
                conn, _ = self.listener.accept()
            except TimeoutError:
                continue
            with conn:
                self._session(conn, running)

    def _session(self, conn: socket.socket, running: Callable[[], bool]) -> None:
        conn.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
        manager = serial.rfc2217.PortManager(self.port, _Connection(conn))
        alive = threading.Event()
        alive.set()

        def port_to_client() -> None:
            while alive.is_set():
                try:
                    data = self.port.read(self.port.in_waiting or 1)
                    if data:
                        conn.sendall(b"".join(manager.escape(data)))
                    manager.check_modem_lines()
                except (OSError, serial.SerialException):
                    break
            alive.clear()

        self.port.timeout = MODEM_POLL_S
        reader = threading.Thread(target=port_to_client, daemon=True, name="rfc2217 out")
        reader.start()
        conn.settimeout(0.2)
        try:
            while alive.is_set() and running():
                try:
                    data = conn.recv(1024)
                except TimeoutError:
                    continue
                if not data:
                    break  # the client closed
                self.port.write(b"".join(manager.filter(data)))
        except (OSError, serial.SerialException):
            pass
        finally:
            alive.clear()
            reader.join(timeout=5)

    def close(self) -> None:
        self.listener.close()


class _Connection:
    """What PortManager writes its Telnet replies to."""

    def __init__(self, conn: socket.socket) -> None:
        self.conn = conn

    def write(self, data: bytes) -> None:
        self.conn.sendall(data)
