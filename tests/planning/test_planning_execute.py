"""Plans executed through the session layer on the real firmware: on the
embedded simulator's URL (verified by the plant) and on the ptys of a
simulator in another process (the hardware path: verified by localizing
again). Both must do the same moves and reach the same verdicts."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from hexbot.cli import main
from hexbot.errors import HexBotTimeoutError
from hexbot.host.host import IR, Host
from hexbot.host.link import PortSettings
from hexbot.host.session import Session
from hexbot.host.simproc import SimProcess
from hexbot.host.workflows import Verify
from hexbot.planning.configuration import Configuration, Module
from hexbot.planning.execute import execute
from hexbot.planning.moves import Move
from hexbot.planning.plan import Plan, Step

pytest.importorskip("hexbot.hil_sim._avr")

EXAMPLES = Path(__file__).resolve().parents[2] / "planning" / "examples"
FIRMWARE = Path(__file__).resolve().parents[2] / "firmware" / "build"
pytestmark = pytest.mark.skipif(not (FIRMWARE / "comm.elf").exists(),
                                reason="firmware not built (make -C firmware)")

# The pair rig: module 2 on side 1 of the base module 1; CW about its joint 4
# lands it on (0, 1) (scenario pair.toml, Table 3-1's example).
PAIR_INITIAL = "cells = [[0, 0], [-1, 1]]\n"
PAIR_GOAL = "cells = [[0, 0], [0, 1]]\n"


def _run_json(capsys, *argv) -> tuple[int, dict]:
    status = main(["plan", *argv, "--execute", "--json", "--no-log"])
    captured = capsys.readouterr()
    assert captured.out, captured.err
    return status, json.loads(captured.out)


def _moves(out: dict) -> list[tuple]:
    return [(m["module"], tuple(m["to"]), m["orientation"], m["ok"])
            for m in out["execution"]["moves"]]


def test_cli_executes_a_plan_on_thesis_fig5_8(capsys):
    status, out = _run_json(capsys, str(EXAMPLES / "test_all_p01_initial.txt"),
                            str(EXAMPLES / "block6_goal.txt"), "--scenario", "thesis-fig5-8")
    assert status == 0
    run = out["execution"]
    assert run["reached"] and run["localized"] == 6
    planned = [(m["module"], m["to"]) for s in out["steps"] for m in s["moves"]]
    assert [(m["module"], m["to"]) for m in run["moves"]] == planned
    # the plant agrees: every executed move ended where the plan put it
    assert all(m["ok"] and m["verified_by"] == "plant" for m in run["moves"])


def test_the_same_plan_on_a_pty_and_on_the_url_does_the_same(tmp_path, capsys):
    initial, goal = tmp_path / "initial.toml", tmp_path / "goal.toml"
    initial.write_text(PAIR_INITIAL)
    goal.write_text(PAIR_GOAL)
    status, on_url = _run_json(capsys, str(initial), str(goal), "--scenario", "pair")
    assert status == 0, on_url["execution"]["failure"]
    with SimProcess("pair", speed=0) as sim:  # another process: the hardware path
        _wait_booted(sim.ports.ir, {1, 2})
        status, on_pty = _run_json(capsys, str(initial), str(goal), "--port", sim.ports.ir,
                                   "--reference", "1")
    assert status == 0, on_pty["execution"]["failure"]
    assert _moves(on_pty) == _moves(on_url) == [(2, (0, 1), 2, True)]
    assert [m["verified_by"] for m in on_pty["execution"]["moves"]] == ["localize"]
    assert on_pty["execution"]["moves"][0]["got"] == {"to": [0, 1], "orientation": 2}


def _wait_booted(port: str, ids: set[int]) -> None:
    """As a user waits for the modules' boot texts before the first command."""
    with Host() as host:
        host.add_port(IR, PortSettings(port))
        host.start(5.0)
        assert Session(host).wait_booted(ids, timeout=30.0) == ids


def _fixed_base_plan() -> Plan:
    # Module 1 is fixed to the base: CW about its joint 1 (substrate module 2
    # on its side 1, goal on side 6, Table 4-3) must be refused by the plant.
    # Module 2 is the reference (the one that moves cannot be): it is (0, 0).
    initial = Configuration({(1, -1): Module(1, 0), (0, 0): Module(2, 0)})
    bad = Move(module=1, src=(1, -1), dst=(0, -1), joint=1, direction="CW",
               substrate=(0, 0), substrate_module=2)
    return Plan("robust", initial, frozenset({(0, -1), (0, 0)}), [Step([bad])], reached=True)


def test_execute_with_summary_reports_the_run_without_the_plans_steps(tmp_path, capsys):
    initial, goal = tmp_path / "initial.toml", tmp_path / "goal.toml"
    initial.write_text(PAIR_INITIAL)
    goal.write_text(PAIR_GOAL)
    status = main(["plan", str(initial), str(goal), "--scenario", "pair", "--execute",
                   "--summary", "--no-log"])
    lines = capsys.readouterr().out.splitlines()
    assert status == 0
    assert lines[0].startswith("mode robust") and "goal reached" in lines[0]
    assert not any(line.startswith("step 1:") or "CW(" in line for line in lines)
    assert any("module 2 moved at (0, 1)" in line for line in lines)
    assert lines[-1].startswith("executed 1/1 moves") and "goal reached (localized)" in lines[-1]


