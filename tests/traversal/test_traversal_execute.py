"""hexbot traverse MAP --execute: the rounds run on the embedded simulator
(real firmware on simavr) through the session layer and the rotation
workflow of plan --execute, each move verified by the plant."""

from __future__ import annotations

import json

import pytest

from hexbot.cli import main
from hexbot.errors import ScenarioError
from hexbot.planning.traversal.bridges import find_bridge_cells
from hexbot.planning.traversal.cli import resolve_map
from hexbot.planning.traversal.engine import traverse
from hexbot.planning.traversal.execute import cluster_of, rounds_plan


def test_the_rounds_become_a_plan_over_surface_and_movers():
    cluster = cluster_of(resolve_map("hil-basic-2"))
    result = traverse(find_bridge_cells(cluster.surface, "hexbot"))
    plan = rounds_plan(cluster, result)
    assert len(plan.initial) == 3 + len(cluster.surface.surface)
    assert plan.initial.cell_of(cluster.reference) == (0, 0)
    assert plan.move_count == result.moves and plan.final.cells == plan.goal
    surface_ids = set(cluster.ids.values())
    assert all(m.module <= 3 for s in plan.steps for m in s.moves)  # the surface never moves
    assert {m.substrate_module for s in plan.steps for m in s.moves} & surface_ids


def test_a_map_too_big_for_legacy_select_is_refused():
    with pytest.raises(ScenarioError, match="at most 63"):
        cluster_of(resolve_map("flat"))


@pytest.mark.parametrize(("name", "modules", "fills"),
                         [("hil-flat", 10, 0),  # 2 movers on 8 surface modules
                          ("hil-basic-2", 29, 2),  # the paper's 2-cell BASIC bridge
                          ("hil-three", 33, 3)])  # the paper's straight 3-bridge
def test_maps_are_crossed_on_the_simulator(capsys, name, modules, fills):
    status = main(["traverse", name, "--execute", "--json", "--no-log"])
    out = json.loads(capsys.readouterr().out)
    assert status == 0, out["execution"]["failure"]
    run = out["execution"]
    # deeper than the 4 hops of one Localize wave for the pockets: all localized
    assert run["reached"] and run["localized"] == modules
    assert sum(len(b["cells"]) for b in out["bridges"] if b["kind"] == "FILL") == fills
    planned = [(m["module"], m["to"]) for r in out["rounds"] for m in r["moves"]]
    assert [(m["module"], m["to"]) for m in run["moves"]] == planned
    assert all(m["ok"] and m["verified_by"] == "plant" for m in run["moves"])


def test_a_refused_move_stops_with_one_line(tmp_path, capsys):
    # the same cluster, but mover 1 fixed to the base: refused before any move
    from hexbot.planning.traversal.execute import scenario_toml

    cluster = cluster_of(resolve_map("hil-flat"))
    result = traverse(find_bridge_cells(cluster.surface, "hexbot"))
    text = scenario_toml(cluster, result.initial).replace(f"base = {cluster.reference}",
                                                          "base = 1")
    scenario = tmp_path / "fixed.toml"
    scenario.write_text(text)
    status = main(["traverse", "hil-flat", "--execute", "--scenario", str(scenario),
                   "--no-log"])
    err = capsys.readouterr().err.strip().splitlines()[-1]
    assert status == 1
    assert err.startswith("hexbot traverse: execution stopped: the plan moves module 1, "
                          "bolted to the base in the scenario: nothing sent")


def test_a_cluster_that_is_not_the_maps_start_sends_no_move(tmp_path, capsys):
    # execute()'s own check is the only one on this path: module 1 turned
    # by half a turn localizes elsewhere than the map says
    from hexbot.planning.traversal.execute import scenario_toml

    cluster = cluster_of(resolve_map("hil-flat"))
    result = traverse(find_bridge_cells(cluster.surface, "hexbot"))
    text = scenario_toml(cluster, result.initial)
    turned = text.replace("id = 1\nposition = [-2, 1]\n",
                          "id = 1\nposition = [-2, 1]\norientation = 3\n")
    assert turned != text
    scenario = tmp_path / "turned.toml"
    scenario.write_text(turned)
    status = main(["traverse", "hil-flat", "--execute", "--scenario", str(scenario),
                   "--no-log"])
    err = capsys.readouterr().err
    assert status == 1, err
    assert "does not start from the cluster as localized" in err, err
