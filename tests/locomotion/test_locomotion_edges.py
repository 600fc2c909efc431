"""Edges of the locomotion engine a user depends on: splits the local
connectivity certificate must not let through, the goal line of a map, a
disconnected start, and rule files that must be refused with their line."""

import pytest

from hexbot.errors import ScenarioError
from hexbot.planning.locomotion import Engine, World, load_ruleset, load_scenario, loads, simulate
from hexbot.planning.locomotion.engine import Goal
from hexbot.planning.locomotion.rules import Atom, Not

FLOOR = [(x, -1) for x in range(-3, 10)]


def run(rules: str, modules, states, support="module", obstacles=(), rounds=5):
    text = f"ruleset t\nstates a b c\nresting b\nsupport {support}\nsymmetry none\n" + rules
    rs = loads(text)
    world = World(FLOOR + list(obstacles), modules, rs.states, module_states=states)
    return Engine(rs, world).run(rounds, Goal())


def test_two_movers_that_land_only_next_to_each_other_split_the_robot():
    # A (1,0) and B (4,0) turn round the raised obstacles (2,0) and (3,0) into
    # (2,1) and (3,1): each lands next to the other and nothing else. The fast
    # local certificate must not count a module that landed in the same round
    # as the one holding it (it would pass this split unreported).
    rules = (
        "rule A\n priority 1\n state a\n require E is obstacle and N is empty and NE is empty\n"
        " move NE\n"
        "rule B\n priority 1\n state c\n require W is obstacle and N is empty and NW is empty\n"
        " move NW\n"
    )
    arch = [(0, 1), (0, 2), (0, 3), (1, 3), (2, 3), (3, 3), (4, 3), (5, 3), (5, 2), (5, 1)]
    modules = [(0, 0), (1, 0), (4, 0), (5, 0), *arch]
    states = ["b", "a", "c", "b"] + ["b"] * len(arch)
    res = run(rules, modules, states, support="module obstacle", obstacles=[(2, 0), (3, 0)])
    assert res.status == "violation"
    assert res.violation.kind == "disconnected" and res.violation.round == 1
    assert res.violation.cells == [(2, 1), (3, 1)]


def test_two_neighbours_that_leave_together_split_the_robot():
    # A strip X A B Y: A turns up round X, B up round Y. Each empty cell alone
    # would be harmless, but the two are neighbours and together they were the
    # only link: the certificate must not judge them one by one.
    rules = (
        "rule A\n priority 1\n state a\n require W is module and N is empty and NW is empty\n"
        " move NW\n"
        "rule B\n priority 1\n state c\n require E is module and N is empty and NE is empty\n"
        " move NE\n"
    )
    res = run(rules, [(0, 0), (1, 0), (2, 0), (3, 0)], ["b", "a", "c", "b"])
    assert res.status == "violation"
    assert res.violation.kind == "disconnected" and res.violation.round == 1
    assert res.violation.cells in ([(0, 0), (0, 1)], [(3, 0), (3, 1)])


def test_a_map_is_reached_only_when_every_module_is_past_the_last_obstacle_column():
    # docs/locomotion.md: "a map's goal is reached when every module is east of
    # the obstacle's last column"; a module standing on that column is not past it.
    scenario = load_scenario("histogram-1", 5)
    res = simulate(load_ruleset("salvador-pyramids"), scenario, rounds=2000)
    assert res.status == "reached"
    assert all(x > scenario.threshold for x, _ in res.positions)
    assert res.rounds == 131


def test_a_robot_in_two_pieces_is_refused_before_the_first_round():
    rs = loads("ruleset t\nstates a b\nrule R\n priority 1\n state a\n become b\n")
    world = World(FLOOR, [(0, 0), (2, 0)], rs.states)
    with pytest.raises(ScenarioError, match="the initial robot is not connected"):
        Engine(rs, world)


def test_the_first_mirror_image_of_a_rule_is_its_east_west_mirror():
    # docs/locomotion.md: the rotations, "then the mirror images"; a mirror
    # image mirrors east and west. Written for a move east into an obstacle,
    # the rule fires as its mirror image only (west), and the report names it.
    text = ("ruleset t\nstates a b\nresting b\nsymmetry rotations+reflections\n"
            "rule R\n priority 1\n state a\n require E is obstacle and N is empty\n move E\n")
    rs = loads(text)
    world = World(FLOOR + [(-1, 0)], [(0, 0), (1, 0)], rs.states, module_states=["a", "b"])
    res = Engine(rs, world).run(3, Goal())
    assert res.violation.kind == "inside-obstacle"
    assert res.violation.cells == [(-1, 0), (0, 0)]
    assert res.violation.rules == ["R [mirror+rot0]"]


def test_four_become_states_turn_with_the_scenario_even_for_a_symmetric_rule():
    # `become A B C D`: one state per quarter turn. A rule without conditions
    # looks the same in every orientation; its four variants still differ in
    # the state they give, so a north-going run (frame 1) gives the second.
    rs = loads("ruleset t\nstates s e n w x\nresting x\n"
               "rule R\n priority 1\n state s\n become e n w x\n")
    for frame, state in enumerate(["e", "n", "w", "x"]):
        world = World(FLOOR, [(0, 0)], rs.states, extend_axis=None)
        res = Engine(rs, world, frame=frame).run(1, Goal())
        assert res.states == [state], frame


def test_agentsystem_obstacles_are_our_obstacle_class():
    # AgentSystem spells an obstacle as the state OBSTA; a translated rule must
    # ask for our `obstacle` class, or it never holds next to the floor.
    from hexbot.planning.locomotion.agentsystem import parse, to_expr, tokenize

    tokens, bad = tokenize("T0,-1,OBSTA !T1,-1,OBSTA")
    assert bad is None
    below, not_right = (to_expr(item) for item in parse(tokens))
    assert below == Atom((0, -1), frozenset({"obstacle"}))
    assert not_right == Not(Atom((1, -1), frozenset({"obstacle"})))


def test_a_map_whose_only_obstacle_stands_over_the_front_module_is_refused():
    # the goal is every module east of the last obstacle column; an obstacle in
    # the front module's own column leaves nothing to cross, as one behind it
    from hexbot.planning.locomotion.scenarios import parse_map

    with pytest.raises(ScenarioError, match=r"behind the strip's front \(x = 4\)"):
        parse_map("....#\n.oooo\n#####\n", "over", "over.map")
    assert parse_map(".....#\n.oooo.\n######\n", "ahead", "ahead.map").threshold == 5
