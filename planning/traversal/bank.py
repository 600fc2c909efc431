"""The map bank: surfaces built from a height profile, pockets dug to a length.

A surface is a block of unmoving modules under a top profile (``tops[x]``
is the highest surface cell of column ``x``; a column of constant ``x``, as
a row of a text map is one of constant ``y``). The chain of ``n`` modules
lies on the flat start, the goal cells on the flat end. A pocket feature
opens the cells its case needs (Fig. 5) and then digs one surface cell at a
time, the shallowest first, until the pocket has the wanted perimeter
length, checking with FINDBRIDGECELLS itself that the case did not change.

``python -m hexbot.planning.traversal.bank`` rewrites the text files in
``planning/traversal/maps/`` (a test checks that they are up to date).
"""

from __future__ import annotations

import random
import sys
from dataclasses import dataclass
from pathlib import Path

from hexbot.errors import ScenarioError
from hexbot.planning.configuration import is_connected
from hexbot.planning.traversal.bridges import BridgeMap, find_bridge_cells
from hexbot.planning.traversal.surface import Surface, map_text
from hexbot.protocol.lattice import SIDES, Cell, distance, neighbor

MAPS = Path(__file__).resolve().parent / "maps"
CASES = ("SINGLE", "BASIC", "LEFT", "RIGHT")
LENGTHS = (1, 2, 3, 5, 8)
DEPTH = 10  # rows of surface under the lowest top


@dataclass
class Feature:
    """A pocket: ``case`` in CASES with ``length`` perimeter cells, or ``THREE``:
    a 3-cell opening over a channel three cells wide and ``length`` rows deep."""

    case: str
    length: int
    at: int = 0
    shape: str = "straight"  # THREE only: the 3-bridge shape the opening calls for


def _surface(tops: dict[int, int], dug: set[Cell]) -> set[Cell]:
    low = min(tops.values()) - DEPTH
    return {(x, y) for x, top in tops.items() for y in range(low, top + 1)} - dug


def _with_ends(cells: set[Cell], tops: dict[int, int], n: int, name: str) -> Surface:
    xs = sorted(tops)
    modules = frozenset((x, tops[x] + 1) for x in xs[1: 1 + n])
    goals = frozenset((x, tops[x] + 1) for x in xs[-1 - n: -1])
    return Surface(frozenset(cells), modules, goals, name)


def _opening(case: str, p: int, h: int, tops: dict[int, int]) -> tuple[list[Cell], Cell, Cell]:
    """Set the tops around column ``p`` (current height ``h``) for ``case``; the
    cells to open first and the BI pair (x, y) (the ends u, v for THREE)."""
    if case == "BASIC":
        return [(p, h), (p + 1, h), (p + 1, h - 1)], (p, h), (p + 1, h)
    if case == "SINGLE":
        return [(p + 1, h)], (p, h + 1), (p + 1, h + 1)
    if case == "LEFT":
        for x in tops:
            if x > p:
                tops[x] = h - 1
        return [(p, h), (p + 1, h - 1)], (p, h), (p + 1, h)
    if case == "RIGHT":
        for x in tops:
            if x > p:
                tops[x] = h + 1
        return [(p + 1, h + 1), (p + 1, h)], (p, h + 1), (p + 1, h + 1)
    if case == "THREE":
        return ([(p, h), (p + 1, h), (p + 2, h), (p + 1, h - 1), (p + 2, h - 1), (p + 2, h - 2)],
                (p, h), (p + 2, h))
    raise ValueError(case)


def _three_opening(shape: str, p: int, h: int, depth: int,
                   tops: dict[int, int]) -> tuple[set[Cell], Cell, Cell]:
    """A 3-cell opening ``u, w, v`` for the 3-bridge ``shape`` over a channel
    ``depth`` rows deep, left of it the surface at height ``h`` (the anchors
    of docs/traversal.md: a bend is a step of one row next to ``u`` or ``v``)."""
    row, cols, right = {"straight": (h, (0, 1, 2), h),
                        "curved-right": (h, (0, 1, 2), h - 1),  # step down after v
                        "curved-symmetric": (h - 1, (0, 1, 2), h - 2),  # down at both ends
                        "curved-left": (h + 1, (1, 2), h + 1)}[shape]  # u on the old top
    for x in tops:
        if x > p + 2:
            tops[x] = right
        elif x >= p:
            tops[x] = row if x - p in cols else h
    dug = {(p + k, row) for k in range(3)}
    dug |= {(p + k, row - r) for r in range(1, depth) for k in cols} | {(p + 2, row - 2)}
    return dug, (p, row), (p + 2, row)


