"""Traversal maps as text: the grid convention of ``hexbot plan`` files.

One token per cell, row 1 on top; the token in row ``r``, column ``c`` of an
``R``-row map is the axial cell ``(c - 1, R - r)`` (as
:mod:`hexbot.planning.config_io`). Tokens: ``S`` surface (unmoving
modules), ``M`` a module of the starting chain, ``G`` a goal cell, ``.``
free. Tokens may be separated by spaces or written together; ``#`` starts a
comment. Every error names the file and the line.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path

from hexbot.errors import ScenarioError
from hexbot.files import read_text
from hexbot.planning.configuration import is_connected
from hexbot.protocol.lattice import SIDES, Cell, neighbor

TOKENS = {"S": "surface", "M": "module", "G": "goal", ".": "free"}


@dataclass(frozen=True)
class Surface:
    """A traversal problem: surface cells, the starting chain, the goal cells."""

    surface: frozenset[Cell]
    modules: frozenset[Cell]
    goals: frozenset[Cell]
    name: str = "surface"
    source: str = ""  # the map file, named by errors found past parsing ("": none)

    @property
    def n(self) -> int:
        return len(self.modules)

    def cells(self) -> frozenset[Cell]:
        return self.surface | self.modules | self.goals


def parse_map(text: str, source: str = "<map>") -> Surface:
    """Parse a map (see the module docstring); checks what the algorithm assumes."""
    rows: list[tuple[int, str]] = []
    for lineno, raw in enumerate(text.splitlines(), start=1):
        line = raw.split("#", 1)[0]
        tokens = "".join(line.split())
        if not tokens:
            continue
        bad = re.search(r"[^SMG.]", tokens)
        if bad:
            raise ScenarioError(
                f"{source}:{lineno}: unknown token {bad.group()!r} (expected S, M, G or .)")
        if rows and len(tokens) != len(rows[0][1]):
            raise ScenarioError(
                f"{source}:{lineno}: row has {len(tokens)} cells, "
                f"row 1 (line {rows[0][0]}) has {len(rows[0][1])}")
        rows.append((lineno, tokens))
    if not rows:
        raise ScenarioError(f"{source}: no map rows found")
    height = len(rows)
    found: dict[str, set[Cell]] = {"S": set(), "M": set(), "G": set(), ".": set()}
    line_of: dict[Cell, int] = {}
    for r, (lineno, tokens) in enumerate(rows):
        for c, token in enumerate(tokens):
            cell = (c, height - 1 - r)
            found[token].add(cell)
            line_of[cell] = lineno
    surface = Surface(frozenset(found["S"]), frozenset(found["M"]), frozenset(found["G"]),
                      Path(source).stem, source)
    _check(surface, source, line_of)
    return surface


def _check(surface: Surface, source: str, line_of: dict[Cell, int]) -> None:
    if not surface.surface:
        raise ScenarioError(f"{source}: the map has no surface cell (S)")
    if not is_connected(surface.surface):
        cell = min(surface.surface, key=lambda c: line_of[c])
        raise ScenarioError(f"{source}:{line_of[cell]}: the surface (S) is not contiguous")
    if surface.n < 1:
        raise ScenarioError(f"{source}: the map has no module (M)")
    if len(surface.goals) != surface.n:
        raise ScenarioError(
            f"{source}: {surface.n} module(s) M but {len(surface.goals)} goal cell(s) G")
    for kind, cells in (("module", surface.modules), ("goal cell", surface.goals)):
        for cell in sorted(cells, key=lambda c: line_of[c]):
            if not any(neighbor(cell, side) in surface.surface for side in SIDES):
                raise ScenarioError(
                    f"{source}:{line_of[cell]}: {kind} at {list(cell)} does not touch the "
                    "surface (every M and G cell must lie on the surface's perimeter)")


def load_map(path: str | Path) -> Surface:
    path = Path(path)
    return parse_map(read_text(path), str(path))


def map_text(surface: Surface, header: str = "") -> str:
    """The map as text (spaced tokens), the inverse of :func:`parse_map`."""
    cells = surface.cells()
    xs, ys = [c[0] for c in cells], [c[1] for c in cells]
    x0, x1, y0, y1 = min(xs), max(xs), min(ys), max(ys)
    lines = [f"# {line}" for line in header.splitlines()]
    for y in range(y1, y0 - 1, -1):
        row = []
        for x in range(x0, x1 + 1):
            cell = (x, y)
            row.append("S" if cell in surface.surface else "M" if cell in surface.modules
                       else "G" if cell in surface.goals else ".")
        lines.append(" ".join(row))
    return "\n".join(lines) + "\n"


def shifted(surface: Surface, dx: int, dy: int) -> Surface:
    """The same problem moved by (dx, dy) (``map_text`` writes from the origin)."""
    def move(cells: frozenset[Cell]) -> frozenset[Cell]:
        return frozenset((x + dx, y + dy) for x, y in cells)

    return Surface(move(surface.surface), move(surface.modules), move(surface.goals),
                   surface.name, surface.source)
