"""Send a real signal to a command's process group at a chosen moment."""

from __future__ import annotations

import os
import signal
import subprocess
import time


def signal_when(argv: list[str], ready, pause: float = 0.0,
                env: dict[str, str] | None = None,
                sig: int = signal.SIGINT) -> tuple[int, str]:
    """Run ``argv`` in a group of its own, send the group ``sig`` (SIGINT: a
    terminal's Ctrl-C reaches every process of it) once ``ready(proc)``, plus
    ``pause`` seconds; (exit status, stderr)."""
    # preexec: a suite started in the background (`make test &`) passes Ctrl-C
    # on as ignored; the command gets the default, as from a terminal
    proc = subprocess.Popen(argv, stderr=subprocess.PIPE, text=True, start_new_session=True,
                            preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL),
                            env=env)
    try:
        deadline = time.monotonic() + 120
        while not ready(proc):
            assert proc.poll() is None, proc.stderr.read()
            assert time.monotonic() < deadline
            time.sleep(0.01)
        time.sleep(pause)
        os.killpg(proc.pid, sig)
        err = proc.communicate(timeout=120)[1]
    finally:
        if proc.poll() is None:
            os.killpg(proc.pid, signal.SIGKILL)
            proc.wait()
    return proc.returncode, err
