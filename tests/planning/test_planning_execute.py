"""Plans executed on the simulated cluster (real firmware on the simulator):
localization from the PC, then the plan's commands, checked move by move
against the plant."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from hexbot.cli import main
from hexbot.planning.execute import configuration_of, execute
from hexbot.planning.moves import Move
from hexbot.planning.plan import Plan, Step

pytest.importorskip("hexbot.hil_sim._avr")
from hexbot.hil_sim import Simulator, load_scenario  # noqa: E402

EXAMPLES = Path(__file__).resolve().parents[2] / "planning" / "examples"
FIRMWARE = Path(__file__).resolve().parents[2] / "firmware" / "build"
pytestmark = pytest.mark.skipif(not (FIRMWARE / "comm.elf").exists(),
                                reason="firmware not built (make -C firmware)")


def test_cli_executes_a_plan_on_thesis_fig5_8(capsys):
    status = main(["plan", str(EXAMPLES / "test_all_p01_initial.txt"),
                   str(EXAMPLES / "block6_goal.txt"), "--execute",
                   "--scenario", "thesis-fig5-8", "--json"])
    out = json.loads(capsys.readouterr().out)
    assert status == 0
    run = out["execution"]
    assert run["reached"] and run["localized"] == 6
    planned = [(m["module"], m["to"]) for s in out["steps"] for m in s["moves"]]
    executed = [(m["module"], m["to"]) for m in run["moves"]]
    assert executed == planned and all(m["ok"] for m in run["moves"])
    # The plant agrees: every executed move ended where the plan put it.
    assert all(m["plant"]["event"] == "moved" for m in run["moves"])


def test_divergence_stops_with_a_report():
    # Module 1 is fixed to the base in the pair scenario: a plan that rotates
    # it must stop at that move, with the plant's reason.
    sim = Simulator(load_scenario("pair"), seed=1)
    sim.run(24.0)  # every module booted (boot-text slots, docs/firmware.md)
    initial = configuration_of(sim)
    # CW about joint 1: substrate on side 1 (module 2), goal on side 6 (Table 4-3).
    bad = Move(module=1, src=(0, 0), dst=(-1, 0), joint=1, direction="CW",
               substrate=(-1, 1), substrate_module=2)
    plan = Plan("robust", initial, frozenset({(-1, 0), (-1, 1)}), [Step([bad])], reached=True)
    report = execute(plan, sim)
    assert not report.reached
    assert "step 1: module 1" in report.failure
    assert "refused (fixed to base)" in report.failure
    assert len(report.moves) == 1 and not report.moves[0].ok


def test_initial_must_match_the_scenario(tmp_path, capsys):
    other = tmp_path / "initial.txt"
    other.write_text("1 1\n")
    status = main(["plan", str(other), str(EXAMPLES / "block6_goal.txt"), "--execute",
                   "--scenario", "thesis-fig5-8"])
    assert status == 1
    assert "does not describe scenario thesis-fig5-8" in capsys.readouterr().err
