"""``hexbot plan``: JSON format, exit status, reasons on stderr, plots, input errors."""

import json
import re

import pytest

from hexbot.cli import main
from hexbot.errors import ScenarioError
from hexbot.planning.config_io import parse_grid, parse_toml

P01 = ("test_all_p01_initial.txt", "test_all_p01_goal.txt")


def run_plan(capsys, *argv):
    code = main(["plan", *map(str, argv)])
    out = capsys.readouterr()
    return code, out.out, out.err


def test_json_object_has_the_documented_shape(capsys, examples_dir):
    code, out, err = run_plan(capsys, examples_dir / P01[0], examples_dir / P01[1],
                              "--mode", "faithful-parallel", "--json")
    assert code == 0 and err == ""
    data = json.loads(out)
    assert set(data) == {"mode", "method", "reached", "moves", "time_steps", "bounds", "steps"}
    assert data["mode"] == "faithful-parallel" and data["reached"] is True
    assert len(data["steps"]) == data["time_steps"] == 5
    assert data["moves"] == sum(len(step["moves"]) for step in data["steps"])
    assert data["bounds"] == {"moves": {"value": 6, "kind": "assignment"},
                              "time_steps": {"value": 3, "kind": "pivot"},
                              "bottleneck": {"value": 2, "kind": "bottleneck"}}
    move = data["steps"][0]["moves"][0]
    assert set(move) == {"module", "from", "to", "joint", "direction", "substrate", "commands"}
    assert 1 <= move["joint"] <= 6 and move["direction"] in ("CW", "CCW")
    assert move["commands"][-1]["code"] in (67, 68)
    assert all(set(c) == {"code", "args"} for c in move["commands"])


def test_unreached_goal_exits_non_zero_with_reason(capsys, examples_dir):
    code, out, err = run_plan(capsys, examples_dir / P01[1], examples_dir / P01[0],
                              "--mode", "faithful-parallel", "--json")
    assert code == 1
    data = json.loads(out)
    assert data["reached"] is False and "stalled" in data["reason"]
    assert "goal not reached" in err and "stalled" in err


def test_the_report_gives_the_pairs_lower_bounds_with_the_fixed_module(capsys, examples_dir):
    """What no plan can beat, next to the plan: the assignment bound on moves,
    the pivot bound on time steps (the bolted module never leaves, so fixing
    one can raise it) and the plain bottleneck; none for a pair that is not one."""
    s02 = (examples_dir / "test_all_s02_initial.txt", examples_dir / "test_all_s02_goal.txt")
    code, out, _ = run_plan(capsys, *s02, "--mode", "exact")
    assert code == 0
    first = out.splitlines()[0]
    assert first.startswith("mode exact (A*): goal reached, ") and " 17 move(s)" in first
    assert first.endswith("(lower bounds: 15 move(s), 4 time step(s); plain bottleneck 2 step(s))")
    code, out, _ = run_plan(capsys, *s02, "--fixed", "0,3", "--json")
    data = json.loads(out)
    assert code == 0 and data["bounds"]["time_steps"] == {"value": 5, "kind": "pivot"}
    assert data["time_steps"] >= 5 and data["moves"] >= 15
    code, out, _ = run_plan(capsys, *s02, "--fixed", "0,0", "--json")  # (0, 0) not in S02
    data = json.loads(out)
    assert code == 1 and "bounds" not in data and "fixed module" in data["reason"]


