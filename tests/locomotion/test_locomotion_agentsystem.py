"""The AgentSystem listing reader: OCR noise, actions, and repaired defects."""

import pytest

from hexbot.errors import ScenarioError
from hexbot.planning.locomotion.agentsystem import parse, read_listing, to_expr, tokenize
from hexbot.planning.locomotion.rules import Atom, Not

LISTING = """
%----- a comment
Step east
3
SACTIV E1,0 !(!T1,-1,STOPA !T1,-1,PIVOT) !T
 O,1,ACTIV
P1,0 A1111

```
Stop
1
SACTIV
SSTOPA

Broken
2
SSTOPA !!(E0,1)) (E1,0
SACTIV
"""


def test_rules_names_priorities_and_actions():
    rules = read_listing(LISTING)
    assert [(r.name, r.priority, r.move, r.become) for r in rules] == [
        ("Step east", 3, (1, 0), None),
        ("Stop", 1, None, "STOPA"),
        ("Broken", 2, None, "ACTIV"),
    ]


def test_ocr_noise_in_terms_is_removed():
    toks, bad = tokenize("!T\n O,1,ACTIV E0, -1")
    assert bad is None
    assert toks == ["!", "T0,1,ACTIV", "E0,-1"]


def test_expression_translation():
    (step, _, _) = read_listing(LISTING)
    tree = parse(step.tokens)
    exprs = [to_expr(item) for item in tree]
    assert exprs[0] == Atom((0, 0), frozenset({"ACTIV"}))
    assert exprs[1] == Atom((1, 0), frozenset({"empty"}))
    assert exprs[-1] == Not(Atom((0, 1), frozenset({"ACTIV"})))


def test_defects_are_repaired_and_listed():
    broken = read_listing(LISTING)[2]
    repairs: list[str] = []
    parse(broken.tokens, repairs)
    assert "'!!' read as no negation" in repairs
    assert "extra ')' dropped" in repairs
    assert "missing ')' added at the end" in repairs


def _deep(body: str) -> str:
    return f"%----- deep\nDeep\n1\nSACTIV {body}\nP1,0\n"


@pytest.mark.parametrize("body, ok", [
    ("(" * 100 + "E1,0" + ")" * 100, True),
    ("(" * 101 + "E1,0" + ")" * 101, False),
    ("!(" * 50 + "E1,0" + ")" * 50, True),  # each negating '!' and each '(' is a level
    ("!(" * 50 + "!E1,0" + ")" * 50, False),
    ("!!(" * 100 + "E1,0" + ")" * 100, True),  # '!!' negates nothing
    ("(" * 5000 + "E1,0", False),  # unclosed: refused before the repair closes them
], ids=["100 (", "101 (", "50 !(", "50 !( and !", "100 !!(", "5000 ("])
def test_a_precondition_nests_at_most_as_deep_as_a_rule_file(body, ok):
    """rulefile.MAX_NESTING and its words, with the rule's FILE:LINE; before,
    5000 parentheses were a RecursionError traceback in to_expr."""
    (rule,) = read_listing(_deep(body), "otero.txt")
    if ok:
        assert [to_expr(item) for item in parse(rule.tokens, where=rule.where)]
        return
    with pytest.raises(ScenarioError) as err:
        parse(rule.tokens, where=rule.where)
    assert str(err.value) == "otero.txt:2: expression nested deeper than 100 levels"
