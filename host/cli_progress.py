"""Progress of long CLI waits on stderr (rich): "n of N", elapsed time, and
a bar when the total is known.

On a terminal the bar redraws in place; piped or redirected, nothing is
drawn and the caller prints its one-line summary instead, so logs stay
clean. Safe to advance from reader threads (rich locks its own state).
"""

from __future__ import annotations

import sys
import threading
from collections.abc import Iterator
from contextlib import contextmanager
from typing import TYPE_CHECKING

from rich.console import Console
from rich.progress import (
    BarColumn,
    MofNCompleteColumn,
    Progress,
    SpinnerColumn,
    TaskID,
    TextColumn,
    TimeElapsedColumn,
)

if TYPE_CHECKING:
    from hexbot.host.session import Session


class Meter:
    """One task's counter; ``done`` is what was counted so far."""

    def __init__(self, progress: Progress, task: TaskID) -> None:
        self._progress, self._task = progress, task
        self.done = 0

    def advance(self, n: int = 1) -> None:
        self.done += n
        self._progress.update(self._task, completed=self.done)

    def describe(self, text: str) -> None:
        self._progress.update(self._task, description=text)


@contextmanager
def meter(description: str, total: int | None, *, stream=None) -> Iterator[Meter]:
    """A progress bar for ``total`` things (None: count only) on ``stream``
    (stderr by default), drawn only when that is a terminal."""
    console = Console(file=stream or sys.stderr)
    progress = Progress(TextColumn("{task.description}"), BarColumn(), MofNCompleteColumn(),
                        TimeElapsedColumn(), console=console,
                        disable=not console.is_terminal, transient=False)
    with progress:
        yield Meter(progress, progress.add_task(description, total=total))


@contextmanager
def stages(description: str, *, stream=None) -> Iterator[Meter]:
    """A spinner, ``description``, the stage (``Meter.describe``) and the time
    elapsed, for work whose length is not known (a plan of 10,000 modules
    takes minutes); drawn only on a terminal, and gone when the work is done."""
    console = Console(file=stream or sys.stderr)
    progress = Progress(SpinnerColumn(), TextColumn("{task.description}"), TimeElapsedColumn(),
                        console=console, disable=not console.is_terminal, transient=True)
    with progress:
        yield Meter(progress, progress.add_task(description, total=None))


@contextmanager
def session_waits(session: Session, *, stream=None, tick_s: float = 0.25) -> Iterator[None]:
    """While the block runs, show each exchange the session waits for:
    "Localize(): n of N replied", elapsed and its time-out (on a terminal)."""
    console = Console(file=stream or sys.stderr)
    if not console.is_terminal:
        yield
        return
    stop = threading.Event()
    progress = Progress(TextColumn("{task.description}"), BarColumn(), MofNCompleteColumn(),
                        TextColumn("{task.fields[time]}"), console=console, transient=True)

    def watch() -> None:
        task: TaskID | None = None
        shown: object = None
        while not stop.wait(tick_s):
            w = session.waiting
            if w is None:
                continue
            if w is not shown:
                if task is not None:
                    progress.remove_task(task)
                task, shown = progress.add_task(f"{w.what}: replied", total=w.need, time=""), w
            elapsed = max(0.0, session.now() - w.started)
            progress.update(task, completed=w.replied,
                            time=f"{elapsed:.1f} s of {w.timeout:.0f} s")

    with progress:
        thread = threading.Thread(target=watch, name="wait progress", daemon=True)
        thread.start()
        try:
            yield
        finally:
            stop.set()
            thread.join()
