"""A script names the scenario it was written for; `hexbot run` uses it."""

import re
from pathlib import Path

import pytest

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


def test_values_that_would_pass_vacuously_or_crash_fail_the_check(tmp_path, cli_status):
    # (audit) 'within abc' passed --check and crashed the run with a green
    # JUnit file; 'count 0' and negative times passed whatever arrived
    lines = ["expect ack Select within abc", "expect text ERROR count 0",
             "expect placements -1 within 5", "expect ack Select within -1",
             "expect quiet 0", "expect text X within 0"]
    script = tmp_path / "bad.hbs"
    script.write_text("\n".join(lines) + "\n")
    code, err = cli_status("run", script, "--check")
    assert code == 1
    for number in range(1, len(lines) + 1):
        assert f"bad.hbs:{number}:" in err, (number, err)


def test_a_command_no_module_answers_is_a_time_out_exit_3(tmp_path, log_dir, cli_status):
    script = tmp_path / "nine.hbs"
    script.write_text("select 9\n")
    code, err = cli_status("run", script, "--scenario", "pair")
    assert code == 3 and "no reply from module 9" in err


def test_a_module_that_never_boots_is_named_before_the_steps(tmp_path, log_dir, cli_status):
    # (audit) "1 of 2 modules booted" and "all steps passed" read as a pass
    # of the whole cluster; the run now names the silent module (no boot
    # text, no answer to a Status). It is not a failure: a run may need only
    # part of the cluster
    firmware = Path(__file__).resolve().parents[2] / "firmware" / "build"
    scenario = tmp_path / "deadcomm.toml"
    scenario.write_text(
        'name = "deadcomm"\nbase = 1\n[[module]]\nid = 1\nposition = [0, 0]\n'
        '[[module]]\nid = 2\nposition = [-1, 1]\n'
        f'firmware = {{ comm = "{firmware / "rf12.elf"}" }}\n')
    script = tmp_path / "s.hbs"
    script.write_text("select 1\nselect 2\n")
    code, err = cli_status("run", script, "--scenario", scenario)
    assert "warning: module(s) 2: no COMM. LISTENING text of theirs heard whole and no " \
           "answer to a Status" in err
    assert code == 3 and "s.hbs:2: select 2" in err  # a step to it fails


_RIG = 'name = "{name}"\nbase = {ident}\n[[module]]\nid = {ident}\nposition = [0, 0]\n'


def test_a_scenario_pragma_names_a_file_beside_the_script(tmp_path):
    (tmp_path / "rig.toml").write_text(_RIG.format(name="rig", ident=1))
    script = tmp_path / "s.hbs"
    script.write_text("# scenario: rig.toml\nselect 1\n")
    assert declared_scenario(script) == str(tmp_path / "rig.toml")


def test_a_scenario_file_is_the_scripts_neighbour_not_the_current_folders(
        tmp_path, monkeypatch, log_dir, cli_status):
    # (fuzz, session 37) with a rig.toml in the current folder and none
    # beside the script, the current folder's was run: another cluster,
    # silently. Now the script's folder decides, in the check and the run
    scripts, elsewhere = tmp_path / "scripts", tmp_path / "cwd"
    scripts.mkdir()
    elsewhere.mkdir()
    (elsewhere / "rig.toml").write_text(_RIG.format(name="wrong", ident=3))
    (scripts / "sub").mkdir()
    (scripts / "sub" / "rig.toml").write_text(_RIG.format(name="right", ident=2))
    monkeypatch.chdir(elsewhere)
    script = scripts / "s.hbs"
    script.write_text("# scenario: rig.toml\nselect 1\n")
    code, err = cli_status("run", script, "--check")
    assert code == 1
    assert f"s.hbs:1: scenario: {scripts / 'rig.toml'}: no such scenario file" in err
    code, err = cli_status("run", script, "--no-log")
    assert code == 1 and f"{scripts / 'rig.toml'}: no such scenario file" in err
    assert "booted" not in err  # refused before the simulator started

    script.write_text("# scenario: sub/rig.toml\nselect 2\n")  # a folder in it: a file too
    code, err = cli_status("run", script, "--no-log")
    assert code == 0, err
    assert f"simulator: {scripts / 'sub' / 'rig.toml'}, 1 of 1 modules booted" in err


