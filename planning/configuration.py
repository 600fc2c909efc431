"""Configurations: which cells hold which module, facing which way.

A configuration maps axial cells (Table 4-1) to :class:`Module` records.
The orientation of a module is ``Yref`` of the firmware: how many sides its
body frame is turned clockwise from the global frame (0..5); see
:func:`hexbot.planning.commands.body_index` for the one place that uses it.

Connectivity is the thesis' connectivity graph (one node per module, one
edge per pair of touching modules), searched breadth-first by
:func:`contact_hops`, the one search of that graph in the planner. The
thesis' own criterion (number of zero Laplacian eigenvalues, Fig. 4-22) is
:func:`laplacian_components`, used by the tests as a cross-check.

networkx did this once; it was dropped: building its graph made each
connectivity test 2.5 to 5 times slower than the search here, and the
planner benchmark 6-8 % slower (docs/planning.md, Performance).
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Iterator, Mapping
from dataclasses import dataclass

import numpy as np

from hexbot.planning.hexlattice import Cell, column_major_key, neighbors


@dataclass(frozen=True)
class Module:
    id: int
    orientation: int = 0  # Yref: clockwise sixth-turns from the global frame


class Configuration(Mapping[Cell, Module]):
    """An immutable map cell -> module. Hashable; equality compares cells and modules."""

    __slots__ = ("_cells", "_hash")

    def __init__(self, modules: Mapping[Cell, Module] | None = None) -> None:
        self._cells: dict[Cell, Module] = dict(modules or {})
        self._hash: int | None = None

    # -- construction ------------------------------------------------------
    @classmethod
    def from_cells(cls, cells: Iterable[Cell], first_id: int = 1) -> Configuration:
        """Number the modules in reading order (top row first, left to right)."""
        ordered = sorted(set(cells), key=lambda c: (-c[1], c[0]))
        return cls({c: Module(first_id + i) for i, c in enumerate(ordered)})

    # -- mapping protocol ----------------------------------------------------
    def __getitem__(self, cell: Cell) -> Module:
        return self._cells[cell]

    def __iter__(self) -> Iterator[Cell]:
        return iter(self._cells)

    def __len__(self) -> int:
        return len(self._cells)

    def __contains__(self, cell: object) -> bool:
        return cell in self._cells

    def __hash__(self) -> int:
        if self._hash is None:
            self._hash = hash(frozenset(self._cells.items()))
        return self._hash

    def __eq__(self, other: object) -> bool:
        if isinstance(other, Configuration):
            return self._cells == other._cells
        return NotImplemented

    def __repr__(self) -> str:
        return f"Configuration({len(self)} modules)"

    # -- views -------------------------------------------------------------
    @property
    def cells(self) -> frozenset[Cell]:
        return frozenset(self._cells)

    def cell_of(self, module_id: int) -> Cell:
        for cell, module in self._cells.items():
            if module.id == module_id:
                return cell
        raise KeyError(module_id)

    def moved(self, src: Cell, dst: Cell, orientation: int | None = None) -> Configuration:
        """A copy with the module at ``src`` moved to the empty cell ``dst``."""
        if src not in self._cells:
            raise ValueError(f"no module at {src}")
        if dst in self._cells:
            raise ValueError(f"cell {dst} is occupied")
        cells = dict(self._cells)
        module = cells.pop(src)
        if orientation is not None:
            module = Module(module.id, orientation % 6)
        cells[dst] = module
        return Configuration(cells)


# --- graph algorithms (work on any set of cells) ------------------------------


def occupied_neighbors(cells: frozenset[Cell] | set[Cell], cell: Cell) -> int:
    return sum(1 for n in neighbors(cell) if n in cells)


def contact_hops(cells: set[Cell] | frozenset[Cell], root: Cell) -> dict[Cell, int]:
    """Contact hops from the module at ``root`` to every module it reaches
    (breadth-first over the connectivity graph of Fig. 4-20)."""
    hops = {root: 0}
    frontier = [root]
    depth = 0
    while frontier:
        depth += 1
        reached = []
        for cell in frontier:
            for n in neighbors(cell):
                if n in cells and n not in hops:
                    hops[n] = depth
                    reached.append(n)
        frontier = reached
    return hops


def is_connected(cells: Iterable[Cell]) -> bool:
    """True when every module reaches every other through touching modules."""
    cells = set(cells)
    return len(cells) <= 1 or len(contact_hops(cells, next(iter(cells)))) == len(cells)


def components(cells: Iterable[Cell]) -> int:
    """Number of connected pieces."""
    left = set(cells)
    count = 0
    while left:
        left.difference_update(contact_hops(left, next(iter(left))))
        count += 1
    return count


def _cut_vertices(cells: Iterable[Cell], count: Callable[[set[Cell]], int]) -> set[Cell]:
    """Modules whose removal leaves more pieces, by the piece counter ``count``."""
    cells = set(cells)
    base = count(cells)
    return {c for c in cells if count(cells - {c}) > base}


def articulation_points(cells: Iterable[Cell]) -> set[Cell]:
    """Modules whose removal disconnects the others (Fig. 4-21), in one depth-first
    pass (Hopcroft-Tarjan low points, iterative: no recursion limit at 10,000 modules).

    The planners call it once per moved module, so it must stay linear; the
    tests check it against removing each module and counting pieces, and
    against the thesis' Laplacian count.
    """
    cells = set(cells)
    depth: dict[Cell, int] = {}
    low: dict[Cell, int] = {}
    cuts: set[Cell] = set()
    for root in cells:
        if root in depth:
            continue
        depth[root] = low[root] = 0
        root_children = 0
        stack = [(root, None, iter(neighbors(root)))]
        while stack:
            cell, parent, rest = stack[-1]
            for n in rest:
                if n not in cells or n == parent:
                    continue
                if n in depth:
                    low[cell] = min(low[cell], depth[n])
                    continue
                depth[n] = low[n] = depth[cell] + 1
                stack.append((n, cell, iter(neighbors(n))))
                break
            else:
                stack.pop()
                if parent is None:
                    continue
                low[parent] = min(low[parent], low[cell])
                if parent == root:
                    root_children += 1
                elif low[cell] >= depth[parent]:
                    cuts.add(parent)
        if root_children > 1:
            cuts.add(root)
    return cuts


def articulation_points_by_removal(cells: Iterable[Cell]) -> set[Cell]:
    """The same, by definition: remove each module and count the pieces (quadratic)."""
    return _cut_vertices(cells, components)


def laplacian_components(cells: Iterable[Cell], tol: float = 1e-9) -> int:
    """Connected components as the number of zero eigenvalues of the Laplacian (Fig. 4-22)."""
    ordered = sorted(set(cells), key=column_major_key)
    if not ordered:
        return 0
    index = {c: i for i, c in enumerate(ordered)}
    lap = np.zeros((len(ordered), len(ordered)))
    for c, i in index.items():
        for n in neighbors(c):
            j = index.get(n)
            if j is not None:
                lap[i, j] = -1.0
                lap[i, i] += 1.0
    eigenvalues = np.linalg.eigvalsh(lap)
    return int(np.sum(np.abs(eigenvalues) < tol))


def laplacian_articulation_points(cells: Iterable[Cell]) -> set[Cell]:
    """Articulation points by the thesis' method: remove a node, count components again."""
    return _cut_vertices(cells, laplacian_components)


def linear_index(cell: Cell, height: int, origin: Cell = (0, 0)) -> int:
    """MATLAB linear (column-major, 1-based) index of ``cell`` in a ``height``-row matrix
    whose bottom-left cell is ``origin`` (the node ids of Fig. 4-19)."""
    row = height - (cell[1] - origin[1])  # 1-based, row 1 on top
    col = cell[0] - origin[0] + 1
    return (col - 1) * height + row
