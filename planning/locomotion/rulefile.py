"""Reader for ``.rules`` files: a line-based format a person can write.

Layout (``#`` starts a comment; indentation is for the reader only)::

    ruleset salvador-free
    states static active        # the first state is every module's initial state
    resting static              # states that count as "stopped"
    support module              # what may carry a slide or pivot a convex move
    symmetry rotations          # none | rotations | rotations+reflections
    front HEADD                 # optional: the strip's front module starts in this state

    rule R1 "Activation"
      priority 10
      state static
      require N is empty
      require E is static and NE is empty
      require W is empty|obstacle
      become active

A ``require`` line is a boolean expression over cells: ``POS is CLASS|CLASS``,
``POS is not CLASS``, ``and``, ``or``, ``not``, parentheses, and names given
earlier by ``define NAME EXPRESSION`` (a shared condition written once), and
``simple``: the module's occupied 8 neighbours form one run that holds all its
edge neighbours, so its leaving cannot cut the robot locally (``POS is simple``
asks the same about the module at POS). POS is a name
(N E S W NE NW SE SW) or an offset ``(dx,dy)``; CLASS is ``empty``,
``obstacle``, ``module`` (any state) or a state name. All ``require`` lines
must hold. Actions: ``become STATE`` and/or ``move POS`` (a neighbour cell);
``become A B C D`` names one state per quarter turn of the rule (0, 90, 180,
270 degrees counter-clockwise), for states that carry a direction.
An expression nests at most ``MAX_NESTING`` levels: each ``not`` and each
pair of parentheses opens one, and a defined name counts as its own
expression in parentheses (a chain of defines nests as deep as it is long).
Every error names the file and line.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path

from hexbot.errors import ScenarioError
from hexbot.files import read_text
from hexbot.planning.locomotion.rules import (
    BUILTIN_CLASSES,
    DIRECTIONS,
    LOOPED,
    SIMPLE,
    SYMMETRIES,
    And,
    Atom,
    Expr,
    Not,
    Offset,
    Or,
    Rule,
    RuleSet,
    atoms_of,
)

HEADER_KEYS = ("ruleset", "states", "resting", "support", "symmetry", "front")

_TOKEN = re.compile(
    r"\s*(?:(?P<offset>\(\s*-?\d+\s*,\s*-?\d+\s*\))|(?P<punct>[()|!])|(?P<word>[A-Za-z_][\w-]*))"
)


class _Error(Exception):
    pass


#: How deep an expression may nest: each ``not`` and each pair of parentheses
#: is one level, a defined name one more than its own expression (as if its
#: expression stood in parentheses where the name is used). The shipped
#: rules nest at most 6; a deeper file is refused with its line instead of
#: overflowing the recursive parser and evaluator (a RecursionError traceback).
MAX_NESTING = 100


def too_deep(via: str = "") -> str:
    """The refusal of an expression deeper than MAX_NESTING (``via``: how, e.g.
    through a defined name), for rule files and AgentSystem listings alike."""
    return f"expression nested deeper than {MAX_NESTING} levels{via}"


def _tokenize(text: str) -> list[str]:
    tokens: list[str] = []
    pos = 0
    text = text.rstrip()
    while pos < len(text):
        m = _TOKEN.match(text, pos)
        if not m or m.end() == pos:
            raise _Error(f"cannot read {text[pos:].strip()[:20]!r}")
        tokens.append(m.group(m.lastgroup or "word").replace(" ", ""))
        pos = m.end()
    return tokens


#: How far from its module a rule may look (cells, either axis). The shipped
#: rules look at most 3 cells away; the engine pads its grid by the reach.
MAX_REACH = 8


def parse_position(token: str) -> Offset:
    if token.startswith("("):
        dx, dy = token[1:-1].split(",")
        off = int(dx), int(dy)
        if max(abs(off[0]), abs(off[1])) > MAX_REACH:
            raise _Error(f"position {token} is more than {MAX_REACH} cells from the module")
        return off
    if token in DIRECTIONS:
        return DIRECTIONS[token]
    raise _Error(f"{token!r} is not a position (use N E S W NE NW SE SW or (dx,dy))")


class _ExprParser:
    def __init__(self, tokens: list[str], classes: set[str], names: dict[str, Expr],
                 levels: dict[str, int], level: int = 0):
        self.toks = tokens
        self.i = 0
        self.classes = classes
        self.names = names
        self.levels = levels  # how deep each defined name nests, its parentheses included
        self.level = level  # levels open where the parser is
        self.deepest = level  # the most levels open at once

    def enter(self, extra: int = 1, through: str = "") -> None:
        """Open ``extra`` levels (a ``not``, a parenthesis, a defined name)."""
        if self.level + extra > MAX_NESTING:
            via = f" (through {through}, which nests {extra})" if through else ""
            raise _Error(too_deep(via))
        self.deepest = max(self.deepest, self.level + extra)

    def peek(self) -> str | None:
        return self.toks[self.i] if self.i < len(self.toks) else None

    def take(self) -> str:
        tok = self.peek()
        if tok is None:
            raise _Error("expression ends too early")
        self.i += 1
        return tok

    def parse(self) -> Expr:
        expr = self.disjunction()
        if self.peek() is not None:
            raise _Error(f"unexpected {self.peek()!r}")
        return expr

    def disjunction(self) -> Expr:
        args = [self.conjunction()]
        while self.peek() == "or":
            self.take()
            args.append(self.conjunction())
        return args[0] if len(args) == 1 else Or(tuple(args))

    def conjunction(self) -> Expr:
        args = [self.unary()]
        while self.peek() == "and":
            self.take()
            args.append(self.unary())
        return args[0] if len(args) == 1 else And(tuple(args))

    def unary(self) -> Expr:
        tok = self.peek()
        if tok in ("not", "!"):
            self.take()
            self.enter()
            self.level += 1
            inner = self.unary()
            self.level -= 1
            return Not(inner)
        if tok == "(":
            self.take()
            self.enter()
            self.level += 1
            inner = self.disjunction()
            self.level -= 1
            if self.peek() != ")":
                raise _Error("missing ')'")
            self.take()
            return inner
        if tok in self.names:
            self.take()
            self.enter(self.levels.get(tok, 1), tok)
            return self.names[tok]
        if tok == "simple":
            self.take()
            return Atom((0, 0), frozenset({SIMPLE}))
        if tok == "looped":
            self.take()
            return Atom((0, 0), frozenset({LOOPED}))
        return self.atom()

    def atom(self) -> Atom:
        offset = parse_position(self.take())
        negated = False
        if self.peek() == "is":
            self.take()
        if self.peek() in ("not", "!"):
            self.take()
            negated = True
        if self.peek() == "simple":  # the ring test, about a neighbour
            self.take()
            if offset == (0, 0):
                raise _Error("write 'simple' for the module itself")
            return Atom(offset, frozenset({SIMPLE}), negated)
        if self.peek() == "looped":  # the cycle test, about a neighbour
            self.take()
            if offset == (0, 0):
                raise _Error("write 'looped' for the module itself")
            return Atom(offset, frozenset({LOOPED}), negated)
        names = [self.cls()]
        while self.peek() == "|":
            self.take()
            names.append(self.cls())
        return Atom(offset, frozenset(names), negated)

    def cls(self) -> str:
        tok = self.take()
        if tok not in self.classes:
            raise _Error(f"unknown cell class {tok!r} (known: {', '.join(sorted(self.classes))})")
        return tok


def parse_expression(
    text: str, states: list[str], names: dict[str, Expr] | None = None,
    levels: dict[str, int] | None = None,
) -> Expr:
    """Parse one ``require`` expression (raises ValueError with the reason).
    ``levels``: how deep each of ``names`` nests (a name missing: 1)."""
    return _parse_nested(text, states, names or {}, levels or {})[0]


def _parse_nested(
    text: str, states: list[str], names: dict[str, Expr], levels: dict[str, int],
    level: int = 0,
) -> tuple[Expr, int]:
    """The expression and how many levels it nests (see MAX_NESTING),
    starting ``level`` deep (1: a define's body, in its implied parentheses)."""
    try:
        classes = set(BUILTIN_CLASSES) | set(states)
        parser = _ExprParser(_tokenize(text), classes, names, levels, level)
        return parser.parse(), parser.deepest
    except _Error as exc:
        raise ValueError(str(exc)) from None


@dataclass
class _Draft:
    ident: str
    title: str
    line: int
    priority: int | None = None
    state: str | None = None
    become: str | None = None
    move: Offset | None = None
    symmetry: str | None = None
    become_turns: tuple[str, str, str, str] | None = None

    def __post_init__(self) -> None:
        self.conditions: list[Expr] = []


def _split_title(rest: str) -> tuple[str, str]:
    m = re.fullmatch(r'(\S+)\s*(?:"([^"]*)")?\s*', rest)
    if not m:
        raise _Error('expected: rule ID "title"')
    return m.group(1), m.group(2) or ""


def loads(text: str, source: str = "<string>") -> RuleSet:
    """Parse a rule file's text; every error names ``source`` and the line."""
    header: dict[str, str] = {}
    header_line: dict[str, int] = {}
    drafts: list[_Draft] = []
    description: list[str] = []
    states: list[str] = []
    names: dict[str, Expr] = {}
    levels: dict[str, int] = {}  # how deep each define nests
    current: _Draft | None = None
    lineno = 0
    try:
        for lineno, raw in enumerate(text.splitlines(), start=1):
            if raw.startswith("##") and not drafts:
                description.append(raw[2:].strip())
            line = raw.split("#", 1)[0].strip()
            if not line:
                continue
            key, _, rest = line.partition(" ")
            rest = rest.strip()
            if key in HEADER_KEYS and current is None:
                if key in header:
                    raise _Error(f"{key!r} given twice")
                if not rest:
                    raise _Error(f"{key!r} needs a value")
                header[key], header_line[key] = rest, lineno
                if key == "states":
                    states = rest.split()
                    _check_state_names(states)
                continue
            if key == "define":
                if "states" not in header:
                    raise _Error("'states' must come before the first define")
                name, _, body = rest.partition(" ")
                if not re.fullmatch(r"[A-Z][A-Z0-9_]*", name):
                    raise _Error(f"define: {name!r} must be an upper-case name like C_SLIDE")
                if name in DIRECTIONS or name in names:
                    raise _Error(f"define: {name!r} is already a position or defined")
                try:
                    # a name stands for its expression in parentheses: one level more
                    names[name], levels[name] = _parse_nested(body, states, names, levels, 1)
                except ValueError as exc:
                    raise _Error(f"define {name}: {exc}") from None
                current = None
                continue
            if key == "rule":
                if "states" not in header:
                    raise _Error("'states' must come before the first rule")
                ident, title = _split_title(rest)
                if any(d.ident == ident for d in drafts):
                    raise _Error(f"rule {ident!r} defined twice")
                current = _Draft(ident, title, lineno)
                drafts.append(current)
                continue
            if current is None:
                raise _Error(f"unknown header keyword {key!r}")
            _rule_line(current, key, rest, states, names, levels)
        if "ruleset" not in header or "states" not in header:
            lineno = 0
            raise _Error("a rule file needs 'ruleset NAME' and 'states ...'")
        default_sym = header.get("symmetry", "rotations")
        if default_sym not in SYMMETRIES:
            lineno = header_line["symmetry"]
            raise _Error(f"symmetry must be one of {', '.join(SYMMETRIES)}")
        resting = set(header.get("resting", states[0]).split())
        support = set(header.get("support", "module").split())
        for key, values in (("resting", resting), ("support", support)):
            bad = values - set(states) - set(BUILTIN_CLASSES)
            if bad:
                lineno = header_line[key]
                raise _Error(f"{key}: unknown class {sorted(bad)[0]!r}")
        front = header.get("front")
        if front is not None and front not in states:
            lineno = header_line["front"]
            raise _Error(f"front: unknown state {front!r}")
        rules = []
        for d in drafts:
            lineno = d.line
            rules.append(_finish(d, default_sym))
        if not rules:
            raise _Error("no rules")
    except _Error as exc:
        where = f"{source}:{lineno}" if lineno else source
        raise ScenarioError(f"{where}: {exc}") from None
    return RuleSet(
        name=header["ruleset"],
        states=states,
        resting=resting,
        support=support,
        rules=rules,
        source=source,
        description=" ".join(description),
        front_state=front,
    )


def _check_state_names(states: list[str]) -> None:
    for s in states:
        if s in BUILTIN_CLASSES or s in DIRECTIONS or s in ("is", "not", "and", "or"):
            raise _Error(f"{s!r} cannot be a state name")
    if len(set(states)) != len(states):
        raise _Error("a state is listed twice")


def _rule_line(
    d: _Draft, key: str, rest: str, states: list[str], names: dict[str, Expr],
    levels: dict[str, int],
) -> None:
    if key == "priority":
        if not re.fullmatch(r"-?\d+", rest):
            raise _Error(f"priority must be an integer, not {rest!r}")
        d.priority = int(rest)
    elif key == "state":
        if rest not in states:
            raise _Error(f"unknown state {rest!r} (states: {', '.join(states)})")
        d.state = rest
    elif key == "require":
        try:
            d.conditions.append(parse_expression(rest, states, names, levels))
        except ValueError as exc:
            raise _Error(str(exc)) from None
    elif key == "become":
        if d.become is not None:
            raise _Error("a rule has one 'become' line")
        words = rest.split()
        if len(words) not in (1, 4):
            raise _Error("become takes one state, or four: one per quarter turn")
        for w in words:
            if w not in states:
                raise _Error(f"unknown state {w!r} (states: {', '.join(states)})")
        d.become = words[0]
        d.become_turns = tuple(words) if len(words) == 4 else None
    elif key == "move":
        if d.move is not None:
            raise _Error("a rule has one 'move' line")
        off = parse_position(rest)
        if off == (0, 0) or max(abs(off[0]), abs(off[1])) != 1:
            raise _Error(f"a move goes to one of the 8 neighbour cells, not {rest!r}")
        d.move = off
    elif key == "symmetry":
        if rest not in SYMMETRIES:
            raise _Error(f"symmetry must be one of {', '.join(SYMMETRIES)}")
        d.symmetry = rest
    else:
        raise _Error(f"unknown keyword {key!r} in rule {d.ident}")


def _finish(d: _Draft, default_sym: str) -> Rule:
    if d.priority is None:
        raise _Error(f"rule {d.ident} has no priority")
    if d.state is None:
        raise _Error(f"rule {d.ident} has no state")
    if d.become is None and d.move is None:
        raise _Error(f"rule {d.ident} has no action (become and/or move)")
    if d.become_turns and (d.symmetry or default_sym) != "rotations":
        raise _Error(f"rule {d.ident}: four 'become' states need 'symmetry rotations'")
    for c in d.conditions:
        for a in atoms_of(c):
            if a.offset == (0, 0) and not a.classes & {SIMPLE, LOOPED}:
                raise _Error(f"rule {d.ident}: use 'state' for the module itself, not (0,0)")
    return Rule(
        ident=d.ident,
        title=d.title,
        priority=d.priority,
        state=d.state,
        conditions=tuple(d.conditions),
        become=d.become,
        become_turns=d.become_turns,
        move=d.move,
        symmetry=d.symmetry or default_sym,
        line=d.line,
    )


def load(path: str | Path) -> RuleSet:
    path = Path(path)
    return loads(read_text(path, "rule file"), str(path))