def test_a_plan_that_moves_the_base_is_refused_before_anything_is_sent(open_session):
    # the audit's case: a reference other than the base, and a plan moving
    # the base, ran its first moves and stopped half-way at the plant's refusal
    session = open_session("pair")
    report = execute(_fixed_base_plan(), session, reference=2)
    assert not report.reached and report.moves == [] and report.exit_status == 1
    assert "the plan moves module 1, bolted to the base in the scenario: nothing sent" in (
        report.failure)
    assert session.host.simulator.verdicts() == []  # no rotation reached the plant


def test_on_a_pty_the_refused_move_is_caught_by_localizing(open_session):
    with SimProcess("pair", speed=0) as sim:
        session = open_session(sim.ports.ir, boot=False)
        session.wait_booted({1, 2})
        report = execute(_fixed_base_plan(), session, reference=2, verify=Verify.LOCALIZE)
    assert not report.reached
    assert ("module 1 should be at (0, -1) facing 2 after CW about joint 1, "
            "localize check finds it at (1, -1) facing 0") in report.failure


def test_initial_must_match_the_cluster(tmp_path, capsys):
    other = tmp_path / "initial.txt"
    other.write_text("1 1\n")
    status = main(["plan", str(other), str(EXAMPLES / "block6_goal.txt"), "--execute",
                   "--scenario", "thesis-fig5-8", "--no-log"])
    assert status == 1
    assert "does not describe scenario thesis-fig5-8" in capsys.readouterr().err


def test_a_plan_request_reads_its_goal_and_options_or_says_what_is_wrong(tmp_path):
    import re

    from hexbot.errors import ScenarioError
    from hexbot.planning.execute import plan_request

    (tmp_path / "g.toml").write_text(PAIR_GOAL)
    request = plan_request(["g.toml", "verify", "Localize", "reference", "2"], tmp_path)
    assert request.goal == frozenset({(0, 0), (0, 1)})
    assert (request.reference, request.verify) == (2, Verify.LOCALIZE)
    assert plan_request([str(tmp_path / "g.toml")]).reference is None
    for words, problem in ((["g.toml", "reference"], "expected GOAL [reference ID]"),
                           (["g.toml", "speed", "2"], "unexpected 'speed'"),
                           (["g.toml", "reference", "two"], "reference must be a module id"),
                           (["g.toml", "verify", "maybe"], "verify must be one of"),
                           (["missing.toml"], "missing.toml")):
        with pytest.raises(ScenarioError, match=re.escape(problem)):
            plan_request(words, tmp_path)


@pytest.mark.parametrize("extra, words", [
    (["--style", "single"], "--style single only prints"),
    (["--reference", "0"], "--reference: the reference must be a module id 1..63, got 0"),
    (["--port", "/dev/null", "--verify", "plant"], "--verify plant needs the embedded simulator"),
])
def test_execute_usage_errors_come_before_the_port_opens(tmp_path, cli_status, extra, words):
    initial, goal = tmp_path / "initial.toml", tmp_path / "goal.toml"
    initial.write_text(PAIR_INITIAL)
    goal.write_text(PAIR_GOAL)
    scenario = [] if "--port" in extra else ["--scenario", "pair"]
    code, err = cli_status("plan", initial, goal, "--execute", "--no-log", *scenario, *extra)
    assert code == 2 and words in err


def test_a_faithful_plan_that_moves_the_reference_sends_no_move(capsys):
    # the thesis planner moves module 1 at (0, 0), the base: two real moves
    # used to run before the plant refused the third
    status = main(["plan", str(EXAMPLES / "test_all_p01_initial.txt"),
                   str(EXAMPLES / "test_all_p01_goal.txt"), "--execute", "--scenario",
                   "thesis-fig5-8", "--no-log", "--mode", "faithful-serial"])
    out, err = capsys.readouterr()
    assert status == 1
    assert "the plan moves module 1, the reference of the localization: nothing sent" in err
    assert "executing through" not in out


def test_execute_json_without_a_plan_is_still_json(tmp_path, capsys):
    initial, goal = tmp_path / "initial.toml", tmp_path / "goal.toml"
    initial.write_text(PAIR_INITIAL)
    goal.write_text("cells = [[0, 0], [5, 5]]\n")  # not connected: no plan
    status, out = _run_json(capsys, str(initial), str(goal), "--scenario", "pair")
    assert status == 1 and out["reached"] is False and out["execution"] is None


def test_a_module_table_must_name_the_modules_as_localized(tmp_path, capsys):
    initial, goal = tmp_path / "initial.toml", tmp_path / "goal.toml"
    initial.write_text("[[module]]\nid = 7\ncell = [0, 0]\n[[module]]\nid = 9\ncell = [-1, 1]\n")
    goal.write_text(PAIR_GOAL)
    status = main(["plan", str(initial), str(goal), "--execute", "--scenario", "pair",
                   "--no-log"])
    assert status == 1
    assert "module 9 at (-1, 1), localized module 2 there" in capsys.readouterr().err


