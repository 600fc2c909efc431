"""``hexbot sweep report``: the tables of docs/locomotion.md from sweep results, a plot."""

from __future__ import annotations

import pytest

from hexbot.cli import main
from hexbot.sweep.engine import run_sweep
from hexbot.sweep.results import ResultStore
from hexbot.sweep.spec import load_spec


def test_report_prints_the_random_map_table_and_plots(write_spec, tmp_path, embedded_client,
                                                      capsys):
    spec = load_spec(write_spec('kind = "locomotion"\n[grid]\nruleset = ["salvador", "otero"]\n'
                                'n = [5, 6]\nseed = [0, 1]\nround_limit = 300\n'))
    out = tmp_path / "out"
    with ResultStore(out, spec.kind.name, spec.param_names) as store:
        run_sweep(spec, embedded_client, store)
    png = tmp_path / "outcomes.png"
    assert main(["sweep", "report", str(out), "--plot", str(png)]) == 0
    text = capsys.readouterr().out
    assert "8 tasks of kind locomotion: ok 8, failed 0, error 0" in text
    lines = text.splitlines()
    header = lines.index("| rule set | runs | reached | violation |")
    assert lines[header + 2:header + 4] == ["| otero | 4 | 4 | 0 |", "| salvador | 4 | 4 | 0 |"]
    assert "| salvador | 6 | 2 | 2 | 0 |" in lines  # per rule set and n
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_report_of_a_folder_without_results_is_exit_1(tmp_path, capsys):
    assert main(["sweep", "report", str(tmp_path)]) == 1
    assert "no results" in capsys.readouterr().err


def test_run_options_do_not_mix_with_report(tmp_path, capsys):
    assert main(["sweep", "report", str(tmp_path), "--resume"]) == 2
    assert "--resume is for running a sweep" in capsys.readouterr().err
    assert main(["sweep", "report"]) == 2
    assert "report needs the results folder" in capsys.readouterr().err


SPEC = 'kind = "hexbot.bench.sweep:noop"\n[grid]\nseed = [1, 2]\n'


@pytest.mark.parametrize(("extra", "words"), [
    (["RESULTS"], "RESULTS and --plot belong to 'hexbot sweep report RESULTS'"),
    (["--workers", "2", "--scheduler", "tcp://127.0.0.1:1"], "not with --scheduler"),
    (["--out", "{file}"], "is a file, not a results folder"),
    (["--out", "{file}/sub"], "is not a folder"),
    (["--out", "/proc/nope"], "--out /proc/nope: cannot"),
])
def test_usage_errors_of_a_run_are_exit_2_before_anything_runs(write_spec, tmp_path, capsys,
                                                               monkeypatch, extra, words):
    monkeypatch.chdir(tmp_path)  # where the default results folder would go
    spec = write_spec(SPEC)
    (tmp_path / "file").write_text("not a folder")
    extra = [e.format(file=tmp_path / "file") for e in extra]
    assert main(["sweep", str(spec), *extra]) == 2
    err = capsys.readouterr().err
    assert words in err and "Traceback" not in err
    assert not (tmp_path / "sweep.results").exists()


def test_a_usage_error_is_exit_2_also_when_the_file_is_wrong_too(write_spec, capsys):
    spec = write_spec('kind = "no-such-kind"\n')
    assert main(["sweep", str(spec), "--workers", "2", "--scheduler", "tcp://127.0.0.1:1"]) == 2
    assert "not with --scheduler" in capsys.readouterr().err


def test_workers_0_is_an_argparse_usage_error(write_spec, capsys):
    with pytest.raises(SystemExit) as exit_:
        main(["sweep", str(write_spec(SPEC)), "--workers", "0"])
    assert exit_.value.code == 2
    assert "--workers: must be at least 1, got 0" in capsys.readouterr().err
