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
type and text), ``SystemExit`` and ``KeyboardInterrupt`` included; only what
kept a task from finishing anywhere (a lost worker, a cancelled run) leaves
no row, so ``--resume`` runs exactly those. A task whose worker died under
it (its own doing or a neighbour's: Dask cannot tell) runs once more,
alone, after the others, before it counts as lost: a task that kills its
worker (``os._exit``, a crash in C code) then costs the tasks that shared
the worker nothing.
Ctrl-C keeps every row of a task that had finished, also those not yet
taken back, and waits while a row is being stored and counted (a second
Ctrl-C does not wait).
"""

from __future__ import annotations

import asyncio
import logging
import multiprocessing
import os
import signal
import struct
import threading
import time
import uuid
from collections.abc import Callable, Coroutine, Iterator
from contextlib import contextmanager, suppress
from dataclasses import dataclass
from typing import Any

from hexbot.errors import HexBotError, LinkUnavailableError
from hexbot.sweep.kinds import resolve_target
from hexbot.sweep.results import ResultStore
from hexbot.sweep.spec import Spec, Task
from hexbot.sweep.summary import ENGINE_COLUMNS

FAILURE = "failure"  # the figure a kind sets to fail its task, with the reason
LOST = "lost"  # what the progress callback hears for a task that left no row
RETRIES = 1  # a task lost with its worker runs again, alone, this many times
CONNECT_SECONDS = 10.0  # to reach a --scheduler and hear its handshake
WORKER_WAIT_SECONDS = 60.0  # for a first worker to join a --scheduler that has none
CLOSE_SECONDS = 20.0  # for the embedded cluster to close; then its workers are killed
# how the embedded cluster makes its worker processes (see connect): spawn
# only where there is no fork server (Windows)
START_METHOD = ("forkserver" if "forkserver" in multiprocessing.get_all_start_methods()
                else "spawn")


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
    failed_before: int = 0  # rows already stored (--resume) whose outcome was not ok

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
    except BaseException as exc:  # noqa: BLE001 - the task's result, with its type and text
        # SystemExit and KeyboardInterrupt too: raised by a task, they would
        # take its worker down with the results it holds
        figures, outcome, error = {}, "error", f"{type(exc).__name__}: {exc}"
    return {"outcome": outcome, "error": error,
            "seconds": round(time.perf_counter() - start, 6), **figures}


def lost_reason(fut: Any, task: Task) -> str:
    """Why a task left no row, for the message that counts the lost ones."""
    params = ", ".join(f"{k}={v!r}" for k, v in task.params.items())
    exc = fut.exception() if fut.status == "error" else None
    if type(exc).__name__ == "KilledWorker":
        why = "its worker died every time it ran (a task that exits or crashes its process?)"
    elif exc is not None:
        why = f"{type(exc).__name__}: {exc}"
    else:
        why = f"its result was lost with its worker (Dask status {fut.status!r})"
    return f"e.g. task {task.id} ({params}): {why}"


@contextmanager
def connect(scheduler: str | None = None, workers: int | None = None,
            worker_wait: float | None = None,
            on_note: Callable[[str], None] | None = None) -> Iterator[Any]:
    """A Dask client: on ``scheduler`` (``tcp://HOST:8786``), or on an embedded
    LocalCluster of ``workers`` single-threaded processes (default: one per core).
    A scheduler with no worker gets ``worker_wait`` seconds for a first one to
    join (default :data:`WORKER_WAIT_SECONDS`), then the sweep gives up. An
    embedded cluster gets :data:`CLOSE_SECONDS` to close, then its worker
    processes are killed. ``on_note`` hears of either wait."""
    import dask
    from distributed import Client, LocalCluster

    if scheduler:
        _hear_handshake(scheduler)
        try:
            client = Client(scheduler, timeout=f"{CONNECT_SECONDS}s")
        except Exception as exc:  # noqa: BLE001 - a port that is not a scheduler fails oddly
            raise LinkUnavailableError(f"cannot reach the Dask scheduler {scheduler}: "
                                       f"{type(exc).__name__}: {exc}") from exc
        try:
            _wait_for_a_worker(client, scheduler, worker_wait or WORKER_WAIT_SECONDS, on_note)
            yield client
        finally:
            _close(client)
        return
    # A terminal's Ctrl-C reaches the whole process group, also worker processes
    # still importing Dask, which then die with a traceback each. A new process
    # keeps an ignored SIGINT (not a blocked one, nor a handler), so the cluster
    # starts while this process ignores it: a Ctrl-C in that second is not
    # seen, the next one stops the sweep as usual. A worker that its nanny
    # restarts later (its process died) would come from this process again,
    # with Ctrl-C live until the preload ignores it, and a Ctrl-C in that half
    # second printed its traceback. So workers are forked by multiprocessing's
    # fork server: it starts in that second too, and every worker it forks,
    # at any time, starts with SIGINT ignored. The start method is Dask's
    # setting, read at each (re)start: it holds for the cluster's whole life.
    with dask.config.set({"distributed.worker.multiprocessing-method": START_METHOD}):
        restore = _ignore_sigint()
        try:
            # loopback only; the scheduler's HTTP server (dashboard) on a free port, never 8787
            cluster = LocalCluster(n_workers=workers or os.cpu_count() or 1,
                                   threads_per_worker=1, processes=True, host="127.0.0.1",
                                   dashboard_address="127.0.0.1:0",
                                   preload=["hexbot.sweep.worker_setup"],
                                   silence_logs=logging.ERROR)
        except BaseException:
            restore()
            raise
        try:
            restore()  # from here a Ctrl-C closes the cluster on its way out
            client = Client(cluster)
            try:
                yield client
            finally:
                with suppress(TimeoutError):  # the cluster's close below is what counts
                    client.close(timeout=CLOSE_SECONDS)
        finally:
            restore()  # also when starting the client failed (a second restore is harmless)
            _close_cluster(cluster, on_note)


def _close_cluster(cluster: Any, on_note: Callable[[str], None] | None) -> None:
    """Close the embedded cluster within :data:`CLOSE_SECONDS`. Dask's own
    close has no deadline and waits on every nanny; a nanny caught in a
    restart once kept a Ctrl-C'd sweep from exiting. Past the deadline the
    worker processes are killed (their rows were stored or are not done,
    so nothing is lost) and the command goes on to exit."""
    nannies = list(cluster.workers.values())  # the close takes them off this list first
    before = _worker_processes(nannies)  # a cancelled close forgets its nannies' processes
    try:
        cluster.close(timeout=CLOSE_SECONDS)
        return
    except TimeoutError:
        pass
    import psutil

    killed = 0
    # those seen before the close and any a nanny started since (a restart)
    for proc in {p.pid: p for p in before + _worker_processes(nannies)}.values():
        with suppress(psutil.Error):
            if proc.status() != psutil.STATUS_ZOMBIE:
                proc.kill()  # psutil checks that the pid is still this process
                killed += 1
    cluster.shutdown_on_close = False  # Dask's exit hook would wait for it once more
    if on_note:
        # the close may have retired the workers before a nanny got stuck
        what = (f"killed {killed} worker process{'es' if killed > 1 else ''} still running"
                if killed else "no worker process was still running")
        on_note(f"the embedded Dask cluster did not close in {CLOSE_SECONDS:g} s: {what}")


def _worker_processes(nannies: list[Any]) -> list[Any]:
    """The worker processes the nannies hold now (psutil, so that a pid taken
    over by another process later is not killed)."""
    import psutil

    procs = []
    for nanny in nannies:
        pid = getattr(nanny, "pid", None)
        if pid:
            with suppress(psutil.Error):
                procs.append(psutil.Process(pid))
    return procs


def _ignore_sigint() -> Callable[[], None]:
    """Ignore SIGINT (in the main thread, where handlers live); returns the undo."""
    if threading.current_thread() is not threading.main_thread():
        return lambda: None
    previous = signal.signal(signal.SIGINT, signal.SIG_IGN)
    return lambda: signal.signal(signal.SIGINT, previous)


def _hear_handshake(scheduler: str) -> None:
    """Open one comm to ``scheduler`` and read its handshake, under a deadline
    of :data:`CONNECT_SECONDS`. Dask's own connect waits for the handshake
    without one, so a port that accepts and stays silent (a dashboard's 8787,
    a stuck process) would hang the sweep for ever.

    Safe to call from a thread that runs an event loop (a notebook, an async
    caller): the probe then runs on a loop of its own in another thread, and
    this thread waits for it, as it waits for ``Client()``."""
    import msgpack
    from distributed.comm import connect as open_comm
    from distributed.security import Security

    # the client's own settings (TLS certificates from Dask's configuration)
    connection_args = Security().get_connection_args("client")
    # Dask retries a refused or unresolvable address until its timeout, then
    # says why; the last fifth of the deadline is for the handshake, so a
    # timeout of the whole means a connection that stayed silent
    trying = 0.8 * CONNECT_SECONDS

    async def handshake() -> None:
        comm = await open_comm(scheduler, timeout=trying, **connection_args)
        await comm.close()

    try:
        _run_apart(lambda: asyncio.wait_for(handshake(), CONNECT_SECONDS))
    except TimeoutError:  # before OSError, whose subclass it is
        raise LinkUnavailableError(
            f"cannot reach the Dask scheduler {scheduler}: it accepts connections but did "
            f"not answer as a scheduler in {CONNECT_SECONDS:g} s") from None
    except OSError as exc:  # refused, unresolvable, unreachable, closed on us
        raise LinkUnavailableError(f"cannot reach the Dask scheduler {scheduler}: "
                                   f"{_with_cause(exc)}") from exc
    except (MemoryError, struct.error, msgpack.UnpackException) as exc:
        # what reading another protocol's bytes as Dask's frames raises (an SSH
        # greeting's first 8 bytes as a frame count: "Unable to allocate 2.82 EiB")
        # a MemoryError's own text ("Unable to allocate 3.07 EiB") reads as if this
        # machine ran short of memory: say what it means instead
        why = ("its first bytes, read as the size of a Dask message, ask for more "
               "memory than exists" if isinstance(exc, MemoryError)
               else f"{type(exc).__name__}: {exc}")
        raise LinkUnavailableError(
            f"cannot reach the Dask scheduler {scheduler}: something answers there, but "
            f"not as a Dask scheduler ({why})") from exc
    except Exception as exc:  # noqa: BLE001 - e.g. TLS settings that do not fit the address
        raise LinkUnavailableError(f"cannot reach the Dask scheduler {scheduler}: "
                                   f"{type(exc).__name__}: {exc}") from exc


def _run_apart(main: Callable[[], Coroutine[Any, Any, Any]]) -> None:
    """``asyncio.run(main())`` in this thread, or in a thread of its own when
    this one already runs an event loop (``asyncio.run`` refuses to start a
    loop there); its exception, if any, is raised here."""
    try:
        asyncio.get_running_loop()
    except RuntimeError:
        asyncio.run(main())
        return
    failed: list[BaseException] = []

    def run() -> None:
        try:
            asyncio.run(main())
        except BaseException as exc:  # noqa: BLE001 - raised again in the caller's thread
            failed.append(exc)

    thread = threading.Thread(target=run, name="hexbot-sweep-handshake", daemon=True)
    thread.start()
    thread.join()
    if failed:
        raise failed[0]


def _with_cause(exc: BaseException) -> str:
    """``exc``'s text, and that of the deepest cause in its chain that says
    why (Dask's time-out says only that it timed out; its cause says refused,
    or no such host, unless the last attempt was itself cut by the clock)."""
    cause = None
    link = exc.__cause__
    while link is not None:
        if not isinstance(link, asyncio.CancelledError | TimeoutError):
            cause = link
        link = link.__cause__
    return str(exc) if cause is None else f"{exc} ({type(cause).__name__}: {cause})"


def _wait_for_a_worker(client: Any, scheduler: str, seconds: float,
                       on_note: Callable[[str], None] | None) -> None:
    if client.nthreads():
        return
    if on_note:
        on_note(f"the Dask scheduler {scheduler} has no worker yet: waiting up to "
                f"{seconds:g} s for one (dask worker {scheduler})")
    try:
        client.wait_for_workers(1, timeout=seconds)
    except Exception as exc:  # noqa: BLE001 - WorkerStartTimeoutError, or the scheduler went
        raise LinkUnavailableError(f"no worker joined the Dask scheduler {scheduler} in "
                                   f"{seconds:g} s: start some with "
                                   f"'dask worker {scheduler}'") from exc


def _close(client: Any) -> None:
    """Close the client; after a lost scheduler quietly (closing cancels its
    reconnect loop, which Dask logs as an error with a traceback)."""
    logs = [logging.getLogger(name) for name in ("distributed", "distributed.client",
                                                 "distributed.utils")]
    levels = [log.level for log in logs]
    if _scheduler_lost(client):
        for log in logs:
            log.setLevel(logging.CRITICAL + 1)
    try:
        client.close()
    finally:
        for log, level in zip(logs, levels, strict=True):
            log.setLevel(level)


def _scheduler_lost(client: Any) -> LinkUnavailableError | None:
    """The error to end the sweep with when the client lost its scheduler
    (Dask then cancels every future; the rows already taken back are kept)."""
    if client.status in ("running", "newly-created"):
        return None
    return _lost_error(client)


def _lost_error(client: Any) -> LinkUnavailableError:
    address = client.scheduler.address if client.scheduler else "?"
    return LinkUnavailableError(
        f"lost the Dask scheduler {address} mid-sweep (client {client.status}): the rows "
        "taken back are stored, --resume runs the rest")


@contextmanager
def interrupt_deferred() -> Iterator[None]:
    """Ctrl-C that comes inside the block takes effect at its end.

    A row is stored, flushed to a part file and counted in a few steps; an
    interrupt between two of them left a row on disk that the count missed
    (a fresh-clone run said 178 tasks were not run where 177 were). A second
    Ctrl-C in the block raises at once: a fetch that hangs stays breakable."""
    previous = signal.getsignal(signal.SIGINT)
    if (threading.current_thread() is not threading.main_thread()
            or not callable(previous)):
        yield  # handlers can only be set from the main thread, and from Python
        return
    pressed: list[int] = []

    def hold(signum: int, frame: Any) -> None:
        if pressed:
            raise KeyboardInterrupt
        pressed.append(signum)

    signal.signal(signal.SIGINT, hold)
    try:
        yield
    finally:
        signal.signal(signal.SIGINT, previous)
    if pressed:
        raise KeyboardInterrupt


def run_sweep(spec: Spec, client: Any, store: ResultStore, *, resume: bool = False,
              on_start: Callable[[int, int], None] | None = None,
              on_result: Callable[[str], None] | None = None,
              window: int | None = None) -> SweepOutcome:
    """Run every task of ``spec`` that ``store`` lacks; rows go to ``store`` as
    they finish. ``on_start(total, already_done)`` and ``on_result(outcome)``
    (ok, failed, error or lost) drive a progress display."""
    from distributed import as_completed

    start = time.perf_counter()
    tasks = list({t.id: t for t in spec.tasks()}.values())  # a task once, whatever the grid
    store.order = {t.id: i for i, t in enumerate(tasks)}
    existing = store.existing()
    done = set(existing.column("task").to_pylist()) if existing is not None else set()
    ids = {t.id for t in tasks}
    failed_before = 0 if existing is None else sum(
        task in ids and result != "ok" for task, result in
        zip(existing.column("task").to_pylist(), existing.column("outcome").to_pylist(),
            strict=True))
    if done and not resume:
        raise HexBotError(f"{store.folder} already holds {len(done)} rows: --resume runs "
                          "only what is missing (or choose another --out)")
    todo = iter([t for t in tasks if t.id not in done])
    skipped = sum(t.id in done for t in tasks)
    if on_start:
        on_start(len(tasks), skipped)
    if window is None:
        window = max(32, 8 * sum(client.nthreads().values()))
    outcome = SweepOutcome(len(tasks), skipped, 0, 0, 0, False, 0.0,
                           failed_before=failed_before)
    in_flight: dict[str, tuple[Task, Any]] = {}
    finished = as_completed()
    # Keys unique to this run: the scheduler forgets a cancelled key
    # asynchronously, so a --resume that reused the key of a task cancelled a
    # moment before could get that cancellation and lose the task.
    run_token = uuid.uuid4().hex[:8]
    tries: dict[str, int] = {}
    suspects: list[Task] = []  # lost with a worker: run again, one at a time

    def submit(task: Task) -> None:
        if lost := _scheduler_lost(client):
            raise lost  # a future of a client that is reconnecting would never finish
        again = tries.get(task.id, 0)
        fut = client.submit(execute, spec.kind.target, task.call, pure=False,
                            key=f"hexbot-sweep-{spec.kind.name}-{task.id}-{run_token}"
                                + (f"-retry{again}" if again else ""))
        in_flight[fut.key] = (task, fut)
        finished.add(fut)

    def submit_next() -> None:
        task = next(todo, None)
        if task is not None:
            submit(task)

    def take(fut: Any, retry: bool = True, report: bool = True) -> None:
        task, _ = in_flight.pop(fut.key)
        if fut.status == "cancelled" and (lost := _scheduler_lost(client)):
            raise lost  # not this task's doing: no retry, no row
        if fut.status != "finished" and retry and tries.get(task.id, 0) < RETRIES:
            tries[task.id] = tries.get(task.id, 0) + 1
            suspects.append(task)  # its worker died: maybe not its fault
            return
        if fut.status == "finished":
            try:
                figures = fut.result()  # fetched through the scheduler
            except OSError as exc:  # CommClosedError too; the client notices a moment later
                raise _lost_error(client) from exc
            row = {"task": task.id, "kind": spec.kind.name, **task.params, **figures}
            store.add(row)
            outcome.stored += 1
            outcome.failed += row["outcome"] != "ok"
            result = row["outcome"]
        else:
            outcome.lost += 1
            outcome.lost_reason = outcome.lost_reason or lost_reason(fut, task)
            result = LOST
        if on_result and report:
            on_result(result)

    for _ in range(window):
        submit_next()
    try:
        for fut in finished:
            with interrupt_deferred():
                take(fut)
            submit_next()
        for task in suspects:  # alone, so one that kills its worker takes no other with it
            submit(task)
            for fut in finished:
                with interrupt_deferred():
                    take(fut)
    except KeyboardInterrupt:
        outcome.interrupted = True
        # the rows already done are kept, without progress reports: the
        # report is what a Ctrl-C interrupts, and calling it again could
        # raise the interrupt a second time, out of the sweep
        for fut in [f for _, f in in_flight.values() if f.status == "finished"]:
            take(fut, retry=False, report=False)
        client.cancel([f for _, f in in_flight.values()])
    finally:
        store.flush()
    outcome.seconds = time.perf_counter() - start
    return outcome
