"""What a benchmark's worker process does first: leave quietly on Ctrl-C.

A terminal's Ctrl-C reaches the whole process group, the workers too. The
parent stops the benchmark and says so; a worker that died of the same
KeyboardInterrupt printed its traceback (one in a scipy import, session 37).
Kept apart from the benchmarks so that a worker imports nothing else first.
"""

from __future__ import annotations

import os
import signal


def quiet_on_ctrl_c() -> None:
    """A ProcessPoolExecutor initializer: SIGINT ends this process at once,
    without a traceback (the parent sees the worker gone and stops)."""
    signal.signal(signal.SIGINT, _leave)


def _leave(signum: int, _frame: object) -> None:
    os._exit(128 + signum)
