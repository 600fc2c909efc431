"""Session 36's mutation audit of host/link.py, each test failing on its
mutant: what a user sees when a port cannot be opened, fails, is closed,
comes later or goes for good (an in-process simulator is never opened
again; a stepped one that stops ends the exchange as "port lost")."""

from __future__ import annotations

import pytest

from hexbot.errors import LinkUnavailableError
from hexbot.host.link import PortSettings


def test_a_baud_rate_of_zero_is_refused_with_the_reason():
    with pytest.raises(LinkUnavailableError, match="baud must be positive, got 0"):
        PortSettings("loop://", baud=0)


def test_a_url_of_an_unknown_kind_cannot_be_opened_and_says_so():
    # pyserial raises ValueError for it: the user gets the one error kind
    # every port failure has, naming the port
    with pytest.raises(LinkUnavailableError, match="cannot open nosuch://x: .*nosuch"):
        PortSettings("nosuch://x").open(0.1)


def test_a_lost_simulator_port_is_not_opened_again(built_images):
    # opening its URL again would silently start a fresh cluster: the link
    # stays lost, with the reason, and its reader ends
    from hexbot.host.endpoints import sim_url
    from hexbot.host.link import Link, LinkState

    link = Link(PortSettings(sim_url("pair", 1, 5.0)), lambda data: None, retry_s=0.01)
    link.start(wait_s=5.0)
    reader = link._thread
    link.simulator.close()  # the cluster is gone, as a pulled cable
    reader.join(timeout=10.0)
    try:
        assert not reader.is_alive()
        assert link.state is LinkState.LOST and "closed" in link.detail
        assert link.simulator is None
    finally:
        link.close()


def test_a_regular_file_is_not_a_serial_port(tmp_path):
    plain = tmp_path / "notes.txt"
    plain.write_text("")
    with pytest.raises(LinkUnavailableError,
                       match=f"cannot open {plain}: not a serial port"):
        PortSettings(str(plain)).open(0.1)


def test_a_failed_write_reports_the_port_lost():
    # the reader then opens it again; the user sees why it was lost
    import serial

    from hexbot.host.link import Link, LinkState

    link = Link(PortSettings("loop://"), lambda data: None, retry_s=60.0).start(wait_s=2.0)
    try:
        def unplugged(data):
            raise serial.SerialException("device disconnected")

        link._port.write = unplugged
        with pytest.raises(LinkUnavailableError, match="write failed: device disconnected"):
            link.write(b"*ANNNNNNNN#")
        assert link.state is LinkState.LOST
        assert link.detail == "write failed: device disconnected"
    finally:
        link.close()


def test_a_closed_link_says_closed_not_connected():
    from hexbot.host.link import Link, LinkState

    states = []
    link = Link(PortSettings("loop://"), lambda data: None,
                lambda state, detail: states.append(state)).start(wait_s=2.0)
    link.close()
    assert link.state is LinkState.CLOSED and not link.connected
    assert states[-1] is LinkState.CLOSED  # listeners (the console's port line) hear it


def _eventually(pred, limit_s=10.0):
    """Whether ``pred()`` holds within ``limit_s`` (a bound against a hang)."""
    import time

    end = time.monotonic() + limit_s
    while not pred() and time.monotonic() < end:
        time.sleep(0.02)
    return pred()


def test_a_port_that_is_gone_tells_the_latest_reason():
    # unplugged: first the read fails, then the port cannot be opened again;
    # the user must see the second reason, not the first for ever (a socket
    # port: a lost pty is not opened again at all)
    import socket

    from hexbot.host.link import Link, LinkState

    server = socket.socket()
    server.bind(("127.0.0.1", 0))
    server.listen()
    url = f"socket://127.0.0.1:{server.getsockname()[1]}"
    link = Link(PortSettings(url), lambda data: None, retry_s=0.05).start(wait_s=3.0)
    try:
        conn, _ = server.accept()
        server.close()  # nobody listens any more: the reconnections are refused
        conn.close()  # and the read fails
        assert _eventually(lambda: link.detail.startswith(f"cannot open {url}")), \
            link.detail
        assert link.state is LinkState.LOST
        with pytest.raises(LinkUnavailableError, match=r"is not connected \(cannot open"):
            link.write(b"*ANNNNNNNN#")  # the write's error says why too
    finally:
        link.close()


def test_a_stepped_simulator_that_stops_ends_the_exchange_as_port_lost(open_session,
                                                                        monkeypatch):
    from hexbot.host.session import OutcomeKind
    from hexbot.protocol import frames

    session = open_session("pair")

    def fault(*args, **kwargs):
        raise RuntimeError("injected fault")

    monkeypatch.setattr(session.host.simulator.simulator, "run", fault)
    out = session.exchange(frames.make("Status"), modules=[1])
    assert out.kind is OutcomeKind.PORT_LOST, out.reason
    assert "the simulator stopped: RuntimeError: injected fault" in out.detail
    assert "the simulator stopped" in session.port_lost()


def test_a_port_that_is_not_there_yet_is_connected_when_it_comes():
    # the console started before the adapter was plugged in
    import socket

    from hexbot.host.link import Link, LinkState

    free = socket.socket()
    free.bind(("127.0.0.1", 0))
    port = free.getsockname()[1]
    free.close()
    link = Link(PortSettings(f"socket://127.0.0.1:{port}"), lambda data: None, retry_s=0.05)
    link.start()
    server = None
    try:
        assert _eventually(lambda: link.state is LinkState.LOST)
        server = socket.create_server(("127.0.0.1", port))
        assert _eventually(lambda: link.connected), link.detail
    finally:
        link.close()
        if server is not None:
            server.close()
