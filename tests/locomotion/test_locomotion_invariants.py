"""Every round is checked: collisions, unsupported moves, disconnection, deadlock."""

from hexbot.planning.locomotion import Engine, World, loads
from hexbot.planning.locomotion.engine import Goal

FLOOR = [(x, -1) for x in range(-3, 8)]


def run(rules: str, modules, states, support="module", rounds=5):
    text = f"ruleset t\nstates a b c\nresting b\nsupport {support}\nsymmetry none\n" + rules
    rs = loads(text)
    world = World(FLOOR, modules, rs.states, module_states=states)
    return Engine(rs, world).run(rounds, Goal())


def test_two_modules_entering_one_cell_is_a_collision():
    rules = (
        "rule L\n priority 5\n state a\n require E is module and NE is empty\n move NE\n"
        "rule R\n priority 5\n state c\n require W is module and NW is empty\n move NW\n"
    )
    res = run(rules, [(0, 0), (1, 0), (2, 0)], ["a", "b", "c"])
    assert res.status == "violation"
    v = res.violation
    assert v.kind == "collision" and v.round == 1
    assert (1, 1) in v.cells
    assert any(r.startswith("L") for r in v.rules) and any(r.startswith("R") for r in v.rules)


def test_moving_into_a_module_or_an_obstacle_is_refused():
    into_module = run("rule M\n priority 1\n state a\n move E\n", [(0, 0), (1, 0)], ["a", "b"])
    assert into_module.violation.kind == "target-occupied"
    into_floor = run("rule M\n priority 1\n state a\n move S\n", [(0, 0), (1, 0)], ["a", "b"])
    assert into_floor.violation.kind == "inside-obstacle"
    assert into_floor.violation.cells == [(0, -1), (0, 0)]


def test_slide_without_carrier_is_unsupported():
    # Sliding east along the floor: the floor is an obstacle, and this rule set
    # lets only modules carry a slide.
    res = run("rule M\n priority 1\n state a\n move E\n", [(0, 0), (-1, 0)], ["a", "b"])
    assert res.violation.kind == "unsupported-move"


def test_the_carrier_must_stay_put():
    rules = "rule M\n priority 1\n state a\n move N\n"
    # (0,0) slides north along (1,0)-(1,1), but (1,1) itself moves north too.
    res = run(rules, [(0, 0), (1, 0), (1, 1)], ["a", "b", "a"], support="module obstacle")
    assert res.violation.kind == "unsupported-move"


def test_move_that_splits_the_robot_is_reported():
    rules = "rule M\n priority 1\n state a\n move E\n"
    res = run(rules, [(0, 0), (1, 0)], ["b", "a"], support="module obstacle")
    assert res.violation.kind == "disconnected"
    assert res.violation.round == 1
    assert res.violation.cells == [(0, 0)] or res.violation.cells == [(2, 0)]


def test_same_move_that_keeps_contact_is_fine():
    rules = "rule M\n priority 1\n state a\n require W is module\n move E\n"
    res = run(rules, [(0, 0), (1, 0), (0, 1), (1, 1)], ["b", "a", "b", "b"],
              support="module obstacle", rounds=1)
    # (1,0) slides to (2,0) but then (2,0) touches nothing: still a split.
    assert res.violation is not None and res.violation.kind == "disconnected"


def test_nothing_fires_is_a_deadlock():
    res = run("rule M\n priority 1\n state a\n require N is obstacle\n become b\n",
              [(0, 0), (1, 0)], ["a", "a"])
    assert res.status == "deadlock"
    assert res.deadlock.round == 1
    assert res.deadlock.moving_states == {"a": 2}


def test_a_configuration_that_comes_back_is_a_livelock():
    # Two states that flip back and forth: rules keep firing, nothing moves.
    rules = ("rule F\n priority 1\n state a\n become c\n"
             "rule G\n priority 1\n state c\n become a\n")
    res = run(rules, [(0, 0), (1, 0)], ["a", "a"], rounds=50)
    assert res.status == "deadlock"
    assert res.deadlock.repeats_round == 0 and res.deadlock.round == 2
    assert "livelock" in res.deadlock.message