def test_robust_mode_text_output_and_plot(capsys, examples_dir, tmp_path):
    png = tmp_path / "plan.png"
    code, out, _ = run_plan(capsys, examples_dir / P01[1], examples_dir / P01[0], "--plot", png)
    assert code == 0
    assert "mode robust (direct): goal reached" in out and "Select(" in out
    assert "tried first" not in out  # the first method planned
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_pair_apart_from_toml_files_goes_through_the_middle_ball(capsys, tmp_path):
    from hexbot.planning.bounds import move_lower_bound
    from hexbot.planning.generate import random_blob

    initial = sorted(random_blob(30, 0, 0.8))
    goal = random_blob(30, 1, 0.8)
    shift = max(x for x, _ in initial) - min(x for x, _ in goal) + 2  # no overlap
    files = []
    for name, cells in (("initial", initial), ("goal", sorted((x + shift, y) for x, y in goal))):
        path = tmp_path / f"{name}.toml"
        path.write_text("cells = [" + ", ".join(f"[{x}, {y}]" for x, y in cells) + "]\n")
        files.append(path)
    code, out, _ = run_plan(capsys, *files, "--json")
    result = json.loads(out)
    assert code == 0 and result["reached"] is True
    assert result["method"] == "middle ball"
    # the detour stays within a few times the move bound (the strip took 9x here)
    bound = move_lower_bound(frozenset(initial), frozenset((x + shift, y) for x, y in goal))
    assert result["bounds"]["moves"] == {"value": bound.value, "kind": "assignment"}
    assert bound.value < result["moves"] < 2 * bound.value
    assert result["moves"] == sum(len(step["moves"]) for step in result["steps"])


def test_a_fallback_plan_says_why_the_methods_before_it_did_not_plan(capsys, tmp_path):
    # a disc of radius 5 whose centre must be emptied: the direct methods, the
    # local flows (with digs too: more than 40 modules wall the centre in) and
    # the middle ball do not plan it, the canonical strip does
    from hexbot.planning.windows import disc

    cells = disc((0, 0), 5)
    files = []
    for name, shape in (("initial", cells - {(5, 0)}), ("goal", cells - {(0, 0)})):
        path = tmp_path / f"{name}.toml"
        path.write_text("cells = [" + ", ".join(f"[{x}, {y}]" for x, y in sorted(shape)) + "]\n")
        files.append(path)
    code, out, _ = run_plan(capsys, *files, "--json")
    result = json.loads(out)
    assert code == 0 and result["reached"] is True and result["method"] == "canonical strip"
    tried = result["tried"]
    assert [reason.split(":")[0] for reason in tried] == [
        "direct", "direct, backwards", "local", "middle ball"]
    assert all(len(reason.split(": ", 1)[1]) > 10 for reason in tried)  # a reason each
    code, out, _ = run_plan(capsys, *files)
    assert code == 0
    notes = [line for line in out.splitlines() if line.startswith("note: tried first")]
    assert len(notes) == 4 and "middle ball" in notes[-1]


def test_a_walled_in_centre_is_dug_out_locally_at_61_modules():
    # the flows without digs stall on it (a ring of modules walls the centre
    # in from the start); below LOCAL_LIMIT the flows with digs run last
    from hexbot.planning.checker import check_plan
    from hexbot.planning.configuration import Configuration
    from hexbot.planning.robust import plan_robust
    from hexbot.planning.windows import disc

    cells = disc((0, 0), 4)
    start = Configuration.from_cells(cells - {(4, 0)})
    plan = plan_robust(start, frozenset(cells - {(0, 0)}))
    assert plan.reached and plan.method == "local" and plan.move_count < 500  # strip: 2,388
    assert check_plan(start, cells - {(0, 0)}, plan.steps).ok


def test_the_planner_tells_each_stage_as_it_starts():
    from hexbot.planning.configuration import Configuration
    from hexbot.planning.robust import plan_robust
    from hexbot.planning.windows import disc

    cells = disc((0, 0), 5)
    told: list[str] = []
    plan = plan_robust(Configuration.from_cells(cells - {(5, 0)}), frozenset(cells - {(0, 0)}),
                       progress=told.append)
    assert plan.reached
    assert told == ["direct", "direct, backwards", "local", "middle ball", "canonical strip",
                    "schedule"]  # the strip's plan is not tidied


def test_bad_grid_file_names_file_and_line(capsys, tmp_path, examples_dir):
    bad = tmp_path / "bad.txt"
    bad.write_text("0 0 1\n0 2 1\n")
    code, _, err = run_plan(capsys, bad, examples_dir / P01[1])
    assert code == 1 and f"{bad}:2" in err and "'2'" in err


