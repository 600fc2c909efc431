"""A results folder with a part file that cannot be read (empty, cut short,
random bytes, a Parquet file of someone else's): ``report`` and ``--resume``
name that file in one line and exit 1, touch nothing, and once it is moved
aside the good rows are reported and ``--resume`` runs only the lost tasks."""

from __future__ import annotations

import os
from pathlib import Path

import pyarrow as pa
import pyarrow.parquet as pq
import pytest

from hexbot.cli import main
from hexbot.sweep.results import ResultStore, part_files
from hexbot.sweep.spec import load_spec

KIND = "tests.sweep.edge_tasks:fail_on"
SPEC = f'kind = "{KIND}"\n[grid]\nseed = [0, 1, 2, 3]\n'


def good_rows(spec_path: Path, out: Path, count: int) -> None:
    """The rows of the grid's first ``count`` tasks, as a sweep stores them."""
    spec = load_spec(spec_path)
    with ResultStore(out, spec.kind.name, spec.param_names) as store:
        for task in spec.tasks()[:count]:
            store.add({"task": task.id, "kind": KIND, **task.params, "outcome": "ok",
                       "error": "", "seconds": 0.5, "echo": task.params["seed"]})
    assert len(part_files(out)) == 1


def damage(path: Path, how: str) -> None:
    good = part_files(path.parent.parent)[0].read_bytes()
    if how == "empty":
        path.write_bytes(b"")  # `: > part`
    elif how == "half":
        path.write_bytes(good[:len(good) // 2])
    elif how == "random":
        path.write_bytes(os.urandom(len(good)))
    else:  # a whole Parquet file, but not one a sweep wrote
        pq.write_table(pa.table({"x": [1, 2]}), path)


def snapshot(folder: Path) -> dict[str, bytes]:
    return {str(p.relative_to(folder)): p.read_bytes()
            for p in sorted(folder.rglob("*")) if p.is_file()}


@pytest.fixture
def damaged(write_spec, tmp_path, request):
    """A folder with two good rows in part 1 and a damaged part 2; the spec."""
    spec = write_spec(SPEC)
    out = tmp_path / "out"
    good_rows(spec, out, 2)
    bad = out / "table" / "part-000002.parquet"
    damage(bad, request.param)
    return spec, out, bad


HOWS = ["empty", "half", "random", "foreign"]


@pytest.mark.parametrize("damaged", HOWS, indirect=True)
def test_report_names_the_damaged_part_in_one_line_and_touches_nothing(damaged, capsys):
    _, out, bad = damaged
    before = snapshot(out)
    assert main(["sweep", "report", str(out)]) == 1
    captured = capsys.readouterr()
    err = captured.err.strip()
    assert "Traceback" not in err and len(err.splitlines()) == 1, err
    assert err.startswith(f"hexbot sweep: error: {bad}: ")
    assert err.endswith("move it aside; --resume then runs its tasks again")
    assert snapshot(out) == before


def test_the_reason_is_pyarrows_without_the_path_twice(tmp_path, write_spec, capsys):
    spec, out = write_spec(SPEC), tmp_path / "out"
    good_rows(spec, out, 2)
    damage(out / "table" / "part-000002.parquet", "empty")
    main(["sweep", "report", str(out)])
    err = capsys.readouterr().err
    assert "(Parquet file size is 0 bytes)" in err and err.count(str(out)) == 1


@pytest.mark.parametrize("damaged", HOWS, indirect=True)
def test_resume_refuses_the_folder_and_leaves_it_as_it_was(damaged, capsys):
    spec, out, bad = damaged
    before = snapshot(out)
    code = main(["sweep", str(spec), "--resume", "--out", str(out), "--workers", "1",
                 "--no-progress"])
    err = capsys.readouterr().err.strip()
    assert code == 1 and "Traceback" not in err
    assert err.splitlines()[-1].startswith(f"hexbot sweep: error: {bad}: ")
    assert snapshot(out) == before  # the good part not merged over, the bad one kept


@pytest.mark.parametrize("damaged", ["empty"], indirect=True)
def test_the_advice_works_moved_aside_resume_runs_only_its_tasks(damaged, tmp_path, capsys):
    spec, out, bad = damaged
    argv = ["sweep", str(spec), "--resume", "--out", str(out), "--workers", "1", "--no-progress"]
    assert main(argv) == 1
    assert "move it aside; --resume then runs its tasks again" in capsys.readouterr().err
    aside = tmp_path / "aside.parquet"
    bad.rename(aside)
    assert main(["sweep", "report", str(out)]) == 0  # the good rows
    assert "| 2 | 2 | 0 | 0 |" in capsys.readouterr().out  # runs, ok, failed, error
    assert main(argv) == 0
    assert "4 of 4 tasks stored (2 by this run" in capsys.readouterr().err
    assert aside.read_bytes() == b""  # what was moved aside is the user's to keep
