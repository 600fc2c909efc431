"""Links: any pyserial URL, reconnection when the port comes back."""

from __future__ import annotations

import errno
import socket
import threading
import time

import pytest
import serial

from hexbot.errors import LinkUnavailableError
from hexbot.host.events import PortChanged
from hexbot.host.host import IR, Host
from hexbot.host.link import Link, LinkState, PortSettings, open_failure
from hexbot.protocol import parser, wire


def _wait(pred, timeout=5.0):
    end = time.monotonic() + timeout
    while time.monotonic() < end:
        if pred():
            return True
        time.sleep(0.01)
    return False


def test_loop_url_round_trip():
    got = bytearray()
    with Link(PortSettings("loop://"), got.extend).start(wait_s=2) as link:
        link.write(b"*ANNNNNNNN#")
        assert _wait(lambda: bytes(got) == b"*ANNNNNNNN#")
        assert link.bytes_out == link.bytes_in == 11


def test_bad_settings_are_refused():
    with pytest.raises(LinkUnavailableError, match="parity"):
        PortSettings("loop://", parity="X")
    with pytest.raises(LinkUnavailableError, match="cannot open /nonexistent"):
        Link(PortSettings("/nonexistent/tty"), lambda d: None).start(wait_s=0.3)



def test_a_device_the_user_may_not_open_says_what_to_check():
    """The usual first failure on a fresh Linux machine: the serial device
    belongs to a group the user is not in. pyserial raises it as
    SerialException(errno, text); the reason names the cause and the fix."""
    denied = serial.SerialException(errno.EACCES, "could not open port /dev/ttyUSB0: "
                                    "[Errno 13] Permission denied: '/dev/ttyUSB0'")
    assert open_failure("/dev/ttyUSB0", denied) == (
        "Permission denied (is your user in the group that owns /dev/ttyUSB0, often "
        "'dialout'?)")
    # a socket URL: pyserial keeps the errno in the exception it raised from
    free = socket.socket()
    free.bind(("127.0.0.1", 0))
    url = f"socket://127.0.0.1:{free.getsockname()[1]}"
    free.close()
    with pytest.raises(LinkUnavailableError) as refused:
        PortSettings(url).open(0.1)
    assert str(refused.value) == f"cannot open {url}: Connection refused"
    # pyserial's own text when nothing holds an errno
    assert open_failure("spy://x", ValueError("invalid URL")) == "invalid URL"

def test_write_while_disconnected_is_a_clear_error():
    link = Link(PortSettings("/nonexistent/tty"), lambda d: None, retry_s=0.05)
    with pytest.raises(LinkUnavailableError, match="not connected"):
        link.write(b"x")
    link.close()


class _Server:
    """A TCP server that plays a module: sends one ACK per connection."""

    def __init__(self, port: int = 0) -> None:
        self.sock = socket.create_server(("127.0.0.1", port))
        self.port = self.sock.getsockname()[1]
        self.conns: list[socket.socket] = []
        threading.Thread(target=self._accept, daemon=True).start()

    def _accept(self) -> None:
        while True:
            try:
                conn, _ = self.sock.accept()
            except OSError:
                return
            self.conns.append(conn)
            # pyserial drops what arrived before open() returned (it resets
            # the input buffer), so a module's greeting comes a little later.
            time.sleep(0.2)
            conn.sendall(parser.reply_ack(65, "S", 1))

    def stop(self) -> None:
        try:
            self.sock.shutdown(socket.SHUT_RDWR)  # wakes the thread blocked in accept()
        except OSError:
            pass
        self.sock.close()
        for c in self.conns:
            c.close()


def acks(host: Host) -> int:
    return sum(isinstance(o.event, parser.Ack) for o in host.since(0))


def test_host_reconnects_and_keeps_state():
    server = _Server()
    states: list[LinkState] = []
    host = Host()
    host.add_listener(lambda e: states.append(e.state) if isinstance(e, PortChanged) else None)
    host.add_port(IR, PortSettings(f"socket://127.0.0.1:{server.port}"), retry_s=0.1)
    host.start(wait_s=3)
    try:
        assert _wait(lambda: acks(host) == 1), (states, host.since(0))
        server.stop()
        assert _wait(lambda: LinkState.LOST in states)
        with pytest.raises(LinkUnavailableError):
            host.send(b"*ANNNNNNNN#")
        assert host.model.module(1).last_ack == 65  # state kept while lost
        server = _Server(server.port)  # the port comes back
        assert _wait(lambda: host.channels[IR].link.connected)
        assert _wait(lambda: acks(host) == 2)
        host.send(b"*ANNNNNNNN#")
        assert _wait(lambda: len(server.conns[0].recv(64)) == wire.PC_FRAME_LEN)
    finally:
        host.close()
        server.stop()
    assert states.index(LinkState.LOST) < len(states) - states[::-1].index(LinkState.CONNECTED)


def test_pty_that_goes_away_is_reported_lost(responder):
    host = Host()
    lost = threading.Event()
    host.add_listener(lambda e: lost.set()
                      if isinstance(e, PortChanged) and e.state is LinkState.LOST else None)
    host.add_port(IR, PortSettings(responder.path), retry_s=0.1)
    host.start(wait_s=3)
    try:
        responder.close()
        assert lost.wait(5)
        # never opened again: its number is the next pty's (another program's)
        link = host.channels[IR].link
        assert not link.retries
        assert _wait(lambda: "a pseudo-terminal is not opened again" in link.detail)
        assert _wait(lambda: not link._thread.is_alive())
    finally:
        host.close()