def _group_at(bmap: BridgeMap, x: Cell, y: Cell, case: str, shape: str = "straight"):
    for group in bmap.groups:
        i, j = group.span
        if case == "THREE":  # the bridge may lean one cell off the opening's row
            if group.kind == "THREE" and group.shape == shape and distance(
                    group.bridge[0], x) <= 1 and distance(group.bridge[-1], y) <= 1:
                return group
        elif bmap.layer1.cells[i] == x and bmap.layer1.cells[j] == y and group.kind != "THREE":
            return group
    return None


def _measure(tops, dug, n, x, y, case, shape: str = "straight") -> int | None:
    """The pocket length of the feature's bridge, None when the case is lost."""
    cells = _surface(tops, dug)
    if not is_connected(cells):
        return None
    try:
        bmap = find_bridge_cells(_with_ends(cells, tops, n, "probe"),
                                 three=case == "THREE")
    except ScenarioError:
        return None
    group = _group_at(bmap, x, y, case, shape)
    if group is None or (case != "THREE" and group.kind != case):
        return None
    return group.pocket_length


def build(features: list[Feature], n: int, *, gap: int = 7, name: str = "surface",
          steps: list[int] | None = None) -> Surface:
    """A surface with the features left to right (``steps``: extra height changes)."""
    width = n + 4 + gap // 2 + len(features) * (gap + 3) + n + 4
    tops = dict.fromkeys(range(width), 0)
    dug: set[Cell] = set()
    p = n + 4 + gap // 2
    for k, feature in enumerate(features):
        h = tops[p]
        if feature.case == "THREE":  # a channel ``length`` rows deep under the opening
            opening, x, y = _three_opening(feature.shape, p, h, feature.length, tops)
        else:
            opening, x, y = _opening(feature.case, p, h, tops)
        dug |= set(opening)
        length = _measure(tops, dug, n, x, y, feature.case, feature.shape)
        if length is None:
            raise ScenarioError(f"feature {feature.case} at column {p}: bad opening")
        if feature.case == "THREE":
            p += gap + 3
            continue
        while length < feature.length:
            length = _dig_one(tops, dug, n, x, y, feature.case, length, feature.length, p)
        if length != feature.length:
            raise ScenarioError(f"{feature.case}: cannot dig a pocket of length "
                                f"{feature.length}")
        p += gap + 3
        if steps and k < len(steps):
            for x_ in tops:
                if x_ >= p - 2:
                    tops[x_] += steps[k]
    return _with_ends(_surface(tops, dug), tops, n, name)


def _dig_one(tops, dug, n, x, y, case, length, target, p) -> int:
    """Dig the first cell (or pair of touching cells: a one-cell dent is not part
    of the perimeter) that makes the pocket longer without passing ``target``."""
    top_y = min(x[1], y[1])
    # a 3-cell opening gets a straight channel three cells wide (no narrow part
    # inside: without its 3-bridge the modules roll through all of it)
    lo, hi = (p, p + 2) if case == "THREE" else (p - 4, p + 8)

    def candidates(around: set[Cell]) -> list[Cell]:
        return sorted((c for c in {neighbor(d, s) for d in around for s in SIDES} - around
                       if c[1] < top_y and lo <= c[0] <= hi
                       and c[1] <= tops.get(c[0], -99)),
                      key=lambda c: (-c[1], abs(c[0] - p - 1), c[0]))

    for first in candidates(dug):
        new = _measure(tops, dug | {first}, n, x, y, case)
        if new is not None and length < new <= target:
            dug.add(first)
            return new
    for first in candidates(dug):
        for second in candidates(dug | {first}):
            if second not in {neighbor(first, s) for s in SIDES}:
                continue
            new = _measure(tops, dug | {first, second}, n, x, y, case)
            if new is not None and length < new <= target:
                dug |= {first, second}
                return new
    raise ScenarioError(f"{case}: cannot grow the pocket past length {length} "
                        f"(wanted {target})")


