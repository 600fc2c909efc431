"""Reader for AgentSystem rule listings (the simulator both theses used).

A listing is a sequence of rules: a name line, a priority line, then a
precondition of juxtaposed (AND) terms and an action::

    N movement
    3
    SACTIV E0,1 !(!E-1,0 !T-1,0,OBSTA ...) ...
    P0,1 A1111

Terms: ``S<state>`` the module's own state, ``E x,y`` an empty cell,
``T x,y,<state>`` a cell holding that state (obstacles are state ``OBSTA``),
``!`` negates the next term, parentheses group. Actions: ``P x,y`` move (with
``A....`` attach flags, which our model does not need) and/or a final
``S<state>`` new state. Whitespace inside terms is OCR noise and is ignored,
as are the letter O for a zero in coordinates and code-fence lines.

`read_listing` returns the rules with every defect it had to repair listed,
so a translation can be checked rule by rule. A precondition nests at most
``rulefile.MAX_NESTING`` levels, as a rule file's expression does: each
``(`` opens one and each ``!`` that negates (an odd run of them) one more;
`parse` refuses a deeper one with the rule's ``FILE:LINE`` and the rule
files' words (before, `to_expr` overflowed: a RecursionError traceback).
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

from hexbot.errors import ScenarioError
from hexbot.planning.locomotion.rulefile import MAX_NESTING, too_deep
from hexbot.planning.locomotion.rules import And, Atom, Expr, Not

_TERM = re.compile(
    r"!|\(|\)|S[A-Z]{5}|E-?\d+,-?\d+|T-?\d+,-?\d+,[A-Z]{5}|P-?\d+,-?\d+|A\d{4}"
)


@dataclass
class ASRule:
    name: str
    priority: int
    line: int  # of the rule's name
    tokens: list[str]
    move: tuple[int, int] | None = None
    become: str | None = None
    repairs: list[str] = field(default_factory=list)
    source: str = "<string>"  # the listing's file name, for errors

    @property
    def where(self) -> str:
        """``FILE:LINE`` of the rule, for an error about it."""
        return f"{self.source}:{self.line}"


def _normalise(body: str) -> str:
    body = re.sub(r"\s+", "", body)
    # OCR reads the digit zero in coordinates as the letter O ("TO,1", "EO,-1").
    return re.sub(r"(?<=[TE])O(?=,)", "0", body)


def tokenize(body: str) -> tuple[list[str], str | None]:
    text = _normalise(body)
    out: list[str] = []
    pos = 0
    while pos < len(text):
        m = _TERM.match(text, pos)
        if not m:
            return out, text[pos : pos + 24]
        out.append(m.group())
        pos = m.end()
    return out, None


def read_listing(text: str, source: str = "<string>") -> list[ASRule]:
    """Rules of an AgentSystem listing (state declarations and comments
    skipped); ``source`` names the file in errors about its rules."""
    lines: list[tuple[int, str]] = []
    for number, raw in enumerate(text.splitlines(), start=1):
        s = raw.strip()
        if not s or s.startswith(("```", "%", "_init")):
            continue
        lines.append((number, s))
    prio_at = [i for i, (_, s) in enumerate(lines) if re.fullmatch(r"\d+", s)]
    rules: list[ASRule] = []
    for j, i in enumerate(prio_at):
        name_line, name = lines[i - 1]
        end = prio_at[j + 1] - 1 if j + 1 < len(prio_at) else len(lines)
        body = " ".join(s for _, s in lines[i + 1 : end])
        toks, bad = tokenize(body)
        rule = ASRule(name, int(lines[i][1]), name_line, toks, source=source)
        if bad:
            rule.repairs.append(f"unreadable text {bad!r} dropped with what follows")
        _split_action(rule)
        rules.append(rule)
    return rules


def _split_action(rule: ASRule) -> None:
    toks = rule.tokens
    for k, t in enumerate(toks):
        if t.startswith("P"):
            dx, dy = t[1:].split(",")
            rule.move = (int(dx), int(dy))
            rest = [x for x in toks[k + 1 :] if not x.startswith("A")]
            if rest and re.fullmatch(r"S[A-Z]{5}", rest[-1]):
                rule.become = rest[-1][1:]
            rule.tokens = toks[:k]
            return
    if toks and re.fullmatch(r"S[A-Z]{5}", toks[-1]):
        rule.become = toks[-1][1:]
        rule.tokens = toks[:-1]


# --- expressions ----------------------------------------------------------


def parse(tokens: list[str], repairs: list[str] | None = None,
          where: str = "<listing>") -> list:
    """Nested lists: a group is a list of items; an item is a term, ('!', item)
    or a sub-group. Unbalanced parentheses are repaired (an extra ')' closes
    nothing and is dropped; missing ')' are added at the end) and noted.
    Nesting deeper than MAX_NESTING is a ScenarioError ``where: expression
    nested deeper than 100 levels`` (``where``: the rule's ``FILE:LINE``)."""
    repairs = repairs if repairs is not None else []
    stack: list[list] = [[]]
    levels = [0]  # levels open inside each group of the stack

    def enter(extra: int) -> int:
        if levels[-1] + extra > MAX_NESTING:
            raise ScenarioError(f"{where}: {too_deep()}")
        return levels[-1] + extra

    pending_not = 0
    for t in tokens:
        if t == "!":
            pending_not += 1
            continue
        if t == "(":
            levels.append(enter(pending_not % 2 + 1))
            stack.append([])
            stack[-1].append(("not-count", pending_not))
            pending_not = 0
            continue
        if t == ")":
            if len(stack) == 1:
                repairs.append("extra ')' dropped")
                continue
            levels.pop()
            group = stack.pop()
            nots = group.pop(0)[1]
            item: object = group
            for _ in range(nots % 2):
                item = ("!", item)
            if nots >= 2:
                repairs.append("'!!' read as no negation")
            stack[-1].append(item)
            continue
        item = t
        enter(pending_not % 2)
        for _ in range(pending_not % 2):
            item = ("!", item)
        if pending_not >= 2:
            repairs.append("'!!' read as no negation")
        pending_not = 0
        stack[-1].append(item)
    while len(stack) > 1:
        repairs.append("missing ')' added at the end")
        group = stack.pop()
        nots = group.pop(0)[1]
        item = group
        for _ in range(nots % 2):
            item = ("!", item)
        stack[-1].append(item)
    return stack[0]


def to_expr(item) -> Expr:
    """One parsed item as our expression (own-state terms become (0,0) atoms);
    `parse` bounds how deep it recurses (MAX_NESTING)."""
    if isinstance(item, tuple) and item[0] == "!":
        return Not(to_expr(item[1]))
    if isinstance(item, list):
        parts = [to_expr(x) for x in item]
        return parts[0] if len(parts) == 1 else And(tuple(parts))
    t = item
    if t.startswith("S"):
        return Atom((0, 0), frozenset({t[1:]}))
    if t.startswith("E"):
        dx, dy = t[1:].split(",")
        return Atom((int(dx), int(dy)), frozenset({"empty"}))
    dx, dy, st = t[1:].split(",")
    cls = "obstacle" if st == "OBSTA" else st
    return Atom((int(dx), int(dy)), frozenset({cls}))


__all__ = ["ASRule", "parse", "read_listing", "to_expr", "tokenize"]