def test_verify_status_assumes_the_planned_place_for_the_next_moves(tmp_path, capsys):
    # module 2 moves twice: the second move needs its place after the first,
    # which a status check cannot see (it used to refuse: "stale")
    initial, goal = tmp_path / "initial.toml", tmp_path / "goal.toml"
    initial.write_text(PAIR_INITIAL)
    goal.write_text("cells = [[0, 0], [1, 0]]\n")
    status, out = _run_json(capsys, str(initial), str(goal), "--scenario", "pair",
                            "--verify", "status")
    run = out["execution"]
    assert status == 0 and run["reached"] and len(run["moves"]) >= 2
    assert all(m["verified_by"] == "status" for m in run["moves"])


def _move_2_on_1() -> Plan:
    """The pair rig's one-move plan: module 2 CW about joint 4 onto (0, 1)."""
    initial = Configuration({(0, 0): Module(1, 0), (-1, 1): Module(2, 0)})
    move = Move(module=2, src=(-1, 1), dst=(0, 1), joint=4, direction="CW",
                substrate=(0, 0), substrate_module=1)
    return Plan("robust", initial, frozenset({(0, 0), (0, 1)}), [Step([move])], reached=True)


@pytest.mark.parametrize("error, status, failure", [
    (lambda: HexBotTimeoutError("CW (67): no reply from modules 1, 2 within 4.9 s"), 3,
     "CW (67): no reply"),
    (lambda: KeyboardInterrupt(), 130, "interrupted (Ctrl-C)"),
])
def test_what_stops_a_run_gives_its_exit_status_and_the_moves_done(open_session, monkeypatch,
                                                                    error, status, failure):
    # a port lost (4) or a time-out (3) mid-run was reported as exit 1, and
    # Ctrl-C left no line saying how far the run got
    from hexbot.host import workflows

    def stopped(*_args, **_kwargs):
        raise error()

    session = open_session("pair")
    monkeypatch.setattr(workflows, "rotate", stopped)
    report = execute(_move_2_on_1(), session, reference=1)
    assert report.exit_status == status and failure in report.failure
    assert report.line(1) == f"executed 0/1 moves in {report.seconds:.1f} s; stopped early"


def test_a_goal_in_pieces_is_refused_before_anything_is_sent(tmp_path):
    from hexbot.errors import ScenarioError
    from hexbot.planning.execute import plan_request

    goal = tmp_path / "apart.toml"
    goal.write_text("cells = [[0, 0], [5, 5]]\n")
    with pytest.raises(ScenarioError, match="the goal is not connected"):
        plan_request([str(goal)])





@pytest.mark.parametrize("status", [3, 4, 130])
def test_a_reports_outcome_keeps_the_exit_status_of_what_stopped_it(status):
    # a script's plan step raises outcome(): its exit status was always 1
    from hexbot.errors import CancelledError, HexBotError
    from hexbot.planning.execute import ExecutionReport

    report = ExecutionReport(failure="stopped", exit_status=status)
    with pytest.raises(HexBotError) as info:
        report.outcome(5)
    assert info.value.exit_status == status
    assert isinstance(info.value, CancelledError) == (status == 130)


def test_plot_and_render_draw_the_executed_plan(tmp_path, capsys):
    """--plot and --render were ignored with --execute (exit 0, no file)."""
    initial, goal = tmp_path / "initial.toml", tmp_path / "goal.toml"
    initial.write_text(PAIR_INITIAL)
    goal.write_text(PAIR_GOAL)
    png, gif = tmp_path / "plan.png", tmp_path / "plan.gif"
    status, out = _run_json(capsys, str(initial), str(goal), "--scenario", "pair",
                            "--plot", str(png), "--render", str(gif))
    assert status == 0 and out["execution"]["reached"]
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert gif.read_bytes()[:6] == b"GIF89a"


def test_a_plan_whose_status_checked_move_did_not_happen_does_not_reach_its_goal(
        open_session):
    # The hardware path, verify status: the base module is bolted down, so
    # the plant refuses the move, the firmware still acknowledges it and says
    # "unlocalized": only the final localization can tell.
    from hexbot.errors import HexBotError

    initial = Configuration({(1, -1): Module(1, 0), (0, 0): Module(2, 0)})
    move = Move(module=1, src=(1, -1), dst=(0, -1), joint=1, direction="CW",
                substrate=(0, 0), substrate_module=2)
    plan = Plan("robust", initial, frozenset({(0, -1), (0, 0)}), [Step([move])], reached=True)
    with SimProcess("pair", speed=0) as sim:
        session = open_session(sim.ports.ir, boot=False)
        session.wait_booted({1, 2})
        report = execute(plan, session, reference=2, verify=Verify.STATUS)
    assert report.finished and not report.reached and report.exit_status == 1
    assert "is not the goal" in report.failure
    with pytest.raises(HexBotError, match="is not the goal"):
        report.outcome(1)
