"""The progress bar of a running sweep: done/total, failures, ETA (rich)."""

from __future__ import annotations

from rich.console import Console
from rich.progress import (
    BarColumn,
    MofNCompleteColumn,
    Progress,
    TextColumn,
    TimeElapsedColumn,
    TimeRemainingColumn,
)


class SweepProgress:
    """``on_start``/``on_result`` for :func:`~hexbot.sweep.engine.run_sweep`; on stderr."""

    def __init__(self, title: str, enabled: bool = True) -> None:
        self.title = title
        self.failures = 0
        self._bar = Progress(
            TextColumn("{task.description}"), BarColumn(), MofNCompleteColumn(),
            TextColumn("failures {task.fields[failures]}"), TimeElapsedColumn(),
            TextColumn("ETA"), TimeRemainingColumn(),
            console=Console(stderr=True), disable=not enabled,
        )
        self._task = None

    def __enter__(self) -> SweepProgress:
        self._bar.start()
        return self

    def __exit__(self, *exc: object) -> None:
        self._bar.stop()

    def on_start(self, total: int, done: int) -> None:
        self._task = self._bar.add_task(self.title, total=total, completed=done, failures=0)

    def on_result(self, outcome: str) -> None:
        self.failures += outcome != "ok"
        self._bar.update(self._task, advance=1, failures=self.failures)
