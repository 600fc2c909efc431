"""Ctrl-C keeps every finished row; --resume runs only the missing tasks."""

from __future__ import annotations

import os
import re
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from hexbot.errors import HexBotError
from hexbot.sweep.engine import run_sweep
from hexbot.sweep.results import ResultStore, part_files, read_table, table_meta
from hexbot.sweep.spec import load_spec
from tests.process_signals import signal_when

HEXBOT = Path(sys.executable).with_name("hexbot")


def sweep_text(seeds: int, n: int = 5) -> str:
    return (f"kind = \"locomotion\"\n[grid]\nruleset = \"salvador\"\nn = {n}\n"
            f"seed = {{ start = 0, stop = {seeds} }}\n")


def seconds_by_task(folder: Path) -> dict[str, float]:
    return {r["task"]: r["seconds"] for r in read_table(folder).to_pylist()}


def test_an_interrupt_keeps_the_finished_rows_and_resume_runs_only_the_rest(
        write_spec, tmp_path, embedded_client):
    spec = load_spec(write_spec(sweep_text(10)))
    out = tmp_path / "out"
    seen = []

    def interrupt_after_three(outcome: str) -> None:
        seen.append(outcome)
        if len(seen) == 3:
            raise KeyboardInterrupt  # what Ctrl-C raises in the client

    with ResultStore(out, spec.kind.name, spec.param_names) as store:
        first = run_sweep(spec, embedded_client, store, on_result=interrupt_after_three,
                          window=2)
    assert first.interrupted
    kept = seconds_by_task(out)
    # the three taken back, and whatever else had finished by then (at most two in flight)
    assert 3 <= len(kept) == first.stored <= 5
    assert first.missing == 10 - len(kept)

    with ResultStore(out, spec.kind.name, spec.param_names) as store:
        second = run_sweep(spec, embedded_client, store, resume=True)
    assert (second.skipped, second.stored, second.interrupted) == (len(kept), 10 - len(kept),
                                                                   False)
    after = seconds_by_task(out)
    assert set(after) == {t.id for t in spec.tasks()}
    assert {t: after[t] for t in kept} == kept  # not run again: the same rows
    assert len(part_files(out)) == 1  # closing merged the parts


ctrl_c_when = signal_when  # SIGINT, as from a terminal


def test_ctrl_c_on_the_command_exits_130_and_resume_completes(write_spec, tmp_path):
    # Enough tasks that the first flush (every 5 s) comes well before the end:
    # with 40 tasks of ~0.1 s a quiet machine once finished them all first.
    tasks = 200
    spec = write_spec(sweep_text(tasks))
    out = tmp_path / "out"
    argv = [str(HEXBOT), "sweep", str(spec), "--out", str(out), "--workers", "1"]
    returncode, err = ctrl_c_when(argv, lambda proc: part_files(out))  # rows on disk
    assert returncode == 130, err
    kept = seconds_by_task(out)
    assert 0 < len(kept) < tasks
    assert f"interrupted: {tasks - len(kept)} tasks not run; add --resume" in err
    assert "Traceback" not in err

    done = subprocess.run([*argv, "--resume", "--no-progress"], capture_output=True, text=True,
                          timeout=300)
    assert done.returncode == 0, done.stderr
    assert re.search(rf"{tasks} of {tasks} tasks stored \({tasks - len(kept)} by this run",
                     done.stderr)
    after = seconds_by_task(out)
    assert len(after) == tasks and {t: after[t] for t in kept} == kept


def test_a_resume_right_after_an_interrupt_loses_no_task(write_spec, embedded_client, tmp_path):
    # The interrupted run cancels its in-flight tasks; the scheduler forgets
    # them asynchronously, so a resume that reused their keys got them back
    # cancelled and counted them lost (seen as 6 rows stored instead of 7).
    spec = load_spec(write_spec(sweep_text(12, n=40)))  # tasks still running when cancelled
    out = tmp_path / "out"

    def interrupt_at_once(outcome: str) -> None:
        raise KeyboardInterrupt

    with ResultStore(out, spec.kind.name, spec.param_names) as store:
        first = run_sweep(spec, embedded_client, store, on_result=interrupt_at_once, window=8)
        assert first.interrupted and first.missing > 0
        second = run_sweep(spec, embedded_client, store, resume=True)  # at once, same store
    assert (second.lost, second.stored) == (0, first.missing)
    assert len(read_table(out)) == 12


