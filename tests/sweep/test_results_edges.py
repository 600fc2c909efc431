"""The results table, the report and the JUnit XML at their edges, on tables
written by hand (no cluster): duplicate rows of a merge cut short, figures
absent from some rows, the failures listed, errors told from failures."""

from __future__ import annotations

from pathlib import Path

from hexbot.sweep.junit import junit_xml
from hexbot.sweep.report import FAILURES_LISTED, report
from hexbot.sweep.results import ResultStore, part_files, read_table
from hexbot.sweep.summary import generic

KIND = "tests.sweep.edge_tasks:fail_on"  # a dotted-path kind: the generic report


def row(task: str, outcome: str = "ok", seconds: float = 1.0, **more) -> dict:
    return {"task": task, "kind": KIND, "outcome": outcome,
            "error": "" if outcome == "ok" else f"{task} went wrong", "seconds": seconds, **more}


def store(folder: Path, rows: list[dict], params: list[str]) -> None:
    with ResultStore(folder, KIND, params, flush_rows=len(rows) or 1) as s:
        for r in rows:
            s.add(r)


def test_reading_keeps_the_last_row_of_a_task_stored_twice(tmp_path):
    """What a merge cut short by a crash leaves: parts that repeat a task."""
    out = tmp_path / "out"
    crashed = ResultStore(out, KIND, ["seed"], flush_rows=1)
    crashed.__enter__()
    for r in [row("a", seed=1, echo=10), row("b", seed=2, echo=20), row("a", seed=1, echo=11)]:
        crashed.add(r)
    crashed._lock.close()  # the process died: no close(), no merge
    assert len(part_files(out)) == 3
    table = read_table(out)
    assert table.num_rows == 2
    assert {r["task"]: r["echo"] for r in table.to_pylist()} == {"a": 11, "b": 20}


def test_the_generic_mean_of_a_figure_is_over_the_rows_that_have_it():
    rows = [row("a", seed=0, echo=2, seconds=1.0), row("b", seed=1, echo=4, seconds=3.0),
            row("c", "error", seed=2, seconds=2.0)]  # an error row has no figures
    text = generic(rows, ["seed"])
    assert text.splitlines() == [
        "| runs | ok | failed | error | mean echo | mean seconds |",
        "|---|---|---|---|---|---|",
        "| 3 | 2 | 0 | 1 | 3 | 2 |",
    ]


def test_the_generic_summary_groups_by_setting_not_by_seed():
    rows = [row(f"{n}-{s}", seed=s, n=n, echo=n * 10 + s) for n in (5, 6) for s in (0, 1, 2)]
    lines = generic(rows, ["n", "seed"]).splitlines()
    assert lines[0] == "| n | runs | ok | failed | error | mean echo | mean seconds |"
    assert lines[2:] == ["| 5 | 3 | 3 | 0 | 0 | 51 | 1 |", "| 6 | 3 | 3 | 0 | 0 | 61 | 1 |"]


def test_the_report_lists_failed_tasks_as_well_as_errors(tmp_path):
    out = tmp_path / "out"
    store(out, [row("a", seed=1), row("b", "failed", seed=2), row("c", "error", seed=3)],
          ["seed"])
    text = report(out)
    assert "3 tasks of kind " + KIND + ": ok 1, failed 1, error 1" in text
    assert "failed tasks (2):" in text
    assert "  seed=2: failed: b went wrong" in text
    assert "  seed=3: error: c went wrong" in text


def test_the_report_says_how_many_failures_it_left_out_and_only_then(tmp_path):
    for n, tail in ((FAILURES_LISTED, None), (FAILURES_LISTED + 1, "  ... and 1 more")):
        out = tmp_path / f"out{n}"
        store(out, [row(f"t{s}", "failed", seed=s) for s in range(n)], ["seed"])
        lines = report(out).splitlines()
        listed = [ln for ln in lines if ln.startswith("  seed=")]
        assert len(listed) == FAILURES_LISTED
        assert [ln for ln in lines if "more" in ln] == ([tail] if tail else [])


def test_junit_counts_failures_and_errors_apart():
    rows = [{**row("a", seed=1), "script": "s.hbs", "firmware": "fw", "scenario": "pair"},
            {**row("b", "failed", seed=2), "script": "s.hbs", "firmware": "fw",
             "scenario": "pair"},
            {**row("c", "error", seed=3), "script": "s.hbs", "firmware": "fw",
             "scenario": "pair"}]
    suite = junit_xml(rows).getroot().find("testsuite")
    assert (suite.get("tests"), suite.get("failures"), suite.get("errors")) == ("3", "1", "1")
    cases = {c.get("name"): c for c in suite.iter("testcase")}
    assert cases["seed 2"].find("failure") is not None and cases["seed 2"].find("error") is None
    assert cases["seed 3"].find("error") is not None and cases["seed 3"].find("failure") is None


def test_closing_sorts_a_single_part_into_grid_order(tmp_path):
    """A small sweep writes all its rows in one part, in the order the workers
    finished them: closing still puts them in grid order."""
    out = tmp_path / "out"
    with ResultStore(out, KIND, ["seed"]) as s:  # flushes only when closed: one part
        s.order = {f"t{i}": i for i in range(4)}
        for i in (2, 0, 3, 1):
            s.add(row(f"t{i}", seed=i))
    assert len(part_files(out)) == 1
    assert [r["seed"] for r in read_table(out).to_pylist()] == [0, 1, 2, 3]
