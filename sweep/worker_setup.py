"""Preload of the embedded cluster's workers: Ctrl-C is the client's business.

A terminal's Ctrl-C reaches every process of the foreground group, the
worker processes too. The client stops the sweep, keeps the finished rows
and closes the cluster; a worker that died of the same SIGINT would only
add tracebacks to the output. So workers ignore SIGINT.

The embedded cluster forks its workers from a fork server that ignores
SIGINT already (see :func:`hexbot.sweep.engine.connect`), so this is the
second line: it holds where there is no fork server, and for a worker whose
SIGINT was set otherwise before the preload ran.
"""

from __future__ import annotations

import signal
import threading


def dask_setup(worker: object) -> None:
    if threading.current_thread() is threading.main_thread():
        signal.signal(signal.SIGINT, signal.SIG_IGN)
