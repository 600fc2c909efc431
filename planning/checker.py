"""An independent checker of plans, for tests and the benchmark.

It shares nothing with the planners but the data: the rotation geometry is
read from :mod:`hexbot.protocol.rotation_geometry` (Table 4-3) through
``Rotation.at``, connectivity is counted by
:func:`scipy.sparse.csgraph.connected_components`, and the configuration is
replayed here as a plain dict. For every time step it checks:

* each move's module stands at its start cell, and the row of Table 4-3 it
  names (joint, direction) takes that cell to its end cell over its substrate;
* the substrate is held by a module that does not move in this step, the
  end cell and the three swept cells are free of modules that stay put, and
  no two moves of the step need the same cell;
* the modules that stay put are connected (so every configuration during the
  step is: each mover touches its substrate all along), the fixed module
  (bolted to the base) never moves;

and at the end that the goal cells are filled.

Speed: a step of one move removes one module; if its occupied neighbours
form one contiguous arc the rest stays connected (any path through it can go
round the arc), so the component count runs only for the other steps.
"""

from __future__ import annotations

from collections import deque
from dataclasses import dataclass

import numpy as np
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import connected_components

from hexbot.planning.configuration import Configuration
from hexbot.planning.plan import Step
from hexbot.protocol.lattice import SIDES, Cell, neighbor
from hexbot.protocol.rotation_geometry import ROTATIONS, Rotation


@dataclass(frozen=True)
class CheckReport:
    ok: bool
    problem: str = ""
    steps: int = 0
    moves: int = 0


def pieces(cells: set[Cell]) -> int:
    """Connected pieces of ``cells`` (contact graph), by scipy."""
    if not cells:
        return 0
    index = {c: i for i, c in enumerate(cells)}
    rows, cols = [], []
    for c, i in index.items():
        for side in (1, 2, 3):  # each contact once
            j = index.get(neighbor(c, side))
            if j is not None:
                rows.append(i)
                cols.append(j)
    graph = coo_matrix((np.ones(len(rows), dtype=np.int8), (rows, cols)),
                       shape=(len(index), len(index)))
    return connected_components(graph, directed=False)[0]


def _one_arc(cells: set[Cell] | dict, cell: Cell) -> bool:
    """Do the occupied neighbours of ``cell`` form a single contiguous arc (or ring)?"""
    x, y = cell
    around = [(x + dx, y + dy) in cells for dx, dy in _OFFSETS]
    starts = sum(1 for k in range(6) if around[k] and not around[k - 1])
    return starts <= 1


#: the six neighbours' offsets, sides 1..6
_OFFSETS = [(neighbor((0, 0), s)) for s in SIDES]


#: Table 4-3 as offsets from the mobile module: (joint, direction) -> substrate,
#: end cell, the three swept cells (read once from Rotation.at, per move it is slow)
_TABLE = {(r.joint, r.direction): (r.substrate, r.goal, *r.swept) for r in ROTATIONS}


def _around(cell: Cell) -> list[Cell]:
    x, y = cell
    return [(x + dx, y + dy) for dx, dy in _OFFSETS]


def still_one_piece(cells: set[Cell] | dict, removed: set[Cell]) -> bool:
    """Is ``cells`` without ``removed`` one piece, ``cells`` being one piece?

    Group the removed cells into clusters of touching ones. A path between two
    cells left that went through removed cells enters and leaves each cluster
    through a neighbour of it, so the rest is one piece exactly when, for every
    cluster, its neighbours left stay connected to each other (:func:`_meet`).
    That is local: a step's movers are usually far apart, and each cluster's
    neighbours meet within a few cells (or lie in one arc) when nothing splits."""
    gone = [r for r in removed if r in cells]
    seen: set[Cell] = set()
    for first in gone:
        if first in seen:
            continue
        seen.add(first)
        cluster = [first]
        for c in cluster:  # grows while iterated
            for n in _around(c):
                if n in removed and n in cells and n not in seen:
                    seen.add(n)
                    cluster.append(n)
        if len(cluster) == 1 and _one_arc(cells, first):
            continue  # its neighbours are all left (none is removed) and touch in a row
        seeds = list({n for c in cluster for n in _around(c)
                      if n in cells and n not in removed})
        if len(seeds) > 1 and not _meet(cells, removed, seeds):
            return False
    return True


