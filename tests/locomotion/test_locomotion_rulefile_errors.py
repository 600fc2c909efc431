"""Malformed rule files the reader must refuse, each error naming the file and
the line (docs/locomotion.md, "Rule files"), and the edge of what it accepts."""

import pytest

from hexbot.errors import ScenarioError
from hexbot.planning.locomotion import loads

HEADER = "ruleset t\nstates static active\n"
RULE = "rule A\n priority 1\n state static\n become active\n"


@pytest.mark.parametrize(("text", "line", "words"), [
    # a second header line would silently replace the first (a second 'states'
    # renames every state the rules above it were checked against)
    (HEADER + "states a b\n" + RULE, 3, "'states' given twice"),
    (HEADER + "symmetry diagonal\n\n" + RULE, 3, "symmetry must be one of"),
    (HEADER + "resting sleepy\n" + RULE, 3, "resting: unknown class 'sleepy'"),
    (HEADER + "support wall\n" + RULE, 3, "support: unknown class 'wall'"),
    (HEADER + "front HEADD\n" + RULE, 3, "front: unknown state 'HEADD'"),
    ("ruleset t\nstates a b a\n" + RULE, 2, "a state is listed twice"),
    (HEADER + "define FREE N is empty\ndefine FREE NE is empty\n" + RULE, 4,
     "'FREE' is already a position or defined"),
    (HEADER + "rule A\n priority 1\n state static\n require (0,0) is active\n become active\n",
     3, "use 'state' for the module itself"),
])
def test_malformed_rule_files_are_refused_with_file_and_line(text, line, words):
    with pytest.raises(ScenarioError) as err:
        loads(text, "my.rules")
    assert f"my.rules:{line}:" in str(err.value), str(err.value)
    assert words in str(err.value)


def test_a_rule_file_without_rules_is_refused():
    # it would otherwise run and "deadlock" in round 1, blaming the rules' logic
    with pytest.raises(ScenarioError, match="no rules"):
        loads(HEADER + "resting static\n", "my.rules")


def test_a_rule_may_look_up_to_8_cells_away_and_no_farther():
    # docs/locomotion.md: "at most 8 cells away on either axis"
    rule = "rule A\n priority 1\n state static\n require {} is empty\n become active\n"
    assert loads(HEADER + rule.format("(8,-8)")).reach() == 8
    with pytest.raises(ScenarioError, match=r"my.rules:6: position \(0,9\) is more than 8"):
        loads(HEADER + rule.format("(0,9)"), "my.rules")