def _rows(seeds) -> list[dict]:
    return [{"task": f"t{s}", "kind": "k", "seed": s, "outcome": "ok"} for s in seeds]


def test_a_refused_run_leaves_another_sweeps_folder_untouched(tmp_path):
    out = tmp_path / "out"
    # what a hard-killed sweep leaves: several parts, never merged
    killed = ResultStore(out, "locomotion", ["seed"], flush_rows=2)
    killed.__enter__()
    for row in _rows(range(4)):
        killed.add(row)
    killed._lock.close()  # the process died: no close()
    before = {p.name: p.read_bytes() for p in part_files(out)}
    assert len(before) == 2

    with ResultStore(out, "plan", ["modules"]) as other:
        with pytest.raises(HexBotError, match="holds a 'locomotion' sweep, not 'plan'"):
            other.existing()
    assert {p.name: p.read_bytes() for p in part_files(out)} == before
    assert table_meta(read_table(out)) == ("locomotion", ["seed"])

    with ResultStore(out, "locomotion", ["seed"]) as nothing_new:
        nothing_new.existing()
    assert {p.name: p.read_bytes() for p in part_files(out)} == before  # no rows: untouched


def test_merging_keeps_the_folders_metadata_and_sorts_by_grid_order(tmp_path):
    out = tmp_path / "out"
    with ResultStore(out, "k", ["seed"], flush_rows=2) as store:
        store.order = {f"t{s}": s for s in range(6)}
        for row in _rows([5, 0, 3, 1, 4, 2]):  # as the workers finished them
            store.add(row)
    assert len(part_files(out)) == 1
    table = read_table(out)
    assert table.column("seed").to_pylist() == list(range(6))
    assert table_meta(table) == ("k", ["seed"])

    with ResultStore(out, "k", ["seed"]) as one_part:  # a single part, out of order
        one_part.order = {"t7": 0, "t6": 1}
        for row in _rows([6, 7]):
            one_part.add(row)
    # this grid's rows first, in its order; rows of no grid task after them, as they were
    assert read_table(out).column("seed").to_pylist() == [7, 6, 0, 1, 2, 3, 4, 5]


def test_a_column_of_mixed_types_is_stored_as_text_not_lost(tmp_path):
    out = tmp_path / "out"
    with ResultStore(out, "k", ["seed"], flush_rows=3) as store:
        for s in range(5):  # the first part all numbers, the second mixed
            store.add({**_rows([s])[0], "note": s if s < 3 or s == 4 else f"s{s}"})
    table = read_table(out)
    assert table.num_rows == 5
    assert table.column("note").to_pylist() == ["0", "1", "2", "s3", "4"]


def test_an_integer_beyond_64_bits_is_stored_as_text_not_lost(tmp_path):
    out = tmp_path / "out"
    with ResultStore(out, "k", ["seed"], flush_rows=10) as store:
        for s in range(4):
            store.add({**_rows([s])[0], "v": 2 ** 70 if s == 2 else s})
    assert read_table(out).column("v").to_pylist() == ["0", "1", str(2 ** 70), "3"]


def test_a_resume_counts_the_failures_stored_before_it(write_spec, tmp_path):
    """A CI job that always runs with --resume must not go green on a table of failures."""
    spec = write_spec('kind = "hexbot.bench.sweep:noop"\n[grid]\nseed = [1, 2]\n')
    out = tmp_path / "out"
    argv = [str(HEXBOT), "sweep", str(spec), "--out", str(out), "--workers", "1",
            "--no-progress"]
    first = subprocess.run(argv, capture_output=True, text=True, timeout=300)
    assert first.returncode == 0, first.stderr
    table = read_table(out)  # make one stored row a failure, as a failed task leaves it
    rows = table.to_pylist()
    rows[0]["outcome"], rows[0]["error"] = "error", "RuntimeError: boom"
    for part in part_files(out):
        part.unlink()
    with ResultStore(out, "hexbot.bench.sweep:noop", ["seed"], flush_rows=10) as store:
        for row in rows:
            store.add(row)
    again = subprocess.run([*argv, "--resume"], capture_output=True, text=True, timeout=300)
    assert again.returncode == 1, again.stderr
    assert "2 of 2 tasks stored (0 by this run" in again.stderr
    assert "1 failed (1 stored before this run)" in again.stderr


