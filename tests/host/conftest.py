"""Fixtures for host tests: a pty test double, a log folder."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).parent))

from responder import PtyResponder  # noqa: E402


@pytest.fixture
def responder():
    r = PtyResponder()
    yield r
    r.close()


@pytest.fixture
def silent_responder():
    r = PtyResponder(silent=True)
    yield r
    r.close()


@pytest.fixture
def log_dir(tmp_path, monkeypatch):
    path = tmp_path / "sessions"
    monkeypatch.setenv("HEXBOT_LOG_DIR", str(path))
    return path



@pytest.fixture
def open_session():
    """``open_session(scenario, seed=1, speed=0, boot=True)``: a Session on the
    embedded simulator's pyserial URL (stepped: virtual time), closed after
    the test. ``scenario`` is a built-in name or a TOML path."""
    from hexbot.host.endpoints import sim_url
    from hexbot.host.host import IR, Host
    from hexbot.host.link import PortSettings
    from hexbot.host.session import Session

    hosts = []

    def factory(scenario, seed=1, speed=0.0, boot=True):
        host = Host()
        hosts.append(host)
        host.add_port(IR, PortSettings(sim_url(str(scenario), seed, speed)))
        host.start(5.0)
        session = Session(host)
        if boot:
            session.wait_booted(host.simulator.module_ids())
        return session

    yield factory
    for host in hosts:
        host.close()
