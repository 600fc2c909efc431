"""The rule-file format: what it accepts, and errors that name the line."""

import pytest

from hexbot.errors import ScenarioError
from hexbot.planning.locomotion import Engine, World, load_ruleset, loads, ruleset_names
from hexbot.planning.locomotion.engine import Goal
from hexbot.planning.locomotion.rules import variants

HEADER = "ruleset t\nstates static active\n"


def test_expression_grammar_and_actions():
    rs = loads(
        HEADER
        + "rule X \"both\"\n priority 7\n state static\n"
        + " require (2,0) is not active and (N is empty|obstacle or not SE is module)\n"
        + " become active\n move E\n"
    )
    (rule,) = rs.rules
    assert rule.priority == 7 and rule.become == "active" and rule.move == (1, 0)
    assert rs.reach() == 2
    assert "(2,0) is not active" in str(rule.conditions[0])


def test_define_and_simple():
    rs = loads(HEADER + "define FREE N is empty and NE is empty\n"
               "rule X\n priority 1\n state static\n require FREE and not simple\n become active\n")
    text = str(rs.rules[0].conditions[0])
    assert "N is empty and NE is empty" in text and "not (simple)" in text


def test_simple_means_leaving_keeps_the_neighbours_joined():
    rs = loads("ruleset t\nstates a b\nrule X\n priority 1\n state a\n require simple\n"
               " become b\n")
    world = World([(x, -1) for x in range(-2, 5)], [(0, 0), (1, 0), (2, 0)], rs.states)
    result = Engine(rs, world).run(1, Goal())
    assert result.states == ["b", "a", "b"]  # the middle module holds the strip together


def test_define_needs_an_upper_case_name():
    with pytest.raises(ScenarioError, match="x.rules:3: define"):
        loads(HEADER + "define free N is empty\n", "x.rules")


def test_symmetry_gives_four_or_eight_orientations():
    text = HEADER + "symmetry {}\nrule X\n priority 1\n state static\n"
    text += " require NE is empty\n move E\n"
    counts = [len(variants(loads(text.format(s)).rules[0])) for s in
              ("none", "rotations", "rotations+reflections")]
    assert counts == [1, 4, 8]


def test_symmetric_rule_is_not_duplicated():
    text = HEADER + "rule X\n priority 1\n state active\n become static\n"
    assert len(variants(loads(text).rules[0])) == 1


@pytest.mark.parametrize(
    ("body", "line", "words"),
    [
        ("rule A\n priority 1\n state static\n require N is full\n become active\n", 6, "full"),
        ("rule A\n priority x\n", 4, "integer"),
        ("rule A\n state static\n become active\n", 3, "no priority"),
        ("rule A\n priority 1\n state static\n require Q is empty\n become active\n", 6, "'Q'"),
        ("rule A\n priority 1\n state static\n move (2,0)\n", 6, "neighbour"),
        ("rule A\n priority 1\n state static\n", 3, "no action"),
        ("rule A\n priority 1\n state sleepy\n", 5, "unknown state"),
        ("rule A\n priority 1\n state static\n frobnicate\n", 6, "frobnicate"),
        ("rule A\n priority 1\n state static\n require (N is empty\n become active\n", 6, ")"),
        (
            "rule A\n priority 1\n state static\n become active\n"
            "rule A\n priority 1\n state static\n become active\n",
            7,
            "twice",
        ),
    ],
)
def test_errors_name_file_and_line(body, line, words):
    with pytest.raises(ScenarioError) as err:
        loads(HEADER + body, "my.rules")
    assert f"my.rules:{line}:" in str(err.value)
    assert words in str(err.value)


def test_file_without_header_is_refused():
    with pytest.raises(ScenarioError, match="x.rules:1: 'states' must come before"):
        loads("rule A\n", "x.rules")
    with pytest.raises(ScenarioError, match="needs 'ruleset NAME'"):
        loads("states a b\n", "x.rules")


def test_shipped_rule_sets_load():
    names = ruleset_names()
    assert {"salvador-free", "salvador-pyramids"} <= set(names)
    for name in names:
        assert load_ruleset(name).rules


def test_unknown_rule_set_lists_the_shipped_ones():
    with pytest.raises(ScenarioError, match="salvador-free"):
        load_ruleset("no-such-rules")


def test_simple_about_a_neighbour():
    # 'S is not simple': the module below cannot leave without cutting its
    # ring. Here it holds two arms that meet only through it.
    rs = loads(HEADER + "rule X\n priority 1\n state active\n require S is not simple\n"
               " become static\n")
    assert str(rs.rules[0].conditions[0]) == "S is not simple"
    assert rs.reach() == 2  # the test reads the ring of a cell one step away

    def after(below_ring):
        cells = [(0, 0), (0, -1), *below_ring]
        world = World([], cells, rs.states, module_states=["active"] + ["static"] * (
            len(cells) - 1), extend_axis=None)
        return Engine(rs, world).run(1, Goal()).states[0]

    assert after([(-1, -1), (1, -1)]) == "static"  # (0,-1) joins W and E arms
    assert after([(-1, -1), (-1, 0)]) == "active"  # one run round it: it could leave


def test_simple_of_the_module_itself_is_written_plain():
    with pytest.raises(ScenarioError, match="write 'simple' for the module itself"):
        loads(HEADER + "rule X\n priority 1\n state active\n require (0,0) is simple\n"
              " become static\n", "x.rules")


def _looped_after(states_of: dict) -> dict:
    rs = loads("ruleset t\nstates a b c\nresting a b\n"
               "rule X\n priority 1\n state a\n require looped\n become b\n")
    assert str(rs.rules[0].conditions[0]) == "looped"
    cells = list(states_of)
    world = World([], cells, rs.states, module_states=[states_of[c] for c in cells],
                  extend_axis=None)
    result = Engine(rs, world).run(1, Goal())
    return dict(zip(result.positions, result.states, strict=True))


RING = [(0, 0), (1, 0), (2, 0), (2, 1), (2, 2), (1, 2), (0, 2), (0, 1)]


def test_looped_means_on_a_cycle_of_resting_modules():
    # A ring round one empty cell with an arm: the ring modules may leave (the
    # ring joins their neighbours the other way round), the joint of the arm
    # and the arm may not.
    after = _looped_after({c: "a" for c in [*RING, (3, 0), (4, 0)]})
    assert [c for c, s in after.items() if s == "b"] == [c for c in RING if c != (2, 0)]


def test_looped_does_not_count_on_modules_that_may_walk_away():
    # The same ring closed by a module in a state that is not resting: no module
    # is on a cycle of resting modules any more.
    states = {c: "a" for c in [*RING, (3, 0), (4, 0)]}
    states[(1, 2)] = "c"
    assert "b" not in _looped_after(states).values()


def test_looped_about_a_neighbour_and_not_for_the_module_itself():
    rs = loads(HEADER + "rule X\n priority 1\n state active\n require S is not looped\n"
               " become static\n")
    assert str(rs.rules[0].conditions[0]) == "S is not looped"
    with pytest.raises(ScenarioError, match="write 'looped' for the module itself"):
        loads(HEADER + "rule X\n priority 1\n state active\n require (0,0) is looped\n"
              " become static\n", "x.rules")
