"""Ctrl-C and SIGTERM end a command with one line and its status (130, 143),
its cleanup done: no traceback, no temporary folder left behind."""

from __future__ import annotations

import importlib
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from hexbot import cli

HEXBOT = Path(sys.executable).with_name("hexbot")


def test_ctrl_c_while_a_command_is_imported_is_one_line(monkeypatch, capsys):
    # the import of a command takes up to a second; a Ctrl-C in it was a traceback
    def interrupted(_name):
        raise KeyboardInterrupt

    monkeypatch.setattr(importlib, "import_module", interrupted)
    assert cli.main(["plan", "a.txt", "b.txt"]) == 130
    assert capsys.readouterr().err == "hexbot plan: interrupted (Ctrl-C)\n"


def _signal_when(argv: list[str], ready, sig: int, env=None) -> tuple[int, str]:
    """Run ``hexbot argv`` in its own process group; send ``sig`` to the group
    once ``ready()`` holds; (exit status, stderr)."""
    proc = subprocess.Popen([str(HEXBOT), *argv], stdout=subprocess.DEVNULL,
                            stderr=subprocess.PIPE, text=True, start_new_session=True,
                            env=env, preexec_fn=lambda: signal.signal(signal.SIGINT,
                                                                      signal.SIG_DFL))
    try:
        deadline = time.monotonic() + 120
        while not ready():
            assert proc.poll() is None, proc.stderr.read()
            assert time.monotonic() < deadline
            time.sleep(0.02)
        os.killpg(proc.pid, sig)
        err = proc.communicate(timeout=120)[1]
    finally:
        if proc.poll() is None:
            os.killpg(proc.pid, signal.SIGKILL)
            proc.wait()
    return proc.returncode, err


@pytest.mark.parametrize(("sig", "status", "said"), [
    (signal.SIGINT, 130, "hexbot traverse: interrupted (Ctrl-C)"),
    (signal.SIGTERM, 143, "hexbot traverse: terminated (SIGTERM)"),
])
def test_a_signal_mid_execution_removes_the_temporary_scenario(tmp_path, sig, status, said):
    # traverse --execute writes its scenario into a temporary folder; SIGTERM
    # killed the process at once and left the folder behind
    env = {**os.environ, "TMPDIR": str(tmp_path)}
    made = lambda: any(tmp_path.glob("hexbot-traverse-*/*.toml"))  # noqa: E731
    code, err = _signal_when(["traverse", "hil-basic-2", "--execute"], made, sig, env)
    assert code == status, err
    assert "Traceback" not in err
    assert list(tmp_path.iterdir()) == []
    if sig == signal.SIGTERM:  # traverse words a Ctrl-C itself
        assert err.rstrip().endswith(said), err
