"""Layer 2: electrons, voids, mobile electrons and potential voids.

Mirrors ``FindVE``, ``Mobile``, ``HexCGT`` and ``PV`` of Appendix C on sets
of cells instead of padded matrices. ``find`` order of MATLAB (column-major)
is :func:`~hexbot.planning.hexlattice.column_major_key`.
"""

from __future__ import annotations

from hexbot.planning.configuration import is_connected, occupied_neighbors
from hexbot.planning.hexlattice import Cell, column_major_key, neighbors

Cells = frozenset[Cell]


def find_ve(current: Cells, goal: Cells) -> tuple[Cells, Cells]:
    """``FindVE``: (voids, electrons). Voids are goal cells not yet filled,
    electrons modules that are not part of the goal."""
    return frozenset(goal - current), frozenset(current - goal)


def mobile_electrons(electrons: Cells, current: Cells) -> list[Cell]:
    """``Mobile``: electrons with fewer than four occupied neighbours whose
    removal keeps the configuration connected (``HexCGT``), in MATLAB order.

    The connectivity test removes one electron at a time from the whole
    configuration, exactly as the listing does, so two mobile electrons may
    together be a cut (the failure of Fig. 5-10 in the parallel planner).
    """
    out = []
    for cell in sorted(electrons, key=column_major_key):
        if occupied_neighbors(current, cell) >= 4:
            continue
        if is_connected(current - {cell}):
            out.append(cell)
    return out


def immobile_modules(current: Cells, mobile: list[Cell]) -> Cells:
    """``C = I - ME``: every module except the mobile electrons."""
    return frozenset(current - set(mobile))


def potential_voids(current: Cells, goal: Cells, mobile: list[Cell] | None = None) -> list[Cell]:
    """``PV``: voids touching at least one immobile module, in MATLAB order.

    The loop body of ``PV`` is missing from the listing; this follows the
    text (section 4.3.5): "if there exists at least one immobile module in
    the neighborhood of the void, it is a potential void".
    """
    voids, electrons = find_ve(current, goal)
    if mobile is None:
        mobile = mobile_electrons(electrons, current)
    fixed = immobile_modules(current, mobile)
    return [
        v
        for v in sorted(voids, key=column_major_key)
        if any(n in fixed for n in neighbors(v))
    ]
