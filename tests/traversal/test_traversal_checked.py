"""The rounds of ``hexbot traverse --motion hexbot`` replayed by the independent
plan checker (Table 4-3 geometry, no two moves of a step needing one cell,
connectivity): what the engine reports as reached, rigid modules can do."""

from __future__ import annotations

import pytest

from hexbot.errors import ScenarioError
from hexbot.planning.checker import check_plan
from hexbot.planning.moves import Move
from hexbot.planning.schedule import cells_of
from hexbot.planning.traversal.bank import MAPS
from hexbot.planning.traversal.bridges import find_bridge_cells
from hexbot.planning.traversal.cli import resolve_map
from hexbot.planning.traversal.engine import traverse
from hexbot.planning.traversal.execute import Cluster, rounds_plan
from hexbot.planning.traversal.motion import body_cells
from hexbot.protocol.rotation_geometry import ROTATIONS

BANK = sorted(p.stem for p in MAPS.glob("*.txt"))
REFUSED = {"fig14", "steps"}  # docs/traversal.md, "Still refused"
SEEDS = [f"random:{seed}" for seed in (0, 1, 3, 5, 7, 9, 10, 24, 98)]
#: random:0..199 whose rigid modules crossed in one cell (status "violation")
#: until modules whose ways fold back held back their start (docs/traversal.md)
FOLDED = (1, 3, 51, 54, 62, 72, 98, 111, 116, 123, 129, 133, 140, 142, 145, 161, 173)


def checked(name: str):
    """The run of ``name`` under the hexbot model and the checker's report on its
    rounds, every map module a module (ids as ``--execute``, without its size
    limit: only the plan is checked)."""
    surface = resolve_map(name)
    ids = {cell: surface.n + k for k, cell in enumerate(sorted(surface.surface), start=1)}
    result = traverse(find_bridge_cells(surface, "hexbot"))
    plan = rounds_plan(Cluster(surface, ids, min(ids.values())), result)
    return result, check_plan(plan.initial, plan.goal, plan.steps)


@pytest.mark.parametrize("name", [n for n in BANK if n not in REFUSED])
def test_every_shipped_map_is_reached_in_rounds_the_checker_accepts(name):
    result, report = checked(name)
    assert result.status == "reached", result.reason
    assert report.ok, report.problem
    assert report.moves == result.moves


@pytest.mark.parametrize("name", SEEDS)
def test_random_surfaces_move_only_as_the_checker_accepts(name):
    # reached or not, every round the engine let through is legal for rigid modules
    try:
        result, report = checked(name)
    except ScenarioError:  # refused under the hexbot model: nothing moves
        return
    assert report.ok, f"{name} ({result.status}): {report.problem}"


@pytest.mark.parametrize("seed", FOLDED)
def test_random_surfaces_whose_ways_fold_back_are_reached_in_rounds_the_checker_accepts(seed):
    result, report = checked(f"random:{seed}")
    assert result.status == "reached", result.reason
    assert any(result.holds)  # a module held back its start
    assert report.ok, report.problem
    assert report.moves == result.moves


def test_a_rigid_module_sweeps_the_cells_the_schedule_says_a_move_needs():
    # the engine's conflict rule and the checker's/schedule's are one notion
    for rotation in ROTATIONS:
        _sub, goal, _swept = rotation.at((3, 4))
        move = Move(1, (3, 4), goal, rotation.joint, rotation.direction, _sub, 2)
        assert set(body_cells(rotation, (3, 4), "hexbot")) == set(cells_of(move))