def test_grid_accepts_matlab_decorations_and_rejects_ragged_rows():
    config = parse_grid("I = [0 0 0 0 0\n     1 0 0 0 0\n     1 1 1 1 1];  % comment\n")
    assert config.cells == {(0, 1), (0, 0), (1, 0), (2, 0), (3, 0), (4, 0)}
    assert config[(0, 1)].id == 1  # reading order: top row first
    with pytest.raises(ScenarioError, match=r"f:3: row has 2 columns"):
        parse_grid("1 1 1\n\n1 0", "f")
    with pytest.raises(ScenarioError, match="all zeros"):
        parse_grid("0 0\n0 0", "f")


def test_toml_cells_and_modules():
    assert parse_toml("cells = [[0, 0], [1, 0]]").cells == {(0, 0), (1, 0)}
    config = parse_toml("[[module]]\nid = 5\ncell = [2, -1]\norientation = 3\n")
    assert config[(2, -1)].id == 5 and config[(2, -1)].orientation == 3
    with pytest.raises(ScenarioError, match="orientation must be 0..5"):
        parse_toml("[[module]]\nid = 5\ncell = [0, 0]\norientation = 7\n", "m.toml")
    with pytest.raises(ScenarioError, match="listed twice"):
        parse_toml("cells = [[0, 0], [0, 0]]", "c.toml")
    with pytest.raises(ScenarioError, match="c.toml"):
        parse_toml("cells = [[0, 0]", "c.toml")


def _toml(path, cells):
    path.write_text("cells = [" + ", ".join(f"[{x}, {y}]" for x, y in sorted(cells)) + "]\n")
    return path


def test_summary_leaves_the_steps_out_and_keeps_the_rest(capsys, examples_dir):
    """``--summary``: what a plan of millions of moves is printed for, without
    its moves: the summary line, the notes, the counts and bounds, the exit
    status."""
    s02 = (examples_dir / "test_all_s02_initial.txt", examples_dir / "test_all_s02_goal.txt")
    code, full, _ = run_plan(capsys, *s02)
    code_short, short, _ = run_plan(capsys, *s02, "--summary")
    assert code == code_short == 0
    assert short.splitlines() == [line for line in full.splitlines()
                                  if not line.startswith(("step ", "  ", "      "))]
    assert short.splitlines()[0] == full.splitlines()[0] and "step 1:" in full
    code, out, _ = run_plan(capsys, *s02, "--json")
    whole = json.loads(out)
    code_short, out, _ = run_plan(capsys, *s02, "--json", "--summary")
    head = json.loads(out)
    assert code == code_short == 0 and "steps" not in head
    assert head == {k: v for k, v in whole.items() if k != "steps"}
    assert head["moves"] == sum(len(step["moves"]) for step in whole["steps"])
    # an unreached goal: still exit 1 with the reason, and no steps
    code, out, err = run_plan(capsys, examples_dir / P01[1], examples_dir / P01[0],
                              "--mode", "faithful-parallel", "--json", "--summary")
    data = json.loads(out)
    assert code == 1 and data["reached"] is False and "steps" not in data
    assert "stalled" in data["reason"] and "goal not reached" in err


def test_json_plans_any_size_and_ids_without_commands_past_the_link(capsys, tmp_path):
    from hexbot.planning.generate import blob_pair, scramble

    initial, _ = blob_pair(100, 0)
    goal = scramble(initial, 30, 0)
    a, b = _toml(tmp_path / "a.toml", initial), _toml(tmp_path / "b.toml", goal)
    code, out, err = run_plan(capsys, a, b, "--json")
    data = json.loads(out)
    assert code == 0 and data["reached"] is True and err == ""
    assert "1..63" in data["commands_omitted"]
    moves = [m for step in data["steps"] for m in step["moves"]]
    assert moves and all(m["commands"] is None for m in moves)
    assert max(m["module"] for m in moves) <= 100


