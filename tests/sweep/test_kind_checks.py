"""The built-in kinds refuse, at --check and before anything runs, every grid
value that their command refuses, in the command's words: a value the task
would only reject later (n = 0), or run as a success (round_limit = -1)."""

from __future__ import annotations

import pytest

from hexbot.cli import main
from hexbot.errors import UsageError

LOCOMOTION = 'kind = "locomotion"\n[grid]\nruleset = ["salvador"]\nseed = 1\n'
PLAN = 'kind = "plan"\n[grid]\nfamily = ["blob"]\nseed = 1\n'
BLOBS = PLAN.replace("seed = 1", "modules = 10")


@pytest.mark.parametrize(("head", "line", "words", "fine"), [
    pytest.param(LOCOMOTION, "n = [0]", "n = 0: must be 1..100,000, got 0", "n = [1]", id="n-0"),
    pytest.param(LOCOMOTION, "n = [5, -1]", "n = -1: must be 1..100,000, got -1", "n = [5, 1]",
                 id="n-neg"),
    pytest.param(LOCOMOTION, "n = [99999999999]",
                 "n = 99999999999: must be 1..100,000, got 99999999999", "n = [100000]",
                 id="n-huge"),
    pytest.param(LOCOMOTION, "round_limit = -1", "round_limit = -1: must be at least 1, got -1",
                 "round_limit = 1", id="rounds-neg"),
    pytest.param(LOCOMOTION, "round_limit = { start = 0, stop = 3 }",
                 "round_limit = 0: must be at least 1, got 0",
                 "round_limit = { start = 1, stop = 3 }", id="rounds-range-from-0"),
    pytest.param(LOCOMOTION, "until_advance = 0",
                 "until_advance = 0: must be at least 1, got 0", "until_advance = 1",
                 id="until-0"),
    pytest.param(PLAN, "modules = [10000000000]",
                 "modules = 10000000000: must be 2..100,000, got 10000000000",
                 "modules = [100000]", id="modules-huge"),
    pytest.param(PLAN, "modules = [1, 10]", "modules = 1: must be 2..100,000, got 1",
                 "modules = [2, 10]", id="modules-1"),
    # documented as 0..1, unchecked before (session 37 fuzz)
    pytest.param(BLOBS, "compact = [0.5, 1.5]", "compact = 1.5: must be at most 1, got 1.5",
                 "compact = [0.0, 1.0]", id="compact-over-1"),
    pytest.param(BLOBS, "compact = -0.1", "compact = -0.1: must be 0 or more, got -0.1",
                 "compact = 0", id="compact-neg"),
    pytest.param(BLOBS, "compact = nan", "compact = nan: not a finite number: 'nan'",
                 "compact = 0.5", id="compact-nan"),
    # `hexbot locomotion random --seeds`'s check: -1 ran, its replay hint named random--1
    pytest.param(LOCOMOTION.replace("seed = 1", "n = 5"), "seed = [2, -1]",
                 "seed = -1: a map seed is a whole number 0..9223372036854775807, got '-1'",
                 "seed = [2, 0]", id="seed-neg"),
])
def test_check_refuses_a_value_the_command_refuses(write_spec, tmp_path, capsys, head, line,
                                                   words, fine):
    path = write_spec(head + line + "\n")
    assert main(["sweep", str(path), "--check", "--out", str(tmp_path / "out")]) == 1
    err = capsys.readouterr().err
    assert f"{path}:5: {words}" in err and "Traceback" not in err
    # the end of the range itself passes
    path = write_spec(head + fine + "\n")
    assert main(["sweep", str(path), "--check", "--out", str(tmp_path / "out")]) == 0


def test_a_negative_round_limit_no_longer_runs_as_a_success(write_spec, tmp_path, capsys):
    """It ran, and every task was stored as ok (rounds-exhausted), exit 0."""
    path = write_spec(LOCOMOTION + "n = [5]\nround_limit = -1\n")
    out = tmp_path / "out"
    assert main(["sweep", str(path), "--out", str(out), "--workers", "1", "--no-progress"]) == 1
    assert "round_limit = -1: must be at least 1" in capsys.readouterr().err
    assert not out.exists()  # no task ran, no row was stored


def test_the_locomotion_command_and_the_sweep_say_the_same(write_spec, tmp_path, cli_status):
    code, err = cli_status("locomotion", "run", "salvador", "flat", "--n", "0")
    assert code == 2 and "argument --n: must be 1..100,000, got 0" in err
    path = write_spec(LOCOMOTION + "n = 0\n")
    code, err = cli_status("sweep", path, "--check", "--out", tmp_path / "o")
    assert code == 1 and "n = 0: must be 1..100,000, got 0" in err


def test_bench_planning_refuses_the_module_counts_the_plan_kind_refuses():
    from hexbot.bench.planning import size_list

    with pytest.raises(UsageError, match=r"^--sizes: must be 2\.\.100,000, got 100001$"):
        size_list("10,100001", "--sizes")
    assert size_list("2,100000", "--sizes") == [2, 100000]


def test_a_size_the_parallelogram_family_lacks_is_refused_at_check(write_spec, tmp_path,
                                                                    capsys):
    """Two parameters together (the kind's check_task, for every task of the
    grid): before, --check passed and the task failed when it ran."""
    spec = 'kind = "plan"\n[grid]\nfamily = [{}]\nmodules = [10, 7]\n'
    path = write_spec(spec.format('"blob", "parallelogram"'))
    assert main(["sweep", str(path), "--check", "--out", str(tmp_path / "out")]) == 1
    err = capsys.readouterr().err
    assert (f"{path}:2: the task family = 'parallelogram', modules = 7: the parallelogram "
            "sizes are 10, 30, 100, 300, 1000, got 7") in err and "Traceback" not in err
    path = write_spec(spec.format('"blob", "apart"'))  # 7 is a blob size
    assert main(["sweep", str(path), "--check", "--out", str(tmp_path / "out")]) == 0


def test_bench_planning_cases_refuses_a_size_without_a_parallelogram(cli_status):
    """The same check: `--cases --sizes 7` was a KeyError traceback after the
    thesis cases had run."""
    code, err = cli_status("bench", "planning", "--cases", "--sizes", "10,7")
    assert code == 2 and err.endswith(
        "--sizes: the parallelogram sizes are 10, 30, 100, 300, 1000, got 7\n"), err