def test_a_repeated_task_runs_once(write_spec, tmp_path, embedded_client):
    spec = load_spec(write_spec('kind = "hexbot.bench.sweep:noop"\n[grid]\n'
                                'seed = [1, 2]\n'))
    spec.axes["seed"] = [1, 2, 1]  # what the file check refuses, should it get through
    with ResultStore(tmp_path / "out", spec.kind.name, spec.param_names) as store:
        outcome = run_sweep(spec, embedded_client, store)
    assert (outcome.total, outcome.stored) == (2, 2)
    assert read_table(tmp_path / "out").column("seed").to_pylist() == [1, 2]


def worker_started(parent: int) -> bool:
    """A process that ``parent`` started runs multiprocessing's spawn or its fork
    server, which imports Dask before it forks the workers (Linux /proc)."""
    for stat in Path("/proc").glob("[0-9]*/stat"):
        try:
            ppid = int(stat.read_text().rsplit(")", 1)[1].split()[1])
            cmdline = stat.with_name("cmdline").read_bytes()
            if ppid == parent and (b"spawn_main" in cmdline or b"forkserver" in cmdline):
                return True
        except (OSError, IndexError, ValueError):
            continue  # gone meanwhile
    return False


def process_group(pgid: int) -> set[int]:
    """The processes of a process group, but its leader (Linux /proc)."""
    found = set()
    for stat in Path("/proc").glob("[0-9]*/stat"):
        try:
            if int(stat.read_text().rsplit(")", 1)[1].split()[2]) == pgid:
                found.add(int(stat.parent.name))
        except (OSError, IndexError, ValueError):
            continue  # gone meanwhile
    return found - {pgid}


def sigint_disposition(pid: int) -> str:
    """``default``, ``ignored`` or ``caught`` (a handler: Python's raises
    KeyboardInterrupt), from /proc/PID/status; ``gone`` for no such process."""
    try:
        status = Path(f"/proc/{pid}/status").read_text()
    except OSError:
        return "gone"
    masks = dict(line.split(":\t") for line in status.splitlines()
                 if line.startswith(("SigIgn", "SigCgt")))
    bit = 1 << (signal.SIGINT - 1)
    if int(masks["SigIgn"], 16) & bit:
        return "ignored"
    return "caught" if int(masks["SigCgt"], 16) & bit else "default"


def test_ctrl_c_while_the_workers_start_prints_no_traceback(write_spec, tmp_path):
    """Workers still importing Dask used to die of the terminal's SIGINT, each
    with a traceback."""
    argv = [str(HEXBOT), "sweep", str(write_spec(sweep_text(20))), "--out", str(tmp_path / "o"),
            "--workers", "2", "--no-progress"]
    # Ctrl-C while the workers import Dask (0.2 s after the first is spawned)
    returncode, err = ctrl_c_when(argv, lambda proc: worker_started(proc.pid), pause=0.2)
    # ignored while the workers start (the sweep then runs to its end), or it stops
    assert returncode in (0, 130), err
    assert "Traceback" not in err and "KeyboardInterrupt" not in err


