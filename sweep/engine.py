"""Runs a sweep's tasks on Dask distributed and streams the rows into the table.

The client keeps a window of tasks submitted (a few per worker thread, so a
sweep of 100,000 tasks does not sit in the scheduler at once) and takes
them back with ``as_completed`` as they finish, in whatever order; each
finished task becomes a row of the :class:`~hexbot.sweep.results.ResultStore`
at once. Dask does the rest: placing tasks, moving them off a worker that
died (a task that keeps killing workers ends as ``KilledWorker``, counted
as lost), and the same code runs on an embedded LocalCluster or on any
scheduler address.

A task's own exception is its result (an ``error`` row with the exception's
type and text); only what kept a task from finishing anywhere (a lost
worker, a cancelled run) leaves no row, so ``--resume`` runs exactly those.
Ctrl-C keeps every row of a task that had finished, also those not yet
taken back.
"""

from __future__ import annotations

import logging
import os
import time
import uuid
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from dataclasses import dataclass
from typing import Any

from hexbot.errors import HexBotError, LinkUnavailableError
from hexbot.sweep.kinds import resolve_target
from hexbot.sweep.results import ResultStore
from hexbot.sweep.spec import Spec, Task
from hexbot.sweep.summary import ENGINE_COLUMNS

FAILURE = "failure"  # the figure a kind sets to fail its task, with the reason
LOST = "lost"  # what the progress callback hears for a task that left no row


@dataclass
class SweepOutcome:
    total: int  # tasks in the grid
    skipped: int  # already stored (--resume)
    stored: int  # rows written by this run
    failed: int  # of those, outcome failed or error
    lost: int  # tasks no worker finished: no row, --resume runs them
    interrupted: bool
    seconds: float
    lost_reason: str = ""

    @property
    def missing(self) -> int:
        return self.total - self.skipped - self.stored


def execute(target: str, call: dict[str, Any]) -> dict[str, Any]:
    """One task, on a worker: the kind's figures, outcome and run time."""
    start = time.perf_counter()
    try:
        figures = dict(resolve_target(target)(**call))
        clash = sorted(set(figures) & (set(call) | set(ENGINE_COLUMNS)))
        if clash:
            raise HexBotError(f"{target} returned figures named like columns: {clash}")
        failure = figures.pop(FAILURE, None)
        outcome, error = ("failed", str(failure)) if failure else ("ok", "")
    except Exception as exc:  # the task's result, stored with its type and text
        figures, outcome, error = {}, "error", f"{type(exc).__name__}: {exc}"
    return {"outcome": outcome, "error": error,
            "seconds": round(time.perf_counter() - start, 6), **figures}


@contextmanager
def connect(scheduler: str | None = None, workers: int | None = None) -> Iterator[Any]:
    """A Dask client: on ``scheduler`` (``tcp://HOST:8786``), or on an embedded
    LocalCluster of ``workers`` single-threaded processes (default: one per core)."""
    from distributed import Client, LocalCluster

    if scheduler:
        try:
            client = Client(scheduler, timeout="10s")
        except (OSError, TimeoutError) as exc:
            raise LinkUnavailableError(f"cannot reach the Dask scheduler {scheduler}: {exc}") \
                from exc
        with client:
            yield client
        return
    # loopback only; the scheduler's HTTP server (dashboard) on a free port, never 8787
    with LocalCluster(n_workers=workers or os.cpu_count() or 1, threads_per_worker=1,
                      processes=True, host="127.0.0.1", dashboard_address="127.0.0.1:0",
                      preload=["hexbot.sweep.worker_setup"],
                      silence_logs=logging.ERROR) as cluster, Client(cluster) as client:
        yield client


def run_sweep(spec: Spec, client: Any, store: ResultStore, *, resume: bool = False,
              on_start: Callable[[int, int], None] | None = None,
              on_result: Callable[[str], None] | None = None,
              window: int | None = None) -> SweepOutcome:
    """Run every task of ``spec`` that ``store`` lacks; rows go to ``store`` as
    they finish. ``on_start(total, already_done)`` and ``on_result(outcome)``
    (ok, failed, error or lost) drive a progress display."""
    from distributed import as_completed

    start = time.perf_counter()
    tasks = spec.tasks()
    existing = store.existing()
    done = set(existing.column("task").to_pylist()) if existing is not None else set()
    if done and not resume:
        raise HexBotError(f"{store.folder} already holds {len(done)} rows: --resume runs "
                          "only what is missing (or choose another --out)")
    todo = iter([t for t in tasks if t.id not in done])
    skipped = sum(t.id in done for t in tasks)
    if on_start:
        on_start(len(tasks), skipped)
    if window is None:
        window = max(32, 8 * sum(client.nthreads().values()))
    outcome = SweepOutcome(len(tasks), skipped, 0, 0, 0, False, 0.0)
    in_flight: dict[str, tuple[Task, Any]] = {}
    finished = as_completed()
    # Keys unique to this run: the scheduler forgets a cancelled key
    # asynchronously, so a --resume that reused the key of a task cancelled a
    # moment before could get that cancellation and lose the task.
    run_token = uuid.uuid4().hex[:8]

    def submit_next() -> None:
        task = next(todo, None)
        if task is not None:
            fut = client.submit(execute, spec.kind.target, task.call,
                                key=f"hexbot-sweep-{spec.kind.name}-{task.id}-{run_token}")
            in_flight[fut.key] = (task, fut)
            finished.add(fut)

    def take(fut: Any) -> None:
        task, _ = in_flight.pop(fut.key)
        if fut.status == "finished":
            row = {"task": task.id, "kind": spec.kind.name, **task.params, **fut.result()}
            store.add(row)
            outcome.stored += 1
            outcome.failed += row["outcome"] != "ok"
            result = row["outcome"]
        else:
            outcome.lost += 1
            outcome.lost_reason = outcome.lost_reason or repr(fut.exception())
            result = LOST
        if on_result:
            on_result(result)

    for _ in range(window):
        submit_next()
    try:
        for fut in finished:
            take(fut)
            submit_next()
    except KeyboardInterrupt:
        outcome.interrupted = True
        for fut in [f for _, f in in_flight.values() if f.status == "finished"]:
            take(fut)
        client.cancel([f for _, f in in_flight.values()])
    finally:
        store.flush()
    outcome.seconds = time.perf_counter() - start
    return outcome
