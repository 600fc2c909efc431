"""Fill cells: where rigid HexBot modules need the first modules to stay.

Under the ``hexbot`` motion model a rotation sweeps three cells, one of
them in the second ring (Table 4-3), so a lone module that rolls into a
narrow pocket or over a sharp edge can end in a cell with no move left: the
probing module is stuck there. The paper's bridges do not help, since the
probe never gets past that cell to number the perimeter beyond it, and a
bridge of rigid modules flush with a 3-cell opening could never be released
(each of its modules needs a neighbouring Bridge cell empty to leave). The
first modules stay instead: each stops for good in a cell on its way (a
Fill cell, a Bridge that is never released) and the next ones roll over
them as over the surface.

:func:`fill_cells` finds, where the probe is stuck, the fewest Fill cells
that let the walk go on (iterative deepening over the cells of the walk
near the stuck cell, each taken in order by the module whose way passes it
first), and repeats until the walk reaches the goals. See
docs/traversal.md, "HexBot motion model".
"""

from __future__ import annotations

from collections.abc import Iterable

from hexbot.errors import ScenarioError
from hexbot.planning.traversal.layers import Stuck, layer1
from hexbot.protocol.lattice import SIDES, Cell, distance, neighbor

NEAR = 3  # Fill cells are looked for within this many cells of the last part of
WINDOW = 16  # the stuck walk (its last WINDOW cells): the pocket it went into
DEEPEST = 4  # at most this many Fill cells for one stuck place
TRIES = 60  # sequences tried at one stuck place before giving up on it
MAX_WALKS = 4000  # probe walks for the whole search (it is exponential in the depth)


class OutOfWalks(Exception):
    """The search for Fill cells took more probe walks than MAX_WALKS."""


_walks_left = [0]


def _walk(surface: frozenset[Cell], held: tuple[Cell, ...], modules: frozenset[Cell],
          goals: frozenset[Cell], model: str) -> Stuck | None:
    """None when the probe's walk reaches the goals with ``held`` held, else
    where it got stuck (with its way there)."""
    _walks_left[0] -= 1
    if _walks_left[0] < 0:
        raise OutOfWalks
    try:
        layer1(surface | frozenset(held), modules, goals, model)
    except Stuck as stuck:
        return stuck
    return None


def _in_order(surface: frozenset[Cell], fills: tuple[Cell, ...], modules: frozenset[Cell],
              goals: frozenset[Cell], model: str) -> bool:
    """Module k, with the first k - 1 Fill cells held, meets the k-th before
    any later one (a module stops in the first Fill cell it enters)."""
    for k, cell in enumerate(fills):
        stuck = _walk(surface, fills[:k], modules, goals, model)
        way = stuck.walk.cells if stuck is not None else []
        later = set(fills[k + 1:])
        for c in way:
            if c == cell:
                break
            if c in later:
                return False
        else:
            if stuck is None:  # the full walk: check it too
                try:
                    walk = layer1(surface | frozenset(fills[:k]), modules, goals, model)
                except ScenarioError:
                    return False
                for c in walk.cells:
                    if c == cell:
                        break
                    if c in later:
                        return False
                else:
                    return False
            else:
                return False
    return True


def _to_goals(cell: Cell, goals: frozenset[Cell]) -> int:
    return min(distance(cell, g) for g in goals)


def _passes(stuck: Stuck | None, best: int, goals: frozenset[Cell]) -> bool:
    """The walk reached the goals, or got stuck nearer to them than the walk
    it replaces ever came (``best``)."""
    return stuck is None or _to_goals(stuck.cell, goals) < best


EXTRA = 9  # on refusal: how many more Fill cells than modules the search tries


def fill_cells(surface: frozenset[Cell], modules: Iterable[Cell], goals: Iterable[Cell],
               model: str) -> tuple[Cell, ...]:
    """The Fill cells, in the order the modules take them (module k stays in
    the k-th). At least one module must be left to reach a goal."""
    modules, goals = frozenset(modules), frozenset(goals)
    _walks_left[0] = MAX_WALKS
    try:
        found = _fill_from(surface, modules, goals, model, (), len(modules) - 1)
    except OutOfWalks:
        found = None
    if found is None:
        raise ScenarioError(refusal(surface, modules, goals, model))
    return found


def refusal(surface: frozenset[Cell], modules: frozenset[Cell], goals: frozenset[Cell],
            model: str) -> str:
    """Why no Fill cells let a module cross, one of three reasons (the table in
    docs/traversal.md): the probe is stuck on an edge or in a pocket, and the
    Fill cells that let it on hold K >= n modules, or none was found (the
    search, with EXTRA more modules, is not exhaustive: fewest per stuck place)."""
    n = len(modules)
    _walks_left[0] = 1
    stuck = _walk(surface, (), modules, goals, model)
    assert stuck is not None
    touching = sum(1 for s in SIDES if neighbor(stuck.cell, s) in surface)
    where = "over an edge (one surface neighbour)" if touching == 1 else \
        f"in a pocket or a corner ({touching} surface neighbours)"
    _walks_left[0] = MAX_WALKS
    try:
        more = _fill_from(surface, modules, goals, model, (), n - 1 + EXTRA)
    except OutOfWalks:
        more = None
    if more is not None:
        why = (f"the Fill cells that let the walk on hold {len(more)} modules, "
               f"more than the {n - 1} of {n} that may stay")
    else:
        why = (f"no set of at most {n - 1 + EXTRA} Fill cells lets the walk on within "
               f"{MAX_WALKS} probe walks")
    return (f"{stuck} {where} under the {model} motion model; {why}: this surface cannot "
            "be crossed by rigid modules")


def _around(cells: list[Cell]):
    """Cells within NEAR of any of ``cells`` (the pocket the walk went into)."""
    return lambda cell: any(distance(cell, p) <= NEAR for p in cells)


def _fill_from(surface, modules, goals, model, fills, most):
    """Fill cells after ``fills`` up to the goals; fewest first at each stuck
    place, and the next sequence when a later stuck place runs out of
    modules (at most ``most`` Fill cells; None: none works)."""
    stuck = _walk(surface, fills, modules, goals, model)
    if stuck is None:
        return fills
    budget = min(most - len(fills), DEEPEST)
    best = min(_to_goals(c, goals) for c in stuck.walk.cells)
    near = stuck.walk.cells[-WINDOW:]
    region = _around(near)
    tried = 0
    for depth in range(1, budget + 1):
        for extra in _iter_search(surface, modules, goals, model, fills, region, best, depth):
            if not _in_order(surface, fills + extra, modules, goals, model):
                continue
            tried += 1
            rest = _fill_from(surface, modules, goals, model, fills + extra, most)
            if rest is not None:
                return rest
            if tried >= TRIES:
                return None
    return None


def _iter_search(surface, modules, goals, model, held, region, best, depth):
    """Every sequence of exactly ``depth`` Fill cells of ``region`` that lets
    the walk go on (each taken from the way the walk takes with the ones
    before it held)."""
    stuck = _walk(surface, held, modules, goals, model)
    if _passes(stuck, best, goals):
        if depth == 0:
            yield ()
        return
    if depth == 0 or stuck is None:
        return
    taken = set(held) | modules | goals
    for cell in dict.fromkeys(stuck.walk.cells):
        if cell in taken or not region(cell):
            continue
        for rest in _iter_search(surface, modules, goals, model, held + (cell,), region, best,
                                 depth - 1):
            yield (cell,) + rest
