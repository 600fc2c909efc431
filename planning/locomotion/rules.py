"""Rules of a locomotion rule set: positions, preconditions, actions, symmetry.

A rule is written once, in a canonical orientation. ``variants()`` derives the
rotated (and, where the rule set asks for it, reflected) copies, so a file
never spells out the four or eight orientations the way AgentSystem needed.
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass, field

Offset = tuple[int, int]

# Relative positions by name; y grows upwards (north), as in the theses.
DIRECTIONS: dict[str, Offset] = {
    "N": (0, 1),
    "E": (1, 0),
    "S": (0, -1),
    "W": (-1, 0),
    "NE": (1, 1),
    "NW": (-1, 1),
    "SE": (1, -1),
    "SW": (-1, -1),
}

# Cell classes that are not module states.
EMPTY = "empty"
OBSTACLE = "obstacle"
MODULE = "module"  # a module in any state
SIMPLE = "@simple"  # pseudo-class of the `simple` test on the module's own ring
LOOPED = "@looped"  # pseudo-class of the `looped` test (the module lies on a cycle)
LOOP_RADIUS = 4  # how far (Chebyshev) the `looped` test looks for the other way round
BUILTIN_CLASSES = (EMPTY, OBSTACLE, MODULE)

SYMMETRIES = ("none", "rotations", "rotations+reflections")


def rotate(off: Offset, quarter_turns: int) -> Offset:
    """Rotate an offset counter-clockwise by ``quarter_turns`` * 90 degrees."""
    dx, dy = off
    for _ in range(quarter_turns % 4):
        dx, dy = -dy, dx
    return dx, dy


def reflect(off: Offset) -> Offset:
    """Mirror an offset in the vertical axis (east <-> west)."""
    return -off[0], off[1]


def transform(off: Offset, quarter_turns: int, mirrored: bool) -> Offset:
    return rotate(reflect(off) if mirrored else off, quarter_turns)


def offset_name(off: Offset) -> str:
    for name, value in DIRECTIONS.items():
        if value == off:
            return name
    return f"({off[0]},{off[1]})"


# --- precondition expressions ---------------------------------------------


@dataclass(frozen=True)
class Atom:
    """``position is one of classes`` (or, with ``negated``, none of them)."""

    offset: Offset
    classes: frozenset[str]
    negated: bool = False

    def transformed(self, quarter_turns: int, mirrored: bool) -> Atom:
        return Atom(transform(self.offset, quarter_turns, mirrored), self.classes, self.negated)

    def __str__(self) -> str:
        if self.classes & {SIMPLE, LOOPED}:
            test = "simple" if SIMPLE in self.classes else "looped"
            test = f"not {test}" if self.negated else test
            return test if self.offset == (0, 0) else f"{offset_name(self.offset)} is {test}"
        cls = "|".join(sorted(self.classes))
        return f"{offset_name(self.offset)} is {'not ' if self.negated else ''}{cls}"


@dataclass(frozen=True)
class Not:
    arg: Expr

    def transformed(self, quarter_turns: int, mirrored: bool) -> Not:
        return Not(self.arg.transformed(quarter_turns, mirrored))

    def __str__(self) -> str:
        return f"not ({self.arg})"


@dataclass(frozen=True)
class And:
    args: tuple[Expr, ...]

    def transformed(self, quarter_turns: int, mirrored: bool) -> And:
        return And(tuple(a.transformed(quarter_turns, mirrored) for a in self.args))

    def __str__(self) -> str:
        return " and ".join(f"({a})" if isinstance(a, Or) else str(a) for a in self.args)


@dataclass(frozen=True)
class Or:
    args: tuple[Expr, ...]

    def transformed(self, quarter_turns: int, mirrored: bool) -> Or:
        return Or(tuple(a.transformed(quarter_turns, mirrored) for a in self.args))

    def __str__(self) -> str:
        return " or ".join(str(a) for a in self.args)


Expr = Atom | Not | And | Or


def atoms_of(expr: Expr) -> Iterator[Atom]:
    if isinstance(expr, Atom):
        yield expr
    elif isinstance(expr, Not):
        yield from atoms_of(expr.arg)
    else:
        for a in expr.args:
            yield from atoms_of(a)


# --- rules ---------------------------------------------------------------------


@dataclass(frozen=True)
class Rule:
    """One rule as written in the file (canonical orientation)."""

    ident: str
    title: str
    priority: int
    state: str
    conditions: tuple[Expr, ...]  # all must hold
    become: str | None = None
    move: Offset | None = None
    symmetry: str = "rotations"
    line: int = 0  # where the rule starts in its file
    # One new state per quarter turn (0, 90, 180, 270 degrees counter-clockwise):
    # Otero's cycle breakers keep their direction of travel in their state.
    become_turns: tuple[str, str, str, str] | None = None

    @property
    def label(self) -> str:
        return f"{self.ident} {self.title}".strip()


@dataclass(frozen=True)
class Variant:
    """One orientation of a rule, as the engine evaluates it."""

    rule: Rule
    quarter_turns: int
    mirrored: bool
    conditions: tuple[Expr, ...]
    move: Offset | None

    @property
    def become(self) -> str | None:
        turns = self.rule.become_turns
        return turns[self.quarter_turns] if turns else self.rule.become

    @property
    def label(self) -> str:
        turn = f"rot{90 * self.quarter_turns}"
        return f"{self.rule.label} [{'mirror+' if self.mirrored else ''}{turn}]"


def variants(rule: Rule) -> list[Variant]:
    """The distinct orientations of a rule, canonical one first.

    Order is rotations 0, 90, 180, 270 (counter-clockwise), then the same for
    the mirror image; it is the tie-break between variants that both hold.
    """
    turns = range(1) if rule.symmetry == "none" else range(4)
    mirrors = (False, True) if rule.symmetry == "rotations+reflections" else (False,)
    out: list[Variant] = []
    seen: set[tuple] = set()
    for mirrored in mirrors:
        for q in turns:
            conds = tuple(c.transformed(q, mirrored) for c in rule.conditions)
            move = transform(rule.move, q, mirrored) if rule.move else None
            become = rule.become_turns[q] if rule.become_turns else rule.become
            key = (conds, move, become)
            if key in seen:  # a symmetric rule gives the same variant twice
                continue
            seen.add(key)
            out.append(Variant(rule, q, mirrored, conds, move))
    return out


@dataclass
class RuleSet:
    name: str
    states: list[str]  # the first is every module's initial state
    resting: set[str]
    support: set[str]  # classes that can carry a slide or pivot a convex move
    rules: list[Rule] = field(default_factory=list)
    source: str = ""
    description: str = ""
    front_state: str | None = None  # the state the strip's front module starts in

    def ordered_variants(self, frame: int = 0) -> list[Variant]:
        """All variants by decreasing priority; file order, then orientation, breaks ties.

        Orientations are ranked counting from ``frame`` (quarter turns of the
        scenario), so a scenario turned by 90 degrees makes the same choices,
        turned: the tie-break must not depend on which way is north.
        """
        ranked = sorted(enumerate(self.rules), key=lambda ir: (-ir[1].priority, ir[0]))
        out: list[Variant] = []
        for _, r in ranked:
            vs = variants(r)
            out.extend(sorted(vs, key=lambda v: ((v.quarter_turns - frame) % 4, v.mirrored)))
        return out

    def reach(self) -> int:
        """How far (Chebyshev) from the module the rules look."""
        far = 1
        for r in self.rules:
            for c in r.conditions:
                for a in atoms_of(c):
                    ring = 1 if SIMPLE in a.classes else 0  # the test reads the cell's ring
                    ring = LOOP_RADIUS + 1 if LOOPED in a.classes else ring
                    far = max(far, abs(a.offset[0]) + ring, abs(a.offset[1]) + ring)
        return far
