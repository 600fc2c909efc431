"""Otero's rules, our reconstructions for closed holes (tags in otero.rules):
each fires where it should, in every orientation, and each fixes a bank run
that deadlocks without it."""

import pytest

from hexbot.planning.locomotion import Engine, World, load_scenario, loads, simulate
from hexbot.planning.locomotion.engine import Goal
from hexbot.planning.locomotion.rules import rotate
from hexbot.planning.locomotion.scenarios import _data

TEXT = _data("rulesets", ".rules")["otero"].read_text()
OTERO = loads(TEXT)


def _without_rule(text: str, name: str) -> str:
    """otero.rules without the rule NAME (its block, up to the next blank line)."""
    out, skip = [], False
    for line in text.splitlines():
        if line.startswith(f"rule {name} "):
            skip = True
        elif skip and not line.strip():
            skip = False
        if not skip:
            out.append(line)
    assert len(out) < len(text.splitlines())
    return "\n".join(out)


def run(rules, modules: dict, obstacles=(), rounds=1, turns=0):
    """``rounds`` rounds on a hand-made configuration turned by ``turns``
    quarter turns; returns {turned-back cell: state}."""
    world = World([rotate(c, turns) for c in obstacles], [rotate(c, turns) for c in modules],
                  rules.states, module_states=list(modules.values()), extend_axis=None)
    result = Engine(rules, world).run(rounds, Goal())
    assert result.violation is None, result.violation
    return {rotate(p, -turns): s for p, s in zip(result.positions, result.states, strict=True)}


ALL_TURNS = pytest.mark.parametrize("turns", [0, 1, 2, 3])

# The tail of wide-cavity-right (n = 50): a pivot bridges an empty cell closed
# by the floor and two static modules; the tail module west of it cannot move.
#   # s P s .
#   # s . s s
#   # # # # #
BRIDGE = {(0, 0): "PIVOT", (-1, 0): "STOPA", (1, 0): "STOPA", (-1, -1): "STOPA",
          (1, -1): "STOPA", (2, -1): "STOPA"}
FLOOR = [(-2, 0), (-2, -1), (-2, -2), (-1, -2), (0, -2), (1, -2), (2, -2)]


@ALL_TURNS
def test_a_pivot_over_a_closed_hole_drops_into_it(turns):
    after = run(OTERO, BRIDGE, FLOOR, turns=turns)
    assert after.get((0, -1)) == "ACTIV" and (0, 0) not in after


def test_a_hole_open_below_is_no_wall_deadlock():
    after = run(OTERO, BRIDGE, [c for c in FLOOR if c != (0, -2)])
    assert after.get((0, 0)) == "PIVOT"


def test_without_the_hole_rule_the_bridge_stays():
    after = run(loads(_without_rule(TEXT, "U5")), BRIDGE, FLOOR)
    assert after.get((0, 0)) == "PIVOT"


def test_the_hole_rule_brings_wide_cavity_right_n50_home():
    # HOLE: without U5 the tail of the robot is left as a U round a closed
    # hole at the far end of the cavity and the run deadlocks (round 380).
    ours = simulate(OTERO, load_scenario("wide-cavity-right", 50), rounds=3000)
    assert ours.status == "reached", ours.violation or ours.deadlock
    old = simulate(loads(_without_rule(TEXT, "U5")), load_scenario("wide-cavity-right", 50),
                   rounds=3000)
    assert old.status == "deadlock" and old.violation is None
