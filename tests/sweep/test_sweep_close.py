"""The embedded cluster closes within a deadline: past it, its worker
processes are killed and the sweep goes on to exit (a Ctrl-C'd sweep once
did not exit while a nanny restarted a worker)."""

from __future__ import annotations

import os

import dask
import distributed  # noqa: F401 - its defaults in dask.config before we set one of them
import psutil
import pytest

from hexbot.sweep import engine

HANGS = "tests.sweep.hang_on_close"  # a nanny preload whose teardown never ends


def test_a_cluster_that_does_not_close_has_its_workers_killed(monkeypatch):
    monkeypatch.setattr(engine, "CLOSE_SECONDS", 1.5)
    notes: list[str] = []
    with dask.config.set({"distributed.nanny.preload": [HANGS]}), \
            engine.connect(workers=2, on_note=notes.append) as client:
        assert client.submit(sum, [1, 2]).result() == 3
        workers = [psutil.Process(pid) for pid in client.run(os.getpid).values()]
    # the close retires workers first: killed are those still running then
    assert len(notes) == 1 and notes[0] in (
        "the embedded Dask cluster did not close in 1.5 s: killed 2 worker processes "
        "still running",
        "the embedded Dask cluster did not close in 1.5 s: killed 1 worker process "
        "still running",
        "the embedded Dask cluster did not close in 1.5 s: no worker process was still "
        "running"), notes
    _, alive = psutil.wait_procs(workers, timeout=30)  # a killed process is reaped
    assert [p for p in alive if p.status() != psutil.STATUS_ZOMBIE] == []


def test_a_cluster_that_closes_in_time_says_nothing(monkeypatch):
    notes: list[str] = []
    with engine.connect(workers=1, on_note=notes.append) as client:
        worker = psutil.Process(next(iter(client.run(os.getpid).values())))
    assert notes == []
    assert not worker.is_running() or worker.status() == psutil.STATUS_ZOMBIE


@pytest.mark.parametrize("hang", [False, True])
def test_the_sweep_command_exits_after_its_cluster_closed_or_timed_out(
        hang, monkeypatch, write_spec, tmp_path, capsys):
    from hexbot.cli import main

    monkeypatch.setattr(engine, "CLOSE_SECONDS", 1.5)
    spec = write_spec('kind = "tests.sweep.edge_tasks:fail_on"\n[grid]\n'
                      'seed = [1, 2, 3]\nbad = 0\n')
    preload = [HANGS] if hang else []
    with dask.config.set({"distributed.nanny.preload": preload}):
        code = main(["sweep", str(spec), "--out", str(tmp_path / "o"), "--workers", "1",
                     "--no-progress"])
    err = capsys.readouterr().err
    assert code == 0, err
    assert "3 of 3 tasks stored" in err
    assert ("the embedded Dask cluster did not close in 1.5 s: " in err) == hang