@pytest.mark.parametrize("pragma, problem", [
    ("nosuchscenario", "scenario: unknown scenario 'nosuchscenario': built-in ones are "),
    ("nosuch.toml", "nosuch.toml: no such scenario file"),
    ("bad.toml", "bad.toml:1: a scenario needs at least one [[module]] table"),
])
def test_the_check_refuses_a_scenario_line_that_names_nothing_loadable(tmp_path, cli_status,
                                                                       pragma, problem):
    (tmp_path / "bad.toml").write_text("name = 'bad'\n")
    script = tmp_path / "s.hbs"
    script.write_text(f"echo hi\n# scenario: {pragma}\nselect 1\n")
    code, err = cli_status("run", script, "--check")
    assert code == 1
    assert "s.hbs:2: scenario: " in err and problem in err, err


def test_a_lost_port_is_no_quiet_and_ctrl_c_is_no_pass(log_dir, monkeypatch):
    import argparse

    import pytest

    from hexbot.errors import LinkUnavailableError
    from hexbot.host import script as script_module
    from hexbot.host.cli_common import session
    from hexbot.host.endpoints import add_port_arguments
    from hexbot.host.script import ScriptRunner, StepStatus, parse_script
    parser = argparse.ArgumentParser()
    add_port_arguments(parser)
    args = parser.parse_args(["--scenario", "pair", "--no-log"])
    with session(args) as sess:
        runner = ScriptRunner(sess, "q.hbs", out=lambda _line: None)
        monkeypatch.setattr(sess, "port_lost", lambda: "read failed")  # the port died
        with pytest.raises(LinkUnavailableError, match="port lost"):
            runner.run(parse_script("expect quiet 15\n", "q.hbs"))
        monkeypatch.undo()

        runner = ScriptRunner(sess, "c.hbs", out=lambda _line: None)
        real = script_module.ScriptRunner._step

        def interrupted(self, step):
            if step.line == 2:
                raise KeyboardInterrupt
            return real(self, step)

        monkeypatch.setattr(script_module.ScriptRunner, "_step", interrupted)
        with pytest.raises(KeyboardInterrupt):
            runner.run(parse_script("echo one\necho two\necho three\n", "c.hbs"))
    assert [r.status for r in runner.results] == [StepStatus.PASSED, StepStatus.ERROR,
                                                  StepStatus.NOT_RUN]


def test_two_runs_of_a_seed_write_the_same_capture(tmp_path, monkeypatch):
    # (audit) the port's "connected" line carried wall-clock time (0.007 s,
    # 0.014 s, ...): the captures of one seed differed between runs
    from hexbot.cli import main

    captures = []
    for run in range(2):
        folder = tmp_path / f"run{run}"
        assert main(["run", str(EXAMPLES / "actuators_smoke.hbs"), "--seed", "4",
                     "--log-dir", str(folder)]) == 0
        (capture,) = folder.rglob("capture.hbcap")
        # (@N: the simulator's number within this process, 1 in a fresh one)
        captures.append([re.sub(r"hexbot-sim://@\d+", "hexbot-sim://@", line)
                         for line in capture.read_text().splitlines()
                         if not line.startswith("#")])
    assert captures[0] == captures[1]
    # before the simulator's clock runs its time is 0: the "connecting" line
    # carried a wall-clock 0.001 s now and then (a fresh-clone run failed on it)
    assert [line.split()[0] for line in captures[0] if " state " in line][:1] == ["0.000"]


def test_a_bad_role_in_expect_status_is_named(tmp_path, cli_status):
    script = tmp_path / "r.hbs"
    script.write_text("expect status 2 role m\n")
    code, err = cli_status("run", script, "--check")
    assert code == 1 and "r.hbs:1: role must be M, S or -, got 'm'" in err


def test_a_file_named_like_a_built_in_scenario_does_not_replace_it(
        tmp_path, monkeypatch, log_dir, cli_status):
    """(fuzz, session 37) `--scenario pair` and `# scenario: pair` ran a file
    `pair` of the current folder. A value is a file only when it ends in
    .toml or holds a path separator (hil_sim.scenario.is_scenario_file)."""
    (tmp_path / "pair").write_text(_RIG.format(name="wrong", ident=3))
    monkeypatch.chdir(tmp_path)
    script = tmp_path / "s.hbs"
    script.write_text("# scenario: pair\nselect 2\n")
    for option in ([], ["--scenario", "pair"]):
        code, err = cli_status("run", script, "--no-log", *option)
        assert code == 0, err
        assert "simulator: pair, 2 of 2 modules booted" in err
    code, err = cli_status("run", script, "--no-log", "--scenario", "./pair")  # the file
    assert code == 3 and "1 of 1 modules booted" in err
    assert f"hexbot-sim://{tmp_path / 'pair'}?" in err