def random_surface(seed: int, n: int = 4, width: int = 36, pockets: int = 4) -> Surface:
    """A seeded random surface: a height walk with random dug pockets."""
    rng = random.Random(seed)
    tops, h = {}, 0
    for x in range(width):
        if n + 3 < x < width - n - 4 and rng.random() < 0.3:
            h = max(-3, min(3, h + rng.choice((-1, 1))))
        tops[x] = h
    dug: set[Cell] = set()
    for _ in range(pockets):
        px = rng.randrange(n + 5, width - n - 6)
        cell = (px, tops[px])
        for _ in range(rng.randrange(2, 12)):
            dug.add(cell)
            cell = neighbor(cell, rng.choice((3, 4, 5, 6, 4, 5)))
            if cell[1] <= min(tops.values()) - DEPTH + 2:
                break
    cells = _surface(tops, dug)
    if not is_connected(cells):  # keep the piece under the chain
        from hexbot.planning.configuration import contact_hops

        cells = set(contact_hops(cells, (1, tops[1])))
    return _with_ends(cells, tops, n, f"random-{seed}")


def bank() -> dict[str, tuple[Surface, str]]:
    """name -> (surface, description) of every map of the bank."""
    out: dict[str, tuple[Surface, str]] = {
        "flat": (build([], 4, name="flat"), "flat surface, 4 modules"),
        "steps": (_steps(4), "steps up and down, 4 modules"),
    }
    for case in CASES:
        for length in LENGTHS:
            name = f"{case.lower()}-{length}"
            try:
                out[name] = (build([Feature(case, length)], 4, name=name),
                             f"one {case} pocket of perimeter length {length}, 4 modules")
            except ScenarioError as exc:
                print(f"bank: no {name}: {exc}", file=sys.stderr)
    for depth in (2, 4, 8):
        name = f"three-deep{depth}"
        out[name] = (build([Feature("THREE", depth)], 4, name=name),
                     f"a 3-cell opening over a channel three wide and {depth} rows deep")
    for shape in ("curved-left", "curved-right", "curved-symmetric"):
        name = f"three-{shape}"
        out[name] = (build([Feature("THREE", 4, shape=shape)], 4, name=name),
                     f"a 3-cell opening whose 3-bridge is {shape}, over a channel 4 rows deep")
    # under the hexbot model the 3-wide opening takes four Fill cells: one more module
    out["three-deep2-n5"] = (build([Feature("THREE", 2)], 5, name="three-deep2-n5"),
                             "three-deep2 with five modules (crossed under --motion hexbot)")
    fig14 = [Feature("BASIC", 5), Feature("SINGLE", 1), Feature("LEFT", 5), Feature("THREE", 4),
             Feature("RIGHT", 5), Feature("BASIC", 2), Feature("SINGLE", 3)]
    out["fig14"] = (build(fig14, 11, name="fig14", steps=[0, 0, -1, 1]),
                    "a long surface with every bridge type and eleven modules (Fig. 14)")
    # under the hexbot model its pockets hold 12 modules for good (Fill cells)
    out["fig14-n13"] = (build(fig14, 13, name="fig14-n13", steps=[0, 0, -1, 1]),
                        "fig14 with thirteen modules (crossed under --motion hexbot)")
    return out


def _steps(n: int) -> Surface:
    width = 2 * n + 26
    tops = {}
    for x in range(width):
        tops[x] = 0 if x < n + 5 else 1 if x < n + 9 else 3 if x < n + 13 else 2 \
            if x < n + 17 else 0
    return _with_ends(_surface(tops, set()), tops, n, "steps")


def write_bank(folder: Path = MAPS) -> list[Path]:
    folder.mkdir(parents=True, exist_ok=True)
    written = []
    for name, (surface, description) in bank().items():
        path = folder / f"{name}.txt"
        path.write_text(map_text(surface, f"{name}: {description}\n"
                                          "generated by python -m hexbot.planning.traversal.bank"))
        written.append(path)
    return written


if __name__ == "__main__":
    for path in write_bank():
        print(path)
