"""The built-in kinds refuse, at --check and before anything runs, every grid
value that their command refuses, in the command's words: a value the task
would only reject later (n = 0), or run as a success (round_limit = -1)."""

from __future__ import annotations

import pytest

from hexbot.cli import main
from hexbot.errors import UsageError

LOCOMOTION = 'kind = "locomotion"\n[grid]\nruleset = ["salvador"]\nseed = 1\n'
PLAN = 'kind = "plan"\n[grid]\nfamily = ["blob"]\nseed = 1\n'


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
