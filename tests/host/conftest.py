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




def _session_on(responder, ids=()):
    """A Session on the pty test double, told ``ids`` (none: an unknown cluster)."""
    from hexbot.host.host import IR, Host
    from hexbot.host.link import PortSettings
    from hexbot.host.session import Session

    host = Host()
    host.add_port(IR, PortSettings(responder.path))
    host.start(5.0)
    try:
        yield Session(host, ids)
    finally:
        host.close()


@pytest.fixture
def pty_session(responder):
    """A Session on the pty test double's seven modules."""
    yield from _session_on(responder, [m.ident for m in responder.modules])


@pytest.fixture
def unknown_cluster(responder):
    """A Session on the pty test double that was told no module ids."""
    yield from _session_on(responder)
