"""Dotted-path task functions of the sweep tests (workers import them by name)."""

from __future__ import annotations

import os
import sys
import time
from pathlib import Path


def misbehave(seed: int, how: str = "ok") -> dict:
    """Seed 2 leaves the way ``how`` says; the others return their seed."""
    if seed == 2:
        if how == "exit":
            sys.exit(3)
        if how == "interrupt":
            raise KeyboardInterrupt
        if how == "die":
            os._exit(7)  # the worker process with it
    return {"echo": seed}


def mixed_figure(seed: int) -> dict:
    """A figure that is a number for some tasks and text for others."""
    return {"note": seed if seed % 2 else f"s{seed}"}


def slow_echo(seed: int) -> dict:
    """A task that takes a while, so a sweep is still running when a test breaks it."""
    time.sleep(0.5)
    return {"echo": seed}


def echo_params(**params) -> dict:
    """Any parameters; says how many it got."""
    return {"got": len(params)}


def note_worker(seed: int, folder: str) -> dict:
    """Leaves a file named by its worker's process id in ``folder``, then takes
    a while (a test kills that worker)."""
    Path(folder, str(os.getpid())).touch()
    time.sleep(0.2)
    return {"echo": seed}
