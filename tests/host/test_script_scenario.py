"""A script names the scenario it was written for; `hexbot run` uses it."""

from pathlib import Path

from hexbot.host.cli_run import declared_scenario

EXAMPLES = Path(__file__).resolve().parents[2] / "docs" / "examples"


def test_examples_declare_their_scenarios():
    assert declared_scenario(EXAMPLES / "pair_rotate.hbs") == "pair"
    assert declared_scenario(EXAMPLES / "flower7_localize.hbs") == "flower7"


def test_no_pragma_means_no_scenario(tmp_path):
    script = tmp_path / "s.hbs"
    script.write_text("# just a comment: scenario pair is not a pragma\nselect 1\n")
    assert declared_scenario(script) is None


def test_a_rotation_the_plant_refuses_fails_with_its_reason(tmp_path, log_dir, capsys):
    from hexbot.cli import main

    # Module 2 is the reference; module 1 is bolted to the base: the plant
    # refuses to turn it, and the CLI says so and exits 1, never "ok".
    script = tmp_path / "refused.hbs"
    script.write_text("select 2\nRef\nselect 0\nLocalize\nstatus\n"
                      "rotate cw 1 mobile 1 substrate 2\n")
    assert main(["run", str(script), "--scenario", "pair"]) == 1
    err = capsys.readouterr().err
    assert "refused.hbs:6: rotate cw 1 mobile 1 substrate 2: the plant refused: " \
           "module 1 fixed to base" in err
    assert "5 of 6 steps passed" in err


def test_the_shipped_rotation_script_passes_on_its_scenario(log_dir, capsys):
    from hexbot.cli import main

    assert main(["run", str(EXAMPLES / "pair_rotate.hbs")]) == 0, capsys.readouterr().err


def test_the_shipped_plan_script_plans_executes_and_verifies(log_dir, capsys):
    from hexbot.cli import main

    assert declared_scenario(EXAMPLES / "pair_plan.hbs") == "pair"
    assert main(["run", str(EXAMPLES / "pair_plan.hbs")]) == 0, capsys.readouterr().err
    out = capsys.readouterr().out
    assert "mode robust (direct): goal reached, 1 time step(s), 1 move(s)" in out
    assert "module 2 moved at (0, 1) facing 2 (verified by plant)" in out
    assert "ok    plan pair_goal.toml reference 1  -> goal reached (localized): 1 of 1 moves" in out


def test_a_plan_step_fails_with_the_planners_reason_and_sends_no_rotation(tmp_path, log_dir,
                                                                          capsys):
    from hexbot.cli import main

    (tmp_path / "three.toml").write_text("cells = [[0, 0], [0, 1], [1, 0]]\n")
    script = tmp_path / "p.hbs"
    script.write_text("plan three.toml\n")  # relative to the script
    assert main(["run", str(script), "--scenario", "pair"]) == 1
    captured = capsys.readouterr()
    assert "p.hbs:1: plan three.toml: no plan: the initial configuration has 2 modules, " \
           "the goal 3 cells" in captured.err
    assert "CW(" not in captured.out


def test_a_plan_step_whose_goal_cannot_be_read_fails_the_check(tmp_path, capsys):
    from hexbot.cli import main

    script = tmp_path / "p.hbs"
    script.write_text("select 0\nplan nowhere.toml\nplan goal.txt verify sideways\n")
    (tmp_path / "goal.txt").write_text("1 1\n")
    assert main(["run", str(script), "--check"]) == 1
    err = capsys.readouterr().err
    assert "p.hbs:2: " in err and "nowhere.toml" in err
    assert "p.hbs:3: verify must be one of auto, plant, localize, status" in err
