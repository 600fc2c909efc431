"""Sweep files at their edges: every wrong value refused with file:line before
anything runs, and task ids that do not depend on how the file is laid out."""

from __future__ import annotations

import pytest

from hexbot.cli import main
from hexbot.errors import ScenarioError
from hexbot.sweep.spec import load_spec

DOTTED = 'kind = "tests.sweep.edge_tasks:fail_on"\n'


@pytest.mark.parametrize(("text", "line", "words"), [
    (DOTTED + "[grid]\nseed = { start = 0, stop = 5, step = 0 }\n", 3,
     "seed: range step must be at least 1"),
    (DOTTED + "[grid]\nseed = { start = 5, stop = 0, step = -1 }\n", 3,
     "seed: range step must be at least 1"),
    (DOTTED + "[grid]\nseed = { start = 0, stop = 9, setp = 3 }\n", 3,
     "seed: a range is { start = A, stop = B } with optional step = K, not ['setp', "),
    (DOTTED + "[grid]\n\nseed = [1, \"two\"]\n", 4,
     "seed: values of one type, please (this list mixes int, str"),
    (DOTTED + "[grid]\nseed = [true, 2]\n", 3, "seed: values of one type, please"),
    (DOTTED + "output = 5\n[grid]\nseed = 1\n", 2, "output must be a folder name"),
    (DOTTED + 'description = ["a", "list"]\n[grid]\nseed = 1\n', 2,
     "description must be a string"),
])
def test_a_wrong_value_is_refused_with_file_and_line(write_spec, text, line, words):
    path = write_spec(text)
    with pytest.raises(ScenarioError) as err:
        load_spec(path)
    assert str(err.value).startswith(f"{path}:{line}: "), str(err.value)
    assert words in str(err.value)


def test_the_cli_refuses_a_zero_step_with_exit_1_and_no_traceback(write_spec, tmp_path, capsys):
    path = write_spec(DOTTED + "[grid]\nseed = { start = 0, stop = 5, step = 0 }\n")
    assert main(["sweep", str(path), "--check", "--out", str(tmp_path / "o")]) == 1
    err = capsys.readouterr().err
    assert f"{path}:3: seed: range step must be at least 1" in err
    assert "Traceback" not in err


def test_task_ids_do_not_depend_on_the_order_of_the_grids_lines(write_spec):
    """--resume finds the stored rows of a file whose [grid] lines were reordered."""
    a = load_spec(write_spec(DOTTED + '[grid]\nseed = [1, 2]\nbad = 2\ntag = "x"\n', "a.toml"))
    b = load_spec(write_spec(DOTTED + '[grid]\ntag = "x"\nbad = 2\nseed = [1, 2]\n', "b.toml"))
    assert {t.id: t.params for t in a.tasks()} == {t.id: t.params for t in b.tasks()}
