"""Ctrl-C and SIGTERM end a command with one line and its status (130, 143),
its cleanup done: no traceback, no temporary folder left behind."""

from __future__ import annotations

import contextlib
import importlib
import os
import signal
import sys
from pathlib import Path

import pytest

from hexbot import cli
from tests.process_signals import signal_when

HEXBOT = Path(sys.executable).with_name("hexbot")


def test_ctrl_c_while_a_command_is_imported_is_one_line(monkeypatch, capsys):
    # the import of a command takes up to a second; a Ctrl-C in it was a traceback
    def interrupted(_name):
        raise KeyboardInterrupt

    monkeypatch.setattr(importlib, "import_module", interrupted)
    assert cli.main(["plan", "a.txt", "b.txt"]) == 130
    assert capsys.readouterr().err == "hexbot plan: interrupted (Ctrl-C)\n"


@pytest.mark.parametrize(("sig", "status", "said"), [
    (signal.SIGINT, 130, "hexbot traverse: interrupted (Ctrl-C)"),
    (signal.SIGTERM, 143, "hexbot traverse: terminated (SIGTERM)"),
])
def test_a_signal_mid_execution_removes_the_temporary_scenario(tmp_path, sig, status, said):
    # traverse --execute writes its scenario into a temporary folder; SIGTERM
    # killed the process at once and left the folder behind
    env = {**os.environ, "TMPDIR": str(tmp_path)}
    made = lambda: any(tmp_path.glob("hexbot-traverse-*/*.toml"))  # noqa: E731
    code, err = signal_when([str(HEXBOT), "traverse", "hil-basic-2", "--execute"],
                            lambda proc: made(), env=env, sig=sig)
    assert code == status, err
    assert "Traceback" not in err
    assert list(tmp_path.iterdir()) == []
    if sig == signal.SIGTERM:  # traverse words a Ctrl-C itself
        assert err.rstrip().endswith(said), err


def test_ctrl_c_in_a_planning_benchmark_leaves_its_worker_quietly(tmp_path):
    # the pair is planned in a spawned worker, which got the Ctrl-C too and
    # printed its KeyboardInterrupt traceback (from a scipy import)
    import psutil

    argv = [str(HEXBOT), "bench", "planning", "--families", "blob", "--sizes", "1000",
            "--seeds", "1", "--fixed", "no"]
    def importing(proc) -> bool:
        # the worker past its start (about 0.05 s of CPU) and into the
        # imports of the pair's planner (numpy, scipy: about half a second):
        # counted in CPU time, which a loaded machine does not stretch
        for child in psutil.Process(proc.pid).children():  # and the resource tracker
            with contextlib.suppress(psutil.Error):
                times = child.cpu_times()
                if times.user + times.system >= 0.15:
                    return True
        return False

    code, err = signal_when(argv, importing)
    assert code == 130, err
    assert "Traceback" not in err and "KeyboardInterrupt" not in err, err
    assert err.endswith("hexbot bench: interrupted (Ctrl-C)\n"), err