def test_json_is_written_a_step_at_a_time_as_the_object_would_be(examples_dir):
    """--json streams its steps (millions of moves at 10,000 modules); the text
    is json.dumps of the whole object, with commands and without."""
    import io

    from hexbot.planning.cli_plan import plan_json, write_plan_json
    from hexbot.planning.config_io import load_configuration
    from hexbot.planning.generate import blob_pair, scramble
    from hexbot.planning.robust import plan_robust

    small = plan_robust(load_configuration(examples_dir / P01[0]),
                        load_configuration(examples_dir / P01[1]).cells)
    initial, _ = blob_pair(100, 0)
    large = plan_robust(parse_toml("cells = " + str([list(c) for c in sorted(initial)])),
                        frozenset(scramble(initial, 30, 0)))
    for plan in (small, large):
        for extra in (None, {"execution": {"ok": True}}):
            out = io.StringIO()
            write_plan_json(plan, "combined", out, extra)
            assert out.getvalue() == json.dumps({**plan_json(plan), **(extra or {})}) + "\n"
    assert "commands_omitted" in plan_json(large) and "commands_omitted" not in plan_json(small)


def test_execute_refuses_more_modules_than_the_link_addresses(capsys, tmp_path):
    from hexbot.planning.generate import random_blob

    cells = random_blob(70, 0)
    a = _toml(tmp_path / "a.toml", cells)
    code, _, err = run_plan(capsys, a, a, "--execute")
    assert code == 1 and "1..63" in err and len(err.strip().splitlines()) == 1


def test_budget_used_up_exits_non_zero_with_the_reason(capsys, examples_dir):
    code, out, err = run_plan(capsys, examples_dir / "test_all_s02_initial.txt",
                              examples_dir / "test_all_s02_goal.txt", "--json",
                              "--budget", "0.000001")
    assert code == 1 and json.loads(out)["reached"] is False
    assert "time budget" in err and len(err.strip().splitlines()) == 1


def test_exact_mode_from_the_cli(capsys, examples_dir):
    code, out, _ = run_plan(capsys, examples_dir / "test_all_s02_initial.txt",
                            examples_dir / "test_all_s02_goal.txt", "--mode", "exact",
                            "--json", "--serial")
    data = json.loads(out)
    assert code == 0 and data["mode"] == "exact" and len(data["steps"]) == 17


def test_render_animates_every_time_step_with_legend_and_grid(capsys, examples_dir, tmp_path):
    import numpy as np
    from PIL import Image

    from hexbot.planning.plot import COLORS

    out = tmp_path / "plan.gif"
    code, text, _ = run_plan(capsys, examples_dir / "test_all_s02_initial.txt",
                             examples_dir / "test_all_s02_goal.txt", "--mode", "exact",
                             "--json", "--render", out)
    steps = len(json.loads(text)["steps"])
    gif = Image.open(out)
    assert code == 0 and gif.n_frames == steps + 1  # the start, then after each step
    gif.seek(1)
    pixels = np.asarray(gif.convert("RGB")).reshape(-1, 3)
    seen = set(map(tuple, pixels.tolist()))
    mover = tuple(int(COLORS["mover"][k:k + 2], 16) for k in (1, 3, 5))
    assert mover in seen  # this step's movers, and the legend's swatch


def test_a_binary_configuration_file_is_not_text(cli_status, capsys, tmp_path, examples_dir):
    binary = tmp_path / "g.bin"
    binary.write_bytes(bytes([0xA9, 0xFF, 0x00, 0xC3]) * 75)
    code, err = cli_status("plan", binary, examples_dir / "block6_goal.txt")
    assert code == 1 and "Traceback" not in err
    assert err.strip() == (f"hexbot plan: error: {binary}: not a text file (UTF-8): "
                           "byte 0xa9 at offset 0")


def test_an_output_in_a_missing_folder_is_refused_before_planning(cli_status, tmp_path,
                                                                   examples_dir):
    pair = (examples_dir / P01[1], examples_dir / P01[0])
    for option, name in (("--plot", "x.png"), ("--render", "x.gif")):
        code, err = cli_status("plan", *pair, option, tmp_path / "nope" / name)
        assert code == 2, err
        assert f"argument {option}: {tmp_path / 'nope' / name}: folder" in err
    code, err = cli_status("plan", *pair, "--plot", tmp_path)
    assert code == 2 and "is a folder, give a file name" in err


