"""Ctrl-C keeps every finished row; --resume runs only the missing tasks."""

from __future__ import annotations

import os
import re
import signal
import subprocess
import sys
import time
from pathlib import Path

from hexbot.sweep.engine import run_sweep
from hexbot.sweep.results import ResultStore, part_files, read_table
from hexbot.sweep.spec import load_spec

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


def test_ctrl_c_on_the_command_exits_130_and_resume_completes(write_spec, tmp_path):
    # Enough tasks that the first flush (every 5 s) comes well before the end:
    # with 40 tasks of ~0.1 s a quiet machine once finished them all first.
    tasks = 200
    spec = write_spec(sweep_text(tasks))
    out = tmp_path / "out"
    argv = [str(HEXBOT), "sweep", str(spec), "--out", str(out), "--workers", "1"]
    # preexec: a suite started in the background (`make test &`) passes Ctrl-C
    # on as ignored; the command gets the default, as from a terminal
    proc = subprocess.Popen(argv, stderr=subprocess.PIPE, text=True, start_new_session=True,
                            preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
    try:
        deadline = time.monotonic() + 120
        while not part_files(out):  # rows are on disk: the sweep is under way
            assert proc.poll() is None, proc.stderr.read()
            assert time.monotonic() < deadline
            time.sleep(0.05)
        os.killpg(proc.pid, signal.SIGINT)  # a terminal's Ctrl-C reaches the whole group
        err = proc.communicate(timeout=120)[1]
    finally:
        if proc.poll() is None:
            os.killpg(proc.pid, signal.SIGKILL)
            proc.wait()
    assert proc.returncode == 130, err
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
