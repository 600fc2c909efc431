"""Salvador's rules for walking over corks and openers (Chapter 5, Rules 6
and 7): under our reading of "occupied by a static module" (static, cork or
opener) Rules 2 and 3 already carry an active module over a cork, first."""

import pytest

from hexbot.planning.locomotion import Engine, World, load_ruleset
from hexbot.planning.locomotion.engine import Goal
from hexbot.planning.locomotion.rules import rotate

SALVADOR = load_ruleset("salvador")


def one_round(modules: dict, obstacles: list, turns: int):
    world = World([rotate(c, turns) for c in obstacles], [rotate(c, turns) for c in modules],
                  SALVADOR.states, module_states=list(modules.values()), extend_axis=None)
    result = Engine(SALVADOR, world, frame=turns).run(1, Goal())
    assert result.violation is None, result.violation
    after = {rotate(p, -turns): s for p, s in zip(result.positions, result.states, strict=True)}
    return after, result.rule_counts


FLOOR = [(x, 0) for x in range(-2, 7)]


@pytest.mark.parametrize("turns", [0, 1, 2, 3])
def test_an_active_module_slides_over_a_cork_by_rule_2(turns):
    cfg = {(0, 1): "static", (1, 1): "cork", (2, 1): "static", (3, 1): "static",
           (1, 2): "active"}
    after, rules = one_round(cfg, FLOOR, turns)
    assert after.get((2, 2)) == "active" and (1, 2) not in after
    assert after[(1, 1)] == "cork"  # a cork does not move under an active module
    assert "R2 Slide" in rules and "R6 Slide over a cork or opener" not in rules


@pytest.mark.parametrize("turns", [0, 1, 2, 3])
def test_a_cork_ahead_carries_a_slide_by_rule_2(turns):
    cfg = {(0, 1): "static", (1, 1): "cork", (0, 2): "active"}
    after, rules = one_round(cfg, FLOOR, turns)
    assert after.get((1, 2)) == "active" and (0, 2) not in after
    assert "R2 Slide" in rules


@pytest.mark.parametrize("turns", [0, 1, 2, 3])
def test_an_active_module_turns_round_a_cork_by_rule_3(turns):
    cfg = {(0, 1): "static", (1, 1): "cork", (1, 2): "active"}
    after, rules = one_round(cfg, FLOOR, turns)
    assert after.get((2, 1)) == "active" and (1, 2) not in after
    assert "R3 Convex transition" in rules
    assert "R7 Convex transition over a cork or opener" not in rules