def test_ctrl_c_after_a_worker_was_restarted_prints_no_traceback(write_spec, tmp_path):
    """A worker process that dies mid-sweep is started again by its nanny. It
    came from the command with Ctrl-C live until the preload ignored it (half
    a second), so a Ctrl-C then printed its KeyboardInterrupt traceback. The
    Ctrl-C goes out as soon as the new process has its SIGINT set up."""
    pids = tmp_path / "pids"
    pids.mkdir()
    spec = write_spec('kind = "tests.sweep.sample_tasks:note_worker"\n[grid]\n'
                      f'seed = {{ start = 0, stop = 400 }}\nfolder = "{pids}"\n')
    argv = [str(HEXBOT), "sweep", str(spec), "--out", str(tmp_path / "o"), "--workers", "2",
            "--no-progress"]
    # the repository on the path, so the workers import the tests' task function
    env = {**os.environ, "PYTHONPATH": os.pathsep.join(
        filter(None, [os.environ.get("PYTHONPATH"), str(Path(__file__).parents[2])]))}
    before: set[int] = set()
    seen: list[str] = []

    def restarted(proc) -> bool:
        if not before:
            working = [int(p.name) for p in pids.iterdir()]
            if not working:
                return False  # no task has started yet
            before.update(process_group(proc.pid))
            os.kill(working[0], signal.SIGKILL)  # a worker dies mid-task
            return False
        new = process_group(proc.pid) - before  # the worker its nanny starts again
        seen[:] = [sigint_disposition(pid) for pid in new]
        return "ignored" in seen or "caught" in seen

    returncode, err = ctrl_c_when(argv, restarted, env=env)
    assert returncode == 130, err
    assert "interrupted: " in err and "add --resume" in err
    assert "Traceback" not in err and "KeyboardInterrupt" not in err, (seen, err)
    assert seen == ["ignored"]  # from its first moment


def test_a_progress_report_that_raises_the_interrupt_is_not_called_again(
        write_spec, embedded_client, tmp_path):
    # The rows finished when Ctrl-C came are stored without progress reports:
    # calling the report again raised the interrupt out of run_sweep (seen in
    # a fresh-clone run of test_a_resume_right_after_an_interrupt_loses_no_task
    # as a crashed xdist worker, when tasks had finished during the first report).
    spec = load_spec(write_spec(sweep_text(8)))
    calls = []

    def slow_then_interrupted(outcome: str) -> None:
        calls.append(outcome)
        time.sleep(1.0)  # the other tasks of the window finish meanwhile
        raise KeyboardInterrupt

    with ResultStore(tmp_path / "out", spec.kind.name, spec.param_names) as store:
        outcome = run_sweep(spec, embedded_client, store, on_result=slow_then_interrupted,
                            window=4)
    assert outcome.interrupted and len(calls) == 1
    assert outcome.stored >= 1  # the row reported, and those done meanwhile, are kept


class _CtrlCWhileStoring(ResultStore):
    """A real store that gets Ctrl-C (a real SIGINT) once, at a chosen point
    of storing its second row: after the row is buffered, or after the part
    file holding it is on disk and before the store has noted that."""

    def __init__(self, *args, at: str, **kwargs) -> None:
        super().__init__(*args, **kwargs)
        self.at, self.adds, self.sent = at, 0, False

    def _ctrl_c(self) -> None:
        if not self.sent:
            self.sent = True
            os.kill(os.getpid(), signal.SIGINT)

    def add(self, row) -> None:
        self.adds += 1
        if self.adds == 2 and self.at == "part":
            self.flush_rows = 1  # this row is flushed at once
        super().add(row)
        if self.adds == 2 and self.at == "buffered":
            self._ctrl_c()

    def _write(self, table, meta=None) -> None:
        super()._write(table, meta)
        if self.adds == 2 and self.at == "part":
            self._ctrl_c()


@pytest.mark.parametrize("at", ["buffered", "part"])
def test_ctrl_c_while_a_row_is_stored_keeps_the_counts_and_the_rows_in_step(
        write_spec, embedded_client, tmp_path, at):
    # A fresh-clone run printed "178 tasks not run" where 177 were: the
    # interrupt came between storing a row and counting it.
    previous = signal.signal(signal.SIGINT, signal.default_int_handler)
    spec = load_spec(write_spec(sweep_text(8)))
    out = tmp_path / "out"
    try:
        with _CtrlCWhileStoring(out, spec.kind.name, spec.param_names, at=at) as store:
            outcome = run_sweep(spec, embedded_client, store, window=2)
    finally:
        signal.signal(signal.SIGINT, previous)
    assert store.sent and outcome.interrupted
    tasks = read_table(out).column("task").to_pylist()
    assert outcome.stored == len(tasks) >= 2
    assert outcome.missing == 8 - len(tasks)
