"""FINDBRIDGECELLS: narrow pockets and the cells that bridge them.

Step 3 finds the non-consecutive perimeter (NCP) pairs of ``layer1`` (cells
that touch but whose perimeter numbers are not consecutive) and keeps the
outermost ones as bridge identifiers (BI). Step 4 (SETBRIDGINGCELLS)
classifies each BI by the cells ``d`` and ``e`` on its line (Fig. 5):
neither a surface cell SINGLE, both BASIC, ``d`` only LEFT, ``e`` only
RIGHT, and places Bridge, TempSupport and Support cells; step 5 finds
3-cell bridges across openings of three free cells, whose middle cell lies
in ``layer2``. Bridges covered by a larger one are dropped. The letters
follow Fig. 5 with the pocket on the clockwise side of ``x -> y``; the
derivation of each placement is in docs/traversal.md.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from hexbot.errors import ScenarioError
from hexbot.planning.traversal.fill import fill_cells
from hexbot.planning.traversal.layers import Layer, layer1, layer2
from hexbot.planning.traversal.motion import next_rotation, rotation_to
from hexbot.planning.traversal.surface import Surface
from hexbot.protocol.lattice import SIDES, Cell, distance, neighbor, side_towards, wrap

KINDS = ("SINGLE", "BASIC", "LEFT", "RIGHT", "THREE")
SHAPES = ("straight", "curved-symmetric", "curved-left", "curved-right")
MIN_THREE_SPAN = 4  # a 3-bridge must cut off at least three perimeter cells


@dataclass(frozen=True)
class Letters:
    """The cells around a BI pair ``x, y`` named as in Fig. 5."""

    x: Cell
    y: Cell
    a: Cell
    b: Cell
    c: Cell
    d: Cell
    e: Cell
    f: Cell
    g: Cell
    h: Cell


def letters(x: Cell, y: Cell) -> Letters:
    k = side_towards(x, y)
    if k is None:
        raise ValueError(f"{x} and {y} are not adjacent")
    return Letters(x, y, a=neighbor(x, k - 2), b=neighbor(x, k - 1), c=neighbor(y, k - 1),
                   d=neighbor(x, k + 3), e=neighbor(y, k), f=neighbor(x, k + 2),
                   g=neighbor(x, k + 1), h=neighbor(y, k + 1))


@dataclass
class Group:
    """One bridge: the cells where modules stop, and what they wait for."""

    kind: str
    span: tuple[int, int]  # layer1 numbers of the BI pair (or of the 3-bridge's ends)
    bridge: tuple[Cell, ...]
    pocket: frozenset[Cell]  # perimeter cells cut off by the bridge
    pocket_length: int
    temp_support: Cell | None = None
    support: Cell | None = None
    reverse: bool = True  # TempSupport -> Support: CCW about the Bridge, else on clockwise
    through: bool = False  # the Bridge module leaves through the pocket (it is the last)
    shape: str = ""
    pass_cells: dict[Cell, Cell] = field(default_factory=dict)
    # every cell whose entry counts as a pass, also with neighbouring bridges held
    pass_sets: dict[Cell, frozenset[Cell]] = field(default_factory=dict)

    @property
    def cells(self) -> tuple[Cell, ...]:
        extra = tuple(c for c in (self.temp_support, self.support) if c is not None)
        return self.bridge + tuple(dict.fromkeys(extra))

    def passes_needed(self, cell: Cell, n: int) -> int:
        """Passing modules a Bridge module waits for: n - 1, except that the module
        of a TempSupport/Support pair never passes over its Bridge (n - 2)."""
        return n - 1 - (1 if self.support is not None else 0)

    def as_json(self) -> dict:
        out: dict = {"kind": self.kind, "cells": [list(c) for c in self.bridge],
                     "span": list(self.span), "pocket_length": self.pocket_length}
        if self.temp_support is not None:
            out["temp_support"] = list(self.temp_support)
            out["support"] = list(self.support) if self.support else None
        if self.shape:
            out["shape"] = self.shape
        return out


@dataclass
class BridgeMap:
    """The preprocessing result every module computes from the same map."""

    surface: Surface
    model: str
    layer1: Layer
    layer2: Layer
    ncp: list[tuple[int, int]]
    bis: list[tuple[int, int]]
    groups: list[Group]
    dropped: list[Group]
    fills: tuple[Cell, ...] = ()  # hexbot model: cells the first modules hold for good

    @property
    def crossing(self) -> int:
        """Modules that go on to the goal (those in Fill cells stay)."""
        return self.surface.n - len(self.fills)

    def role_of(self) -> dict[Cell, tuple[str, Group]]:
        roles: dict[Cell, tuple[str, Group]] = {}
        for group in self.groups:
            for cell in group.bridge:
                roles[cell] = ("Bridge", group)
            if group.temp_support is not None:
                roles.setdefault(group.temp_support, ("TempSupport", group))
            if group.support is not None and group.support != group.temp_support:
                roles[group.support] = ("Support", group)
        return roles


def ncp_pairs(layer: Layer) -> list[tuple[int, int]]:
    """Pairs of perimeter numbers (i < j) of touching, non-consecutive cells."""
    pairs = []
    for i, cell in enumerate(layer.cells):
        for side in SIDES:
            other = neighbor(cell, side)
            if other not in layer.visits or other == cell:
                continue
            mine, theirs = layer.visits[cell], layer.visits[other]
            if any(abs(p - q) == 1 for p in mine for q in theirs):
                continue
            pairs.extend((i, j) for j in theirs if j > i + 1)
    return sorted(set(pairs))


def outermost(spans: list[tuple[int, int]]) -> list[tuple[int, int]]:
    """Spans not inside (nor crossing into) an earlier, larger one."""
    kept: list[tuple[int, int]] = []
    reach = -1
    for i, j in sorted(spans, key=lambda s: (s[0], -s[1])):
        if i >= reach:
            kept.append((i, j))
            reach = j
        # else: inside (or crossing) a kept span
    return kept


def theorem1_problems(surface: frozenset[Cell], x: Cell, y: Cell) -> list[str]:
    """Theorem 1: a, b, c, g free; x touches d or f; y touches e or h."""
    t = letters(x, y)
    problems = [f"{name} {list(getattr(t, name))} is a surface cell"
                for name in "abcg" if getattr(t, name) in surface]
    if t.d not in surface and t.f not in surface:
        problems.append("x touches neither d nor f")
    if t.e not in surface and t.h not in surface:
        problems.append("y touches neither e nor h")
    return problems


def classify(surface: frozenset[Cell], x: Cell, y: Cell) -> str:
    t = letters(x, y)
    d, e = t.d in surface, t.e in surface
    return "BASIC" if d and e else "SINGLE" if not (d or e) else "LEFT" if d else "RIGHT"


def _ccw_path(surface: frozenset[Cell], bridge: Cell, start: Cell, goal: Cell,
              model: str) -> tuple[Cell, ...] | None:
    """Counterclockwise rolls about ``bridge`` from ``start`` to ``goal``, or None
    when the model does not allow one of them on the bare surface."""
    occupied = (surface | {bridge}).__contains__
    cell, path = start, []
    for _ in range(6):
        if cell == goal:
            return tuple(path)
        side = side_towards(cell, bridge)
        if side is None:
            return None
        rotation = rotation_to(wrap(side + 1), "CCW")
        rolled = next_rotation(cell, bridge, "CCW", occupied, model)
        if rolled is None or rolled.rotation != rotation:
            return None
        cell = rolled.dst
        path.append(cell)
    return None


def _cw_reaches(held: frozenset[Cell], layer: Layer, start: int, goal: Cell, model: str,
                limit: int) -> bool:
    return _route(held.__contains__, layer, start, model, lambda c: c == goal,
                  limit) is not None


def set_bridging_cells(bmap_surface: frozenset[Cell], layer: Layer, span: tuple[int, int],
                       model: str) -> Group:
    """SETBRIDGINGCELLS for one BI (Fig. 8 plus the placements derived in the docs)."""
    i, j = span
    x, y = layer.cells[i], layer.cells[j]
    t = letters(x, y)
    kind = classify(bmap_surface, x, y)
    inside = layer.cells[i + 1: j]
    pocket = frozenset(inside)
    length = len(pocket)
    if kind == "BASIC":
        return Group(kind, span, (x, y), pocket, length)
    neck = t.f in bmap_surface and t.h in bmap_surface
    if kind == "SINGLE" or neck:
        return Group(kind, span, (t.g,), pocket - {t.g}, length)
    if length <= 2:
        return Group(kind, span, (inside[-1],), pocket - {inside[-1]}, length)
    if kind == "LEFT":
        temp, bridge, support = inside[0], t.g, inside[-2]
    else:
        bridge, temp, support = t.g, inside[1], inside[-1]
    reverse = _ccw_path(bmap_surface, bridge, temp, support, model) is not None
    if kind == "LEFT" and not reverse and not _cw_reaches(
            bmap_surface | {bridge}, layer, i + 1, support, model, 4 * length + 8):
        # the way on through the sealed pocket circles without reaching the Support
        # cell (random:1102): the TempSupport module stays where it is instead
        support = temp
    if kind == "RIGHT" and not reverse:
        # The TempSupport module cannot reach the Support cell past the held
        # Bridge: one Bridge module, which leaves last through the pocket.
        return Group(kind, span, (bridge,), pocket - {bridge}, length, through=True)
    return Group(kind, span, (bridge,), pocket - {bridge}, length, temp_support=temp,
                 support=support, reverse=reverse)


def three_candidates(surface: frozenset[Cell],
                     layer: Layer) -> list[tuple[int, int, Cell, str]]:
    """(i, j, w, shape): perimeter cells ``u = i`` and ``v = j`` two apart, the
    free common neighbour ``w`` off layer1 (a layer2 cell), and surface cells
    touching ``u`` and ``v`` four apart, so that ``u, w, v`` is the whole
    width of a 3-cell opening between them."""
    out = []
    for i, u in enumerate(layer.cells):
        for s1 in SIDES:
            for s2 in (s1, wrap(s1 + 1)):
                w = neighbor(u, s1)
                v = neighbor(w, s2)
                if v not in layer.visits or w in surface or w in layer.visits:
                    continue
                shape = _opening_shape(surface, u, w, v)
                if shape is None:
                    continue
                out.extend((i, j, w, shape) for j in layer.visits[v] if j - i >= MIN_THREE_SPAN)
    return out


def _opening_shape(surface: frozenset[Cell], u: Cell, w: Cell, v: Cell) -> str | None:
    """The shape of the geodesic anchor-u-w-v-anchor (None: no such anchors).

    Directions s0..s3 of its four steps: all equal is ``straight``; mirror
    symmetric about ``w`` (as many bends at each end) is ``curved-symmetric``;
    otherwise the end with the bend names it (``curved-left`` at ``u``)."""
    shapes = []
    for su in (neighbor(u, s) for s in SIDES):
        if su not in surface or distance(su, w) != 2:
            continue
        for sv in (neighbor(v, s) for s in SIDES):
            if sv not in surface or distance(sv, w) != 2 or distance(su, sv) != 4:
                continue
            steps = [side_towards(p, q) for p, q in ((su, u), (u, w), (w, v), (v, sv))]
            if len(set(steps)) == 1:
                shapes.append("straight")
            elif (steps[0] == steps[1]) == (steps[2] == steps[3]):
                shapes.append("curved-symmetric")
            else:
                shapes.append("curved-left" if steps[0] != steps[1] else "curved-right")
    return min(shapes, key=SHAPES.index) if shapes else None


def _pass_cells(surface: frozenset[Cell], layer: Layer, group: Group, model: str) -> bool:
    """For each Bridge cell, the last cell next to it on the way over the held
    bridge: a Bridge module counts the modules entering it. False when the
    way over does not come back to the perimeter beyond the pocket."""
    i, j = group.span
    extra = set(group.bridge) | ({group.support} if group.support else set())

    def held(cell: Cell) -> bool:  # no copy of the surface: O(span) per bridge
        return cell in surface or cell in extra

    start = max(i - 2, 0)
    cell, pivot = layer.cells[start], layer.pivots[start]
    route = [cell]
    for _ in range(4 * (j - i) + 32):
        rolled = next_rotation(cell, pivot, "CW", held, model)
        if rolled is None:
            return False
        cell, pivot = rolled.dst, rolled.substrate
        route.append(cell)
        if cell in layer.visits and max(layer.visits[cell]) > j:
            break
    else:
        return False
    for b in group.bridge:
        near = [c for c in route if distance(c, b) == 1]
        if not near:
            return False
        group.pass_cells[b] = near[-1]
    return True


def _within(cell: Cell, radius: int) -> list[Cell]:
    x, y = cell
    return [(x + dx, y + dy) for dx in range(-radius, radius + 1)
            for dy in range(max(-radius, -dx - radius), min(radius, -dx + radius) + 1)]


def _neighbours(groups: list[Group], radius: int) -> dict[int, list[Group]]:
    """id(group) -> the other groups with a held cell within ``radius`` of one
    of its own (a cell index: O(groups), not O(groups^2))."""
    owner: dict[Cell, list[Group]] = {}
    for group in groups:
        for cell in _held_cells(group):
            owner.setdefault(cell, []).append(group)
    out: dict[int, list[Group]] = {}
    for group in groups:
        found: dict[int, Group] = {}
        for cell in _held_cells(group):
            for near in _within(cell, radius):
                for other in owner.get(near, ()):
                    if other is not group:
                        found[id(other)] = other
        out[id(group)] = list(found.values())
    return out


def _drop_crowding_dents(groups: list[Group]) -> tuple[list[Group], list[Group]]:
    """A bridge over a pocket of one cell only saves moves (the paper: not
    needed to avoid collisions). Next to another bridge its module can be
    walled in by that bridge's module, which waits for it to pass
    (random:52): drop it there."""
    touching = _neighbours(groups, 1)
    crowded = [g for g in groups if g.pocket_length <= 1 and touching[id(g)]]
    return [g for g in groups if g not in crowded], crowded


def _held_cells(group: Group) -> set[Cell]:
    return set(group.bridge) | ({group.support} if group.support else set())


def _neighbour_pass_cells(surface: frozenset[Cell], layer: Layer, groups: list[Group],
                          model: str) -> None:
    """Pass cells when a neighbouring bridge is held too: its module may stop in
    this bridge's pass cell, and the next ones then roll over it and enter
    another cell next to the Bridge module (random:52, :48 deadlocked)."""
    neighbours = _neighbours(groups, 2)
    for group in groups:
        group.pass_sets = {b: frozenset({c}) for b, c in group.pass_cells.items()}
        own = _held_cells(group)
        near = neighbours[id(group)]
        if not near:
            continue
        variants = [_held_cells(other) for other in near]
        if len(near) > 1:
            variants.append(set().union(*variants))
        i, j = group.span
        # the way ends past this bridge, or past the neighbours it goes round
        limit = 4 * (max([j] + [other.span[1] for other in near]) - i) + 64
        for extra in variants:
            held_cells = own | extra
            start = max(i - 2, 0)
            while start > 0 and layer.cells[start] in held_cells:
                start -= 1
            way = _route(lambda c, h=held_cells: c in surface or c in h, layer, start, model,
                         lambda c, h=held_cells, j=j: c in layer.visits and c not in h
                         and max(layer.visits[c]) > j, limit)
            if way is None:
                continue
            route = way[0]
            for b in group.bridge:
                last = [c for c in route if distance(c, b) == 1]
                if last:
                    group.pass_sets[b] = group.pass_sets[b] | {last[-1]}


def _route(held, layer: Layer, start: int, model: str, stop,
           limit: int) -> tuple[list[Cell], Cell] | None:
    """The wall-following way of a module from ``layer.cells[start]`` over the
    ``held`` cells until ``stop(cell)``, and its substrate there; None when it
    gets stuck first."""
    cell, pivot = layer.cells[start], layer.pivots[start]
    route = [cell]
    for _ in range(limit):
        rolled = next_rotation(cell, pivot, "CW", held, model)
        if rolled is None:
            return None
        cell, pivot = rolled.dst, rolled.substrate
        route.append(cell)
        if stop(cell):
            return route, pivot
    return None


def _narrow(route: list[Cell]) -> tuple[Cell, Cell] | None:
    """Two touching cells of a route three or more moves apart: two moving
    modules, two free cells apart along the route, would touch there."""
    first_at: dict[Cell, int] = {}
    for q, cell in enumerate(route):
        for side in SIDES:
            p = first_at.get(neighbor(cell, side))
            if p is not None and q - p >= 3:
                return route[p], cell
        first_at.setdefault(cell, q)
    return None


def three_is_safe(surface: frozenset[Cell], layer: Layer, group: Group, model: str,
                  start: int | None = None, extra: frozenset[Cell] = frozenset()) -> bool:
    """A 3-bridge that leaves a narrow pocket on the way over it (while it is
    formed, one cell after the other, or once it is held) is not safe: a
    moving module would touch the one behind it there (random:150, :167).
    ``extra``: cells of neighbouring bridges held as well."""
    i, j = group.span
    start = max(i - 3, 0) if start is None else start
    held_cells = set(extra)  # no copy of the surface: O(span) per 3-bridge

    def held(cell: Cell) -> bool:
        return cell in surface or cell in held_cells
    limit = 4 * (j - i) + 32
    order: list[tuple[Cell, Cell]] = []  # Bridge cells as they are taken, and the pivot
    while True:
        missing = [c for c in group.bridge if c not in held_cells]

        def stop(cell: Cell, missing: list[Cell] = missing) -> bool:
            if missing:
                return cell in missing
            return cell in layer.visits and max(layer.visits[cell]) > j + 3
        way = _route(held, layer, start, model, stop, limit)
        if way is None or _narrow(way[0]) is not None:
            return False
        if not missing:
            break
        order.append((way[0][-1], way[1]))
        held_cells.add(way[0][-1])
    # released in the order they were taken: each must have a way out while the
    # later ones are still held (a corner cell walled in by the next: random:944)
    for k, (cell, pivot) in enumerate(order):
        later = {c for c, _ in order[k + 1:]} | extra
        if next_rotation(cell, pivot, "CW", lambda c, h=later: c in surface or c in h, model,
                         group.pocket.__contains__) is None:
            return False
    return True


def _select(s: frozenset[Cell], layer: Layer, candidates: list[Group],
            model: str) -> tuple[list[Group], list[Group]]:
    """The outermost candidates whose way over comes back to the perimeter,
    without one-cell-pocket bridges crowding another bridge."""
    keep_spans = set(outermost([g.span for g in candidates]))
    groups, dropped = [], []
    seen: set[tuple[int, int]] = set()
    for group in sorted(candidates, key=lambda g: (g.span[0], -g.span[1], g.kind == "THREE")):
        if group.span in keep_spans and group.span not in seen and _pass_cells(
                s, layer, group, model):
            groups.append(group)
            seen.add(group.span)
        else:
            dropped.append(group)
    groups, crowded = _drop_crowding_dents(groups)
    return groups, dropped + crowded


def _start_before(group: Group, near: list[Group]) -> int:
    """Where a check of ``group`` starts: three cells before it, before any
    bridge next to it (not from inside a pocket)."""
    starts = [group.span[0] - 3] + [other.span[0] - 1 for other in near
                                    if other.span[0] < group.span[0]]
    return max(min(starts), 0)


def _near_held(group: Group, near: list[Group]) -> frozenset[Cell]:
    """The cells of the bridges ``near`` within two cells of ``group``."""
    own = _held_cells(group)
    return frozenset(c for other in near for c in _held_cells(other)
                     if any(distance(c, b) <= 2 for b in own))


def _holds_fill(group: Group, fills: tuple[Cell, ...]) -> bool:
    """A Fill cell in the pocket (next to a cell of it or one of the bridge's
    cells): its module must go into the pocket the bridge closes, and it
    stops there for good (random:13, :24)."""
    near = group.pocket | set(group.cells)
    return any(f in near or any(neighbor(f, s) in near for s in SIDES) for f in fills)


GAP = 4  # moves between two moving modules one after the other (2 free cells: 3)


def _touching_within(route: list[Cell], longest: int) -> tuple[Cell, Cell] | None:
    """Two touching cells of a route 3..``longest`` moves apart: ``longest`` is
    how far apart the first and last of the modules crossing can be."""
    for q, cell in enumerate(route):
        for p in range(max(q - longest, 0), q - 2):
            if distance(route[p], cell) == 1:
                return route[p], cell
    return None


def _check_open_pocket(surface: frozenset[Cell], layer: Layer, group: Group,
                       fills: tuple[Cell, ...], n: int, model: str) -> None:
    """Without its bridge a pocket is crossed by every module after the last
    one that stays in it (or by all when none stays). Where its way is narrow
    (two touching cells three or more moves apart), two of them would touch:
    the map is refused (random:13). Modules cross about GAP moves apart, so
    cells farther apart along the way than the first and last of them can be
    do not count (random:98, a pocket of eleven cells, is crossed)."""
    inside = [k for k, f in enumerate(fills) if _holds_fill(group, (f,))]
    through = n - (inside[-1] + 1 if inside else len(fills))
    if through < 2:
        return
    i, j = group.span
    way = _route(surface.__contains__, layer, max(i - 2, 0), model,
                 lambda c: c in layer.visits and max(layer.visits[c]) > j, 4 * (j - i) + 32)
    narrow = _touching_within(way[0], GAP * (through - 1) + 1) if way is not None else None
    if way is None or narrow is not None:
        where = f"cells {list(narrow[0])} and {list(narrow[1])} touch" if narrow else \
            "its way is stuck"
        why = "a Fill cell lies in it" if inside else "its Bridge cell cannot be entered"
        raise ScenarioError(
            f"the {group.kind} pocket at {list(group.bridge[0])} cannot be bridged by rigid "
            f"modules ({why}) and {through} modules would cross it where {where}: this surface "
            "cannot be crossed by rigid modules")


def _can_form(surface: frozenset[Cell], layer: Layer, group: Group, model: str) -> bool:
    """The bridge can be formed under the model: the module that takes its
    second cell (the Bridge cell after a TempSupport, ``y`` after ``x`` in a
    BASIC bridge) gets there with the first held. Under the hexbot model the
    roll into ``g`` of a LEFT pocket can sweep the far wall (random:98)."""
    if group.temp_support is not None:
        first, second = group.temp_support, group.bridge[0]
    elif group.kind == "BASIC":
        first, second = group.bridge
    else:
        return True
    i, j = group.span
    start = max(i - 2, 0)
    return _route(lambda c: c in surface or c == first, layer, start, model,
                  lambda c: c == second, 4 * (j - i) + 32) is not None


def find_bridge_cells(surface: Surface, model: str = "deformable", *, bridges: bool = True,
                      three: bool = True) -> BridgeMap:
    """FINDBRIDGECELLS (Fig. 7) on a map; under the hexbot model on the
    surface with its Fill cells held (:mod:`.fill`). A map the perimeter
    refuses is a ScenarioError naming its file, as parsing errors do."""
    try:
        return _find_bridge_cells(surface, model, bridges, three)
    except ScenarioError as exc:
        if not surface.source:
            raise
        raise ScenarioError(f"{surface.source}: {exc}") from None


def _find_bridge_cells(surface: Surface, model: str, bridges: bool, three: bool) -> BridgeMap:
    fills = fill_cells(surface.surface, surface.modules, surface.goals, model) \
        if model == "hexbot" else ()
    s = surface.surface | frozenset(fills)
    first = layer1(s, surface.modules, surface.goals, model)
    second = layer2(s, first, model)
    pairs = ncp_pairs(first)
    bis = outermost(pairs)
    candidates: list[Group] = []
    unsafe: list[Group] = []
    if bridges:
        for span in bis:
            candidates.append(set_bridging_cells(s, first, span, model))
        if three:
            for i, j, w, shape in three_candidates(s, first):
                u, v = first.cells[i], first.cells[j]
                inside = frozenset(first.cells[i + 1: j])
                three_group = Group("THREE", (i, j), (u, w, v), inside - {u, v}, len(inside),
                                    shape=shape)
                if three_is_safe(s, first, three_group, model):
                    candidates.append(three_group)
                else:
                    unsafe.append(three_group)
    if model == "hexbot":  # docs/traversal.md, "Fill cells and bridges"
        clash = [g for g in candidates if _holds_fill(g, fills)
                 or not _can_form(s, first, g, model)]
        for group in clash:
            _check_open_pocket(s, first, group, fills, surface.n, model)
        unsafe += clash
        candidates = [g for g in candidates if g not in clash]
    while True:
        groups, dropped = _select(s, first, candidates, model)
        # a 3-bridge must also be safe with the bridges next to it held (random:538)
        near = _neighbours(groups, 2)
        late = [g for g in groups if g.kind == "THREE" and not three_is_safe(
            s, first, g, model, _start_before(g, near[id(g)]),
            _near_held(g, near[id(g)]))]
        if not late:
            break
        unsafe += late
        candidates = [g for g in candidates if g not in late]
    for group in groups:
        _check_pocket_ahead_of_chain(first, group, surface.n)
    _neighbour_pass_cells(s, first, groups, model)
    return BridgeMap(surface, model, first, second, pairs, bis, groups, dropped + unsafe, fills)


def _check_pocket_ahead_of_chain(layer: Layer, group: Group, n: int) -> None:
    """A pocket must begin past the chain. One whose first cell is a module's
    (the front module stands at its edge) is crossed by the modules behind
    before any of them enters its Bridge cell: they roll over the front
    module, not into the pocket. The front module then enters the Bridge cell
    last of all and waits for ``n - 1`` passes that already happened: a
    deadlock (session 33's audit). The paper starts the chain before the first
    pocket; such a map is refused."""
    first = group.span[0]
    if first < n:
        raise ScenarioError(
            f"the {group.kind} pocket at {list(group.bridge[0])} begins at the module in "
            f"{list(layer.cells[first])}: the modules behind it would cross the pocket "
            "before its bridge forms; start the chain at least one cell before the pocket")
