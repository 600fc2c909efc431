"""A console filled from a recorded session, for screenshots and snapshot
tests: deterministic (time stamps come from the capture, nothing depends on
the clock or on pty names)."""

from __future__ import annotations

from pathlib import Path

from hexbot.host.capture import read_capture
from hexbot.host.console.app import HexBotConsole
from hexbot.host.host import DEBUG, IR, Host
from hexbot.host.link import PortSettings
from hexbot.protocol import wire


def demo_app(capture: Path) -> HexBotConsole:
    """A console whose ports are configured (as the recorded session's) but
    not opened; call :func:`play` once it runs."""
    host = Host()
    host.add_port(IR, PortSettings("sim-ir", wire.BAUD_IR))
    host.add_port(DEBUG, PortSettings("sim-uart1-01", wire.BAUD_DEBUG))
    app = HexBotConsole(host, start_ports=False)
    app.demo_records = list(read_capture(capture))  # type: ignore[attr-defined]
    return app


async def play(app: HexBotConsole, pilot) -> None:
    """Replay the whole capture at once and let the UI catch up."""
    assert app.host is not None
    app.host.replay(app.demo_records)  # type: ignore[attr-defined]
    await pilot.pause()
    await pilot.pause(0.2)
