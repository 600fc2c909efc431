"""Sweep files: the grid, the task ids, and every error with file:line before anything runs."""

from __future__ import annotations

import pytest

from hexbot.cli import main
from hexbot.errors import ScenarioError
from hexbot.sweep.spec import load_spec

LOCOMOTION = """\
kind = "locomotion"
[grid]
ruleset = ["salvador", "otero"]
n = [5, 12]
seed = { start = 3, stop = 9, step = 2 }
round_limit = 100
"""


def test_the_grid_is_every_combination_with_the_kinds_defaults(write_spec):
    spec = load_spec(write_spec(LOCOMOTION))
    tasks = spec.tasks()
    assert len(tasks) == 2 * 2 * 3
    assert [t.params["seed"] for t in tasks[:3]] == [3, 5, 7]  # the last axis varies fastest
    first = tasks[0].params
    assert first == {"ruleset": "salvador", "n": 5, "seed": 3, "round_limit": 100,
                     "scenario": "random", "until_advance": None}
    assert spec.param_names == list(first)


def test_task_ids_depend_on_the_parameters_only(write_spec):
    a = load_spec(write_spec(LOCOMOTION, "a.toml")).tasks()
    reordered = LOCOMOTION.replace('["salvador", "otero"]', '["otero", "salvador"]')
    b = load_spec(write_spec(reordered, "b.toml")).tasks()
    assert {t.id for t in a} == {t.id for t in b}
    assert len({t.id for t in a}) == len(a)
    changed = load_spec(write_spec(LOCOMOTION.replace("100", "101"), "c.toml")).tasks()
    assert not {t.id for t in a} & {t.id for t in changed}


@pytest.mark.parametrize(("text", "line", "words"), [
    ('kind = "locomotion"\n[grid]\nn = [5, 12\n', 3, "Unclosed array"),
    ('kind = "locomotion"\n[grid]\nn = 5 6\nseed = 1\n', 3, "Expected newline"),
    ('kind = "locomotion"\nfoo = 1\n[grid]\nruleset = "salvador"\n', 2, "unknown key 'foo'"),
    # the words of plan TOML and scenario files (toml_lines.unknown_key): the close key
    ('kind = "locomotion"\ndescripton = "x"\n[grid]\nruleset = "salvador"\n', 2,
     "unknown key 'descripton' (did you mean 'description'?)"),
    ('kind = "no-such-kind"\n[grid]\nx = 1\n', 1, "unknown kind 'no-such-kind'"),
    ('kind = "nomodule_here.x:f"\n[grid]\nx = 1\n', 1, "cannot import nomodule_here.x"),
    ('kind = "locomotion"\n[grid]\nruleset = "salvador"\nn = [5, "x"]\n', 4,
     "n must be int, not 'x'"),
    ('kind = "locomotion"\n[grid]\nruleset = "salvador"\nseed = { start = 5, stop = 5 }\n', 4,
     "is empty"),
    ('kind = "locomotion"\n[grid]\nruleset = "salvador"\nrounds = 10\n', 4,
     "no parameter 'rounds'"),
    ('kind = "locomotion"\n\n[grid]\nn = 5\n', 3, "needs ruleset"),
    ('kind = "locomotion"\n[grid]\n\nruleset = ["salvador", "salvadore"]\n', 4,
     "unknown rule set 'salvadore'"),
    ('kind = "plan"\n[grid]\nmodules = 10\nfamily = "square"\n', 4, "expected one of blob"),
    ('kind = "locomotion"\n[grid]\nruleset = "salvador"\nn = []\n', 4, "empty list"),
    ('kind = "locomotion"\n[grid]\nruleset = "salvador"\nseed = [1, 2, 1]\n', 4,
     "seed: 1 is in the list twice"),
    ('kind = "hexbot.bench.sweep:noop"\n[grid]\n\nseed = [1, "two", 3.5]\n', 4,
     "seed: values of one type, please (this list mixes float, int, str"),
    ('kind = "locomotion"\n[grid]\nruleset = "salvador"\n'
     'seed = { start = 0, stop = 1000000000 }\n', 4, "seed: 1,000,000,000 values"),
    ('kind = "locomotion"\n[grid]\nruleset = "salvador"\n'  # len(range()) overflowed
     'seed = { start = -9000000000000000000, stop = 9000000000000000000 }\n', 4,
     "seed: 18,000,000,000,000,000,000 values"),
    ('kind = "locomotion"\n[grid]\nruleset = "salvador"\nn = { start = 1, stop = 3000 }\n'
     'seed = { start = 0, stop = 3000 }\nround_limit = { start = 1, stop = 3000 }\n', 2,
     "the grid has 26,982,003,000 tasks (2,999 n x 3,000 seed x 2,999 round_limit)"),
    # the row's own column overwrote the parameter: every row had task "x", one was kept
    ('kind = "tests.sweep.sample_tasks:echo_params"\n[grid]\nseed = [1, 2, 3]\n'
     'task = "x"\n', 4, "task: the results table has a column of that name"),
    ('kind = "tests.sweep.sample_tasks:echo_params"\n[grid]\n\noutcome = 1\n', 4,
     "outcome: the results table has a column of that name"),
])
def test_errors_name_the_file_and_line(write_spec, text, line, words):
    path = write_spec(text)
    with pytest.raises(ScenarioError) as err:
        load_spec(path)
    assert str(err.value).startswith(f"{path}:{line}: "), str(err.value)
    assert words in str(err.value)


