"""Preload of the embedded cluster's workers: Ctrl-C is the client's business.

A terminal's Ctrl-C reaches every process of the foreground group, the
worker processes too. The client stops the sweep, keeps the finished rows
and closes the cluster; a worker that died of the same SIGINT would only
add tracebacks to the output. So workers ignore SIGINT.
"""

from __future__ import annotations

import signal
import threading


def dask_setup(worker: object) -> None:
    if threading.current_thread() is threading.main_thread():
        signal.signal(signal.SIGINT, signal.SIG_IGN)
