"""The sweep engine at its edges: what a task's figures may say, a --resume of
a grid that changed, and a Ctrl-C that comes when more tasks have finished
than were taken back."""

from __future__ import annotations

import time

import pytest

from hexbot.cli import main
from hexbot.sweep.engine import execute, run_sweep
from hexbot.sweep.results import ResultStore, read_table
from hexbot.sweep.spec import load_spec

FAIL_ON = "tests.sweep.edge_tasks:fail_on"


def spec_text(seeds: str, bad: int, tag: str) -> str:
    return f'kind = "{FAIL_ON}"\n[grid]\nseed = {seeds}\nbad = {bad}\ntag = "{tag}"\n'


def test_an_empty_failure_entry_is_not_a_failure():
    assert execute(FAIL_ON, {"seed": 1, "bad": 2})["outcome"] == "ok"
    failed = execute(FAIL_ON, {"seed": 2, "bad": 2})
    assert (failed["outcome"], failed["error"]) == ("failed", "seed 2 is bad")


@pytest.mark.parametrize("name", ["outcome", "error", "seconds", "task", "kind", "seed"])
def test_a_figure_named_like_a_column_is_an_error_row_not_an_overwrite(name):
    got = execute("tests.sweep.edge_tasks:figure_named", {"seed": 7, "name": name})
    assert got["outcome"] == "error"
    assert f"returned figures named like columns: ['{name}']" in got["error"]
    assert isinstance(got["seconds"], float)


def test_a_resume_of_a_narrowed_grid_counts_only_its_own_tasks(write_spec, tmp_path,
                                                               embedded_client):
    out = tmp_path / "out"
    wide = load_spec(write_spec(spec_text("[1, 2, 3]", 3, tmp_path), "wide.toml"))
    with ResultStore(out, wide.kind.name, wide.param_names) as store:
        first = run_sweep(wide, embedded_client, store)
    assert (first.stored, first.failed) == (3, 1)  # seed 3 failed

    narrow = load_spec(write_spec(spec_text("[1, 2]", 3, tmp_path), "narrow.toml"))
    with ResultStore(out, narrow.kind.name, narrow.param_names) as store:
        again = run_sweep(narrow, embedded_client, store, resume=True)
    # seed 3's row stays in the table but is no task of this grid
    assert (again.total, again.skipped, again.stored, again.missing) == (2, 2, 0, 0)
    assert (again.failed, again.failed_before) == (0, 0)
    assert len(read_table(out)) == 3


def test_a_resume_of_a_narrowed_grid_exits_0_when_its_own_tasks_are_ok(write_spec, tmp_path,
                                                                       capsys):
    out = tmp_path / "out"
    wide = write_spec(spec_text("[1, 2, 3]", 3, tmp_path), "wide.toml")
    argv = ["--out", str(out), "--workers", "1", "--no-progress"]
    assert main(["sweep", str(wide), *argv]) == 1  # seed 3 failed
    narrow = write_spec(spec_text("[1, 2]", 3, tmp_path), "narrow.toml")
    capsys.readouterr()
    assert main(["sweep", str(narrow), *argv, "--resume"]) == 0
    assert "2 of 2 tasks stored (0 by this run" in capsys.readouterr().err


def _wait_until_finished(client, task_ids: set[str], count: int) -> None:
    """Until ``count`` futures of these tasks are finished as the client sees them."""
    deadline = time.monotonic() + 60
    while time.monotonic() < deadline:
        states = [state.status for key, state in list(client.futures.items())
                  if any(tid in str(key) for tid in task_ids)]
        if states.count("finished") >= count:
            return
        time.sleep(0.02)
    raise AssertionError(f"the tasks did not finish: {states}")


def test_ctrl_c_keeps_the_rows_finished_but_not_yet_taken_back(write_spec, tmp_path,
                                                               embedded_client):
    spec = load_spec(write_spec(spec_text("[1, 2, 3, 4]", -1, tmp_path)))
    ids = {t.id for t in spec.tasks()}
    calls = []

    def interrupted_once_all_are_done(outcome: str) -> None:
        calls.append(outcome)
        _wait_until_finished(embedded_client, ids, len(ids))  # the other three finish
        raise KeyboardInterrupt  # ...before they were taken back

    out = tmp_path / "out"
    with ResultStore(out, spec.kind.name, spec.param_names) as store:
        outcome = run_sweep(spec, embedded_client, store, on_result=interrupted_once_all_are_done,
                            window=4)
    assert outcome.interrupted and calls == ["ok"]
    assert (outcome.stored, outcome.missing) == (4, 0)
    assert sorted(r["seed"] for r in read_table(out).to_pylist()) == [1, 2, 3, 4]


def test_an_interrupted_resume_counts_missing_without_the_stored_rows(write_spec, tmp_path,
                                                                      embedded_client):
    out = tmp_path / "out"
    first = load_spec(write_spec(spec_text("[0, 1, 2]", -1, tmp_path), "first.toml"))
    with ResultStore(out, first.kind.name, first.param_names) as store:
        assert run_sweep(first, embedded_client, store).stored == 3

    def interrupt(outcome: str) -> None:
        raise KeyboardInterrupt

    grown = load_spec(write_spec(spec_text("{ start = 0, stop = 40 }", -1, tmp_path),
                                 "grown.toml"))
    with ResultStore(out, grown.kind.name, grown.param_names) as store:
        outcome = run_sweep(grown, embedded_client, store, resume=True, on_result=interrupt,
                            window=2)
    assert outcome.interrupted and outcome.skipped == 3
    stored = len(read_table(out))
    assert outcome.missing == 40 - stored  # what a --resume still has to run


def test_a_single_lost_task_fails_the_command(write_spec, tmp_path, capsys):
    """One task that kills its worker every time: no row, exit 1, --resume named."""
    spec = write_spec('kind = "tests.sweep.sample_tasks:misbehave"\n[grid]\n'
                      'seed = [1, 2, 3]\nhow = "die"\n')
    out = tmp_path / "out"
    assert main(["sweep", str(spec), "--out", str(out), "--workers", "2", "--no-progress"]) == 1
    err = capsys.readouterr().err
    assert "1 tasks lost (e.g. task " in err and "--resume runs them again" in err
    assert sorted(r["seed"] for r in read_table(out).to_pylist()) == [1, 3]
