"""The AgentSystem listing reader: OCR noise, actions, and repaired defects."""

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
