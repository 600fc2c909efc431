"""``hexbot sweep report``: the tables of docs/locomotion.md from sweep results, a plot."""

from __future__ import annotations

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
    assert main(["sweep", "report", str(tmp_path), "--resume"]) == 1
    assert "--resume is for running a sweep" in capsys.readouterr().err
    assert main(["sweep", "report"]) == 1
    assert "report needs the results folder" in capsys.readouterr().err