def _meet(cells: set[Cell] | dict, removed: set[Cell], seeds: list[Cell]) -> bool:
    """Are ``seeds`` connected in ``cells`` without ``removed``? One breadth-first
    search from each, taking turns, searches that meet merge: they meet within a
    few cells when nothing splits; a piece cut off is found when its search runs
    dry, which the turns make cost no more than the smaller side."""
    owner = {cell: i for i, cell in enumerate(seeds)}
    parent = list(range(len(seeds)))

    def find(i: int) -> int:
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i

    frontiers = {i: deque([cell]) for i, cell in enumerate(seeds)}
    while True:
        for label in list(frontiers):
            queue = frontiers.get(label)
            if queue is None:  # merged into another search this round
                continue
            if not queue:  # this search ran dry before meeting the others: cut off
                return False
            x, y = queue.popleft()
            for dx, dy in _OFFSETS:
                n = (x + dx, y + dy)
                if n not in cells or n in removed:
                    continue
                other = owner.get(n)
                if other is None:
                    owner[n] = label
                    queue.append(n)
                    continue
                other = find(other)
                if other != label:
                    parent[other] = label
                    queue.extend(frontiers.pop(other))
                    if len(frontiers) == 1:
                        return True


def check_plan(initial: Configuration, goal: frozenset[Cell], steps: list[Step],
               fixed: Cell | None = None) -> CheckReport:
    """Replay ``steps`` from ``initial`` and report the first illegal thing."""
    where: dict[Cell, int] = {c: m.id for c, m in initial.items()}
    if pieces(set(where)) > 1:  # the step test below relies on it
        return CheckReport(False, "the initial configuration is not one piece")
    bolted = where.get(fixed) if fixed is not None else None
    moves = 0
    for t, step in enumerate(steps, start=1):
        problem = _check_step(where, step, bolted)
        if problem:
            return CheckReport(False, f"step {t}: {problem}", t - 1, moves)
        for m in step.moves:
            del where[m.src]
        for m in step.moves:
            where[m.dst] = m.module
        moves += len(step.moves)
    if set(where) != set(goal):
        missing = sorted(set(goal) - set(where))
        return CheckReport(False, f"the plan ends {len(missing)} cell(s) short of the goal "
                                  f"(e.g. {missing[:1]})", len(steps), moves)
    return CheckReport(True, "", len(steps), moves)


def _check_step(where: dict[Cell, int], step: Step, bolted: int | None) -> str:
    starts = {m.src for m in step.moves}
    if len(starts) < len(step.moves):  # a module given two moves (the replay would fail)
        seen: set[Cell] = set()
        for m in step.moves:
            if m.src in seen:
                return f"the module at {m.src} is given two moves in one step"
            seen.add(m.src)
    used: dict[Cell, int] = {}
    for m in step.moves:
        if where.get(m.src) != m.module:
            return f"module {m.module} is not at {m.src}"
        if m.module == bolted:
            return f"module {m.module} is fixed to the base and may not move"
        offsets = _TABLE.get((m.joint, m.direction))
        if offsets is None:  # not a key of the table as written: let Rotation read it
            substrate, end, swept = Rotation(m.joint, m.direction).at(m.src)
        else:
            x, y = m.src
            substrate, end, *swept = [(x + dx, y + dy) for dx, dy in offsets]
        if end != m.dst or substrate != m.substrate:
            return (f"module {m.module}: {m.direction} about joint {m.joint} from {m.src} "
                    f"ends in {end} over {substrate}, not {m.dst} over {m.substrate}")
        if substrate not in where or substrate in starts:
            return f"module {m.module}: its substrate {substrate} is empty or moving"
        if where[substrate] != m.substrate_module:
            return f"module {m.module}: the substrate at {substrate} is not module " \
                   f"{m.substrate_module}"
        for cell in (end, *swept):
            if cell in where and cell not in starts:
                return f"module {m.module}: cell {cell} is occupied by a module that stays"
        for cell in (m.src, end, *swept):
            if used.setdefault(cell, m.module) != m.module:
                return f"modules {used[cell]} and {m.module} both need cell {cell}"
    if len(step.moves) == 1 and _one_arc(where, step.moves[0].src):
        return ""
    if not still_one_piece(where, starts):
        return "the modules that stay put fall apart during the step"
    return ""