def test_a_hil_script_with_a_bad_line_stops_the_sweep_before_it_runs(write_spec, tmp_path):
    (tmp_path / "bad.hbs").write_text("select 1\nfrobnicate 3\n")
    path = write_spec('kind = "hil-script"\n[grid]\nscript = "bad.hbs"\nseed = [1, 2]\n')
    with pytest.raises(ScenarioError) as err:
        load_spec(path)
    assert str(err.value).startswith(f"{path}:3: script = 'bad.hbs': ")
    assert "bad.hbs:2" in str(err.value)  # the script's own line, too


def test_a_hil_script_whose_scenario_line_names_no_file_stops_the_sweep_before_it_runs(
        write_spec, tmp_path):
    (tmp_path / "s.hbs").write_text("# scenario: rig.toml\nselect 1\n")
    path = write_spec('kind = "hil-script"\n[grid]\nscript = "s.hbs"\nseed = [1, 2]\n')
    with pytest.raises(ScenarioError) as err:
        load_spec(path)
    assert str(err.value).startswith(f"{path}:3: script = 's.hbs': ")
    assert f"s.hbs:1: scenario: {tmp_path / 'rig.toml'}: no such scenario file" in str(err.value)


def test_the_cli_reports_a_bad_file_with_exit_1_and_writes_nothing(write_spec, tmp_path, capsys):
    path = write_spec('kind = "locomotion"\n[grid]\nruleset = "salvador"\nn = 0.5\n')
    out = tmp_path / "out"
    assert main(["sweep", str(path), "--out", str(out)]) == 1
    assert f"{path}:4: n must be int" in capsys.readouterr().err
    assert not out.exists()


def test_check_counts_the_tasks(write_spec, tmp_path, capsys):
    path = write_spec(LOCOMOTION)
    assert main(["sweep", str(path), "--check", "--out", str(tmp_path / "o")]) == 0
    assert "kind locomotion, 12 tasks" in capsys.readouterr().out
    assert not (tmp_path / "o").exists()


def test_shipped_example_sweeps_are_valid(capsys):
    from pathlib import Path

    examples = sorted((Path(__file__).parents[2] / "docs" / "examples").glob("sweep_*.toml"))
    assert examples
    for path in examples:
        assert main(["sweep", str(path), "--check"]) == 0, path


def test_a_binary_sweep_file_is_not_text(tmp_path, capsys):
    binary = tmp_path / "g.bin"
    binary.write_bytes(bytes([0xA9, 0xFF, 0x00, 0xC3]) * 75)
    assert main(["sweep", str(binary)]) == 1
    err = capsys.readouterr().err
    assert err.strip() == (f"hexbot sweep: error: {binary}: not a text file (UTF-8): "
                           "byte 0xa9 at offset 0")


def test_ints_among_floats_are_floats_and_a_big_grid_up_to_the_limit_is_fine(write_spec):
    from hexbot.sweep.spec import MAX_TASKS

    spec = load_spec(write_spec('kind = "hexbot.bench.sweep:noop"\n[grid]\nseed = [1, 2.5]\n'))
    assert spec.axes["seed"] == [1.0, 2.5]
    spec = load_spec(write_spec('kind = "hexbot.bench.sweep:noop"\n[grid]\n'
                                f'seed = {{ start = 0, stop = {MAX_TASKS} }}\n', "big.toml"))
    assert len(spec.axes["seed"]) == MAX_TASKS


def test_toml_dates_and_times_are_values_with_task_ids(write_spec):
    """A date in the grid of a dotted-path kind stopped the sweep with a
    traceback (the task id's JSON had no type for it)."""
    text = ('kind = "tests.sweep.sample_tasks:echo_params"\n[grid]\n'
            'day = [1979-05-27, 1980-01-01]\nat = 1979-05-27T07:32:00Z\nt = 07:32:00\n')
    tasks = load_spec(write_spec(text)).tasks()
    assert len({t.id for t in tasks}) == 2
    assert [t.id for t in load_spec(write_spec(text, "again.toml")).tasks()] == [
        t.id for t in tasks]  # the same in every run: --resume finds them
    as_text = load_spec(write_spec(text.replace("1979-05-27,", '"1979-05-27",')
                                   .replace("1980-01-01", '"1980-01-01"'), "s.toml")).tasks()
    assert not {t.id for t in as_text} & {t.id for t in tasks}  # a date is not its text


def test_a_hil_script_scenario_is_a_file_by_its_name_only(write_spec, tmp_path, monkeypatch):
    """(session 37) The rule of --scenario (hil_sim.scenario.is_scenario_file):
    `pair` beside the sweep file was taken for a file; `rig.toml` missing
    there was looked up in the current folder."""
    rig = 'name = "rig"\nbase = 1\n[[module]]\nid = 1\nposition = [0, 0]\n'
    (tmp_path / "s.hbs").write_text("select 1\n")
    (tmp_path / "pair").write_text(rig)
    elsewhere = tmp_path / "cwd"
    elsewhere.mkdir()
    (elsewhere / "rig.toml").write_text(rig)
    monkeypatch.chdir(elsewhere)
    spec = 'kind = "hil-script"\n[grid]\nscript = "s.hbs"\nscenario = "{}"\n'
    (task,) = load_spec(write_spec(spec.format("pair"))).tasks()
    assert task.call["scenario"] == "pair"  # the built-in
    (task,) = load_spec(write_spec(spec.format("./pair"))).tasks()
    assert task.call["scenario"] == str(tmp_path / "pair")
    path = write_spec(spec.format("rig.toml"))
    with pytest.raises(ScenarioError) as err:
        load_spec(path)
    assert str(err.value) == (f"{path}:4: scenario = 'rig.toml': {tmp_path / 'rig.toml'}: "
                              "no such scenario file")