def test_coordinates_beyond_the_planner_limit_name_file_and_line(cli_status, capsys, tmp_path):
    from hexbot.planning.hexlattice import COORD_LIMIT

    big = tmp_path / "big.toml"
    big.write_text("# far\ncells = [[0, 0], [0, 99999999999]]\n")
    two = _toml(tmp_path / "two.toml", [(0, 0), (0, 1)])
    code, err = cli_status("plan", big, two)
    assert code == 1 and "Traceback" not in err
    assert f"{big}:2: cell [0, 99999999999] is outside the planner's coordinate range" in err
    with pytest.raises(ScenarioError, match=r"m.toml:1: \[\[module\]\] #1: cell"):
        parse_toml(f"[[module]]\nid = 1\ncell = [{-COORD_LIMIT - 1}, 0]\n", "m.toml")
    assert parse_toml(f"cells = [[{COORD_LIMIT}, {-COORD_LIMIT}]]").cells == {
        (COORD_LIMIT, -COORD_LIMIT)}


def test_max_steps_below_one_is_a_usage_error(cli_status, capsys, examples_dir):
    code, err = cli_status("plan", examples_dir / P01[1], examples_dir / P01[0],
                        "--mode", "faithful-serial", "--max-steps", "0")
    assert code == 2 and "argument --max-steps: must be at least 1, got 0" in err


# -- the audit of `hexbot plan` (each test failed before its fix) -----------------


def test_a_toml_configuration_not_named_toml_is_refused_not_read_as_a_grid(cli_status, capsys,
                                                                           tmp_path):
    """The format follows the suffix: `cells = [[1, 1], [1, 0]]` in a .cfg file
    was read as the grid `1 1 1 0` and "planned" (goal reached, 0 moves)."""
    cfg = tmp_path / "pair_cells.cfg"
    cfg.write_text("cells = [[1, 1], [1, 0]]\n")
    three = tmp_path / "three.txt"
    three.write_text("1 1 1\n")
    code, err = cli_status("plan", cfg, three)
    assert code == 1 and err.strip() == (
        f"hexbot plan: error: {cfg}:1: a bracket inside a bracket: not a 0/1 grid "
        "(a TOML configuration must be named .toml)")
    with pytest.raises(ScenarioError, match=r"m.cfg:1: a bracket inside a bracket"):
        parse_grid("[[module]]\nid = 1\ncell = [0, 0]\n", "m.cfg")
    with pytest.raises(ScenarioError, match=r"g:2: expected 0 or 1, found 'G'"):
        parse_grid("I = [1 1]\nG = [1 1]\n", "g")  # MATLAB's `I = [` once, before the rows
    with pytest.raises(ScenarioError, match=r"g:1: expected 0 or 1, found 'cells'"):
        parse_grid("cells 1 1\n", "g")


def test_drawing_names_are_checked_before_planning_and_a_failed_write_is_one_line(
        cli_status, capsys, tmp_path, examples_dir, monkeypatch):
    """--plot out.txt was a matplotlib ValueError, --plot /proc/x.png an OSError,
    both tracebacks after the planning; --plot noext wrote noext.png."""
    pair = (examples_dir / P01[1], examples_dir / P01[0])
    for option, name, words in (
            ("--plot", tmp_path / "out.txt", "the name must end in .png"),
            ("--plot", tmp_path / "noext", "the name must end in .png"),
            ("--render", tmp_path / "out.txt", "the name must end in .gif"),
            ("--render", tmp_path / "out.png", "the name must end in .gif"),
            ("--plot", "/proc/x.png", "/proc/x.png: cannot write"),
            ("--render", "/proc/x.gif", "/proc/x.gif: cannot write")):
        code, err = cli_status("plan", *pair, option, name)
        assert code == 2 and f"argument {option}: " in err and words in err, (name, err)
        assert "Traceback" not in err
    assert not list(tmp_path.iterdir())  # nothing written, no probe left behind
    from hexbot.planning import plot

    def full_disk(plan, path):
        raise OSError(28, "No space left on device")
    monkeypatch.setattr(plot, "plot_plan", full_disk)
    code, err = cli_status("plan", *pair, "--plot", tmp_path / "p.png")
    assert code == 1 and err.strip() == (
        f"hexbot plan: error: --plot: cannot write {tmp_path / 'p.png'}: No space left on device")


