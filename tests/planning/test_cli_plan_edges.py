"""``hexbot plan`` at its edges: option values at their limits, --fixed in the
exact mode, --max-steps, and the highest id the link addresses."""

import json

import pytest

from hexbot.cli import main
from hexbot.protocol.wire import MAX_SELECT_ID

P01 = ("test_all_p01_initial.txt", "test_all_p01_goal.txt")


def run_plan(capsys, *argv):
    code = main(["plan", *map(str, argv)])
    out = capsys.readouterr()
    return code, out.out, out.err


def _toml(path, cells):
    path.write_text("cells = [" + ", ".join(f"[{x}, {y}]" for x, y in sorted(cells)) + "]\n")
    return path


@pytest.mark.parametrize("value", ["0", "-1", "0.0"])
def test_a_budget_that_is_not_positive_is_a_usage_error(cli_status, capsys, examples_dir, value):
    code, err = cli_status("plan", *(examples_dir / f for f in P01), "--budget", value)
    assert code == 2 and f"argument --budget: the budget must be positive, got '{value}'" in err


def test_fixed_is_honoured_in_the_exact_mode(capsys, tmp_path):
    # the fewest moves (4) move the module at (1, 0); bolted there, 5
    a = _toml(tmp_path / "a.toml", [(0, 0), (0, 1), (1, 0), (1, 1)])
    b = _toml(tmp_path / "b.toml", [(-1, 0), (0, 0), (1, -1), (1, 0)])
    code, out, err = run_plan(capsys, a, b, "--mode", "exact", "--serial", "--json")
    assert code == 0 and json.loads(out)["moves"] == 4
    code, out, err = run_plan(capsys, a, b, "--mode", "exact", "--serial", "--json",
                              "--fixed", "1,0")
    data = json.loads(out)
    assert code == 0 and err == "" and data["moves"] == 5
    assert all(move["from"] != [1, 0] for step in data["steps"] for move in step["moves"])


def test_max_steps_stops_a_faithful_plan_with_exit_status_1(capsys, examples_dir):
    pair = [examples_dir / f for f in P01]  # five parallel time steps
    code, out, err = run_plan(capsys, *pair, "--mode", "faithful-parallel", "--max-steps", "4",
                              "--json", "--summary")
    assert code == 1 and json.loads(out)["reached"] is False
    assert err == "hexbot plan: goal not reached: goal not reached after 4 time steps\n"
    code, _, err = run_plan(capsys, *pair, "--mode", "faithful-parallel", "--max-steps", "5")
    assert code == 0 and err == ""


def test_the_highest_select_id_still_gets_firmware_commands(capsys, tmp_path):
    a = tmp_path / "a.toml"
    a.write_text(f"[[module]]\nid = {MAX_SELECT_ID - 1}\ncell = [0, 0]\n"
                 f"[[module]]\nid = {MAX_SELECT_ID}\ncell = [1, 0]\n")
    b = _toml(tmp_path / "b.toml", [(0, 0), (0, 1)])
    code, out, err = run_plan(capsys, a, b, "--json")
    data = json.loads(out)
    assert code == 0 and data["reached"] is True and "commands_omitted" not in data
    moves = [m for step in data["steps"] for m in step["moves"]]
    assert moves and all(m["commands"] for m in moves)
    assert {m["module"] for m in moves} == {MAX_SELECT_ID}
