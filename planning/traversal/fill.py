"""Fill cells: where rigid HexBot modules need the first modules to stay.

Under the ``hexbot`` motion model a rotation sweeps three cells, one of
them in the second ring (Table 4-3), so a lone module that rolls into a
narrow pocket or over a sharp edge can end in a cell with no move left: the
probing module is stuck there. The paper's bridges do not help, since the
probe never gets past that cell to number the perimeter beyond it. The
first module that gets there stays: the cell becomes part of the surface
the next modules roll on (a Fill cell, a Bridge that is never released: a
module in it cannot leave, by the same reason the probe could not).
:func:`fill_cells` repeats the probe's walk, each time with the cells
found so far held, until the walk reaches the goals. See docs/traversal.md,
"HexBot motion model".
"""

from __future__ import annotations

from collections.abc import Iterable

from hexbot.errors import ScenarioError
from hexbot.planning.traversal.layers import Stuck, layer1
from hexbot.protocol.lattice import Cell


def fill_cells(surface: frozenset[Cell], modules: Iterable[Cell], goals: Iterable[Cell],
               model: str) -> tuple[Cell, ...]:
    """The Fill cells, in the order the modules take them (module k stays in
    the k-th). At least one module must be left to reach a goal."""
    modules, goals = frozenset(modules), frozenset(goals)
    fills: list[Cell] = []
    while True:
        try:
            layer1(surface | frozenset(fills), modules, goals, model)
            return tuple(fills)
        except Stuck as stuck:
            if stuck.cell in fills or len(fills) + 1 >= len(modules):
                raise ScenarioError(
                    f"{stuck} under the {model} motion model, and {len(fills)} Fill "
                    f"cell(s) {[list(c) for c in fills]} already hold all modules but "
                    "one: this surface cannot be crossed by rigid modules") from stuck
            fills.append(stuck.cell)