def test_a_grid_file_keeps_to_the_coordinate_limit(cli_status, capsys, tmp_path):
    """A grid of 1,100,000 rows crashed the C scheduler ("a cell is out of
    range"): grids pass through the TOML lists' one check."""
    from hexbot.planning.hexlattice import COORD_LIMIT

    tall = tmp_path / "tall.txt"
    tall.write_text("0\n1\n" + "0\n" * COORD_LIMIT + "1\n")  # (0, COORD_LIMIT + 1) on line 2
    code, err = cli_status("plan", tall, tall)
    assert code == 1 and err.strip() == (
        f"hexbot plan: error: {tall}:2: cell [0, {COORD_LIMIT + 1}] is outside the planner's "
        f"coordinate range (-{COORD_LIMIT:,}..{COORD_LIMIT:,})")
    wide = "0 " * (COORD_LIMIT + 1) + "1\n"
    with pytest.raises(ScenarioError, match=rf"w:2: cell \[{COORD_LIMIT + 1}, 0\] is outside"):
        parse_grid("% wide\n" + wide, "w")
    assert parse_grid("1\n" + "0\n" * (COORD_LIMIT - 1) + "1\n").cells == {(0, 0), (0, COORD_LIMIT)}


def test_booleans_are_not_integers_in_toml(tmp_path):
    """`id = true` passed isinstance(True, int): "goal reached", then the JSON failed."""
    for entry, words in (("id = true\ncell = [0, 0]", "id must be an integer 1..63"),
                         ("id = 1\ncell = [0, 0]\norientation = true", "orientation must be 0..5"),
                         ("id = 1\ncell = [true, 0]", "a cell must be [x, y] with two integers")):
        with pytest.raises(ScenarioError, match=re.escape(f"m.toml:1: [[module]] #1: {words}")):
            parse_toml(f"[[module]]\n{entry}\n", "m.toml")


def test_a_far_pair_keeps_to_its_time_budget(capsys, tmp_path):
    """Two modules a million cells from their goal: a window fix built a corridor
    of millions of cells (16 s of CPU and 910 MB with --budget 1)."""
    import time

    from hexbot.planning.windows import corridor

    started = time.process_time()
    assert corridor((1_000_000, 0), (1_000_000, -1_000_000), 1) is None
    assert time.process_time() - started < 0.1
    assert len(corridor((0, 0), (3, 0), 1)) == 16  # a short one is built as before
    a = _toml(tmp_path / "f1.toml", [(1_000_000, 0), (999_999, 0)])
    b = _toml(tmp_path / "f2.toml", [(1_000_000, -1_000_000), (999_999, -1_000_000)])
    started = time.process_time()
    code, _, err = run_plan(capsys, a, b, "--budget", "1", "--summary")
    assert code == 1 and "goal not reached" in err
    assert time.process_time() - started < 8


def test_a_budget_message_names_the_limit_that_ran_out():
    """A method's wall share ran out while its CPU cap did not, and the message
    gave the cap: `--budget 3` said "its time budget of 2 s is used up"."""
    from hexbot.planning.budget import BudgetExhausted, Deadline

    with pytest.raises(BudgetExhausted,
                       match=r"^local: gave up, its time budget of 0 s is used up$"):
        Deadline(0.0).capped(100.0).check("local")
    with pytest.raises(BudgetExhausted,
                       match=r"^direct: gave up, its cap of 0 s of CPU time is used up$"):
        Deadline(100.0).capped(0.0).check("direct")


def test_fixed_is_a_usage_error_in_the_faithful_modes(cli_status, capsys, examples_dir):
    for mode in ("faithful-serial", "faithful-parallel"):
        code, err = cli_status("plan", *(examples_dir / f for f in P01), "--mode", mode,
                               "--fixed", "0,0")
        assert code == 2 and err.strip() == (
            f"hexbot plan: error: --fixed is for the robust and exact modes: the thesis' "
            f"planner ({mode}) bolts no module")


def test_a_faithful_plan_the_checker_rejects_is_no_success(capsys, examples_dir):
    """S02 in faithful-parallel: two moves of step 5 need one cell. The plan is
    the thesis' (unchanged); it exited 0 with "goal reached" and a warning."""
    from hexbot.planning.config_io import load_configuration
    from hexbot.planning.thesis.planner import plan_faithful

    s02 = (examples_dir / "test_all_s02_initial.txt", examples_dir / "test_all_s02_goal.txt")
    code, out, err = run_plan(capsys, *s02, "--mode", "faithful-parallel", "--summary")
    problem = "step 5: modules 2 and 3 both need cell (1, 5)"
    assert code == 1
    assert err == f"hexbot plan: the independent checker rejects the plan: {problem}\n"
    assert out.startswith(
        "mode faithful-parallel: goal reached by an ILLEGAL plan, 10 time step(s)")
    code, out, err = run_plan(capsys, *s02, "--mode", "faithful-parallel", "--json")
    data = json.loads(out)
    assert code == 1 and data["rejected"] == problem and data["reached"] is True
    same = plan_faithful(load_configuration(s02[0]), load_configuration(s02[1]).cells, True)
    assert [[(m["module"], tuple(m["to"])) for m in s["moves"]] for s in data["steps"]] == [
        [(m.module, m.dst) for m in step.moves] for step in same.steps]
    code, out, err = run_plan(capsys, *s02, "--mode", "faithful-serial", "--summary")
    assert code == 0 and err == "" and "ILLEGAL" not in out  # the serial plan is legal


def test_a_pair_farther_apart_than_two_to_the_20_keeps_its_bounds():
    """The bounds' "never" sentinel (2^20) was also the cut-off for "no plan can
    exist": a pair 2,000,000 cells apart lost its bounds."""
    from hexbot.planning.cli_plan import pair_bounds
    from hexbot.planning.configuration import Configuration
    from hexbot.planning.plan import Plan

    start = Configuration.from_cells([(-1_000_000, 0), (-999_999, 0)])
    plan = Plan("robust", start, frozenset({(1_000_000, 0), (999_999, 0)}))
    bounds = pair_bounds(plan)
    assert bounds is not None and bounds.moves.value == 2 * 1_999_999
    assert bounds.bottleneck.value == 1_999_999 and bounds.time_steps.value >= 1_999_999


def test_a_byte_order_mark_is_read_past_in_grid_and_toml_files(capsys, tmp_path):
    grid, toml = tmp_path / "bom.txt", tmp_path / "bom.toml"
    grid.write_text("\ufeff1 1\n", encoding="utf-8")
    toml.write_text("\ufeffcells = [[0, 0], [1, 0]]\n", encoding="utf-8")
    code, out, err = run_plan(capsys, grid, toml)
    assert code == 0 and err == "" and "goal reached, 0 time step(s)" in out


def test_a_disconnected_configuration_gets_no_lower_bounds(capsys, tmp_path):
    apart = tmp_path / "apart.txt"
    apart.write_text("1 0 1\n0 0 0\n")
    two = tmp_path / "two.txt"
    two.write_text("1 1\n")
    for first, second in ((apart, two), (two, apart)):
        code, out, err = run_plan(capsys, first, second, "--summary")
        assert code == 1 and "lower bounds" not in out and "not connected" in err
        code, out, _ = run_plan(capsys, first, second, "--json", "--summary")
        assert code == 1 and "bounds" not in json.loads(out)
