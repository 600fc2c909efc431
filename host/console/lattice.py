"""The cluster drawn on the hexagonal lattice, from localization and status.

With the embedded simulator, modules the replies have not placed (yet)
are drawn dim where the simulator's plant has them: the app passes the
plant's placements (``SimulatorAccess.placements()``, protocol types only);
on hardware there are none.

Coordinates as in Table 4-1: +y is side 2 (up), +x is side 3 (up-right).
While a plan is shown or runs, the goal's empty cells are drawn as yellow
outlines (``/  \\`` over ``\\  /``), so the shape fills in as the moves land.

Each module is two text rows: ``/id\\`` over ``\\role arrow/``; the arrow
points along the module's body side 1 in the lattice (global side
Yref + 1), so orientation is visible at a glance. Neighbours in y are two
rows apart, neighbours in x one row and five columns.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

from rich.text import Text
from textual.widgets import Static

from hexbot.host.cluster import ClusterModel
from hexbot.protocol.lattice import SIDE_OFFSETS
from hexbot.protocol.simulation import Placement, PlantVerdict

Cells = dict[tuple[int, int], tuple[str, str, int | None]]
Truth = Mapping[int, Placement]

CELL_W = 5
ARROWS = {1: "\u2196", 2: "\u2191", 3: "\u2197", 4: "\u2198", 5: "\u2193", 6: "\u2199"}
STYLE = {"S": "bold cyan", "M": "bold green"}


def lattice_cells(model: ClusterModel) -> Cells:
    """(x, y) -> (label, role, yref) for every module the host placed from
    localization and status replies."""
    cells: Cells = {}
    for p in model.cells():
        label = f"{p.module_id:02d}" if p.module_id is not None else "??"
        role = "-"
        if p.module_id is not None and (row := model.module(p.module_id)) is not None:
            role = row.role
        cells[(p.x, p.y)] = (label, role, p.yref)
    for m in model.modules.values():
        if m.position is not None and m.module_id is not None:
            cells[m.position] = (f"{m.module_id:02d}", m.role, m.orientation)
    return cells


def sim_cells(model: ClusterModel, truth: Truth) -> Cells:
    """Cells where the simulator's plant (``truth``: id -> placement) has a
    module the replies have not (yet) placed there: drawn dim, so a wrong
    localization, or where a rotated module went, stands out."""
    known = lattice_cells(model)
    out: Cells = {}
    for ident, placed in sorted(truth.items()):
        if known.get(placed.cell, ("",))[0] != f"{ident:02d}":
            row = model.module(ident)
            out[placed.cell] = (f"{ident:02d}", row.role if row else "-", placed.orientation)
    return out


def draw_lattice(model: ClusterModel, truth: Truth | None = None,
                 goal: frozenset[tuple[int, int]] = frozenset()) -> Text:
    cells = lattice_cells(model)
    ghosts = {c: v for c, v in sim_cells(model, truth or {}).items() if c not in cells}
    if not cells and not ghosts:
        return Text("no positions yet: localize the cluster (key l)", style="dim")
    occupied = set(cells) | set(ghosts)
    wanted = set(goal) - occupied  # goal cells still to fill
    empty = {(x + dx, y + dy) for (x, y) in occupied | wanted
             for dx, dy in SIDE_OFFSETS.values()} - occupied - wanted
    every = occupied | empty | wanted
    rows = [-(x + 2 * y) for x, y in every]
    cols = [x * CELL_W for x, y in every]
    top, left = min(rows), min(cols)
    height = max(rows) - top + 2
    width = max(cols) - left + CELL_W
    grid: list[list[tuple[str, str]]] = [[(" ", "")] * width for _ in range(height)]

    def put(r: int, c: int, text: str, style: str) -> None:
        for i, ch in enumerate(text):
            grid[r][c + i] = (ch, style)

    for x, y in sorted(empty):
        put(-(x + 2 * y) - top, x * CELL_W - left, " .. ", "dim")
    for x, y in sorted(wanted):
        r, c = -(x + 2 * y) - top, x * CELL_W - left
        put(r, c, "/  \\", "yellow")
        put(r + 1, c, "\\  /", "yellow")
    drawn = [(cell, v, False) for cell, v in cells.items()]
    drawn += [(cell, v, True) for cell, v in ghosts.items()]
    for (x, y), (label, role, yref), ghost in sorted(drawn):
        r, c = -(x + 2 * y) - top, x * CELL_W - left
        style = "dim" if ghost else STYLE.get(role, "bold yellow")
        arrow = ARROWS.get((yref or 0) + 1, "?") if yref is not None else "?"
        put(r, c, f"/{label}\\", style)
        put(r + 1, c, f"\\{role}{arrow}/", style)
    out = Text()
    for row in grid:
        line = Text()
        for ch, style in row:
            line.append(ch, style)
        line.rstrip()
        out.append_text(line)
        out.append("\n")
    out.rstrip()
    return out


def lattice_legend(model: ClusterModel, truth: Truth | None = None,
                   verdicts: Sequence[PlantVerdict] = (),
                   goal: frozenset[tuple[int, int]] = frozenset()) -> str:
    """Positions in words, a note on the dim cells, the plant's last verdicts,
    how much of a plan's goal is filled."""
    cells = lattice_cells(model)
    lines = []
    if goal:
        filled = len(goal & set(cells))
        lines.append(f"goal: {filled} of {len(goal)} cells filled (yellow: still empty)")
    if cells:
        parts = [f"{label} ({x:+d},{y:+d}) yref {'?' if yref is None else yref}"
                 for (x, y), (label, _, yref) in sorted(cells.items(), key=lambda kv: kv[1][0])]
        lines.append(f"{len(cells)} placed: " + ", ".join(parts))
    if truth:
        lines.append("dim: where the simulator has a module the replies did not place")
    lines.extend(f"sim {v.t:.2f}s {v.describe()}" for v in verdicts[-3:])
    if lines:
        lines.append("+x = side 3 (up-right), +y = side 2 (up); arrow = body side 1")
    return "\n".join(lines)


class LatticeView(Static):
    """The drawing (scrolls with its container for big clusters)."""

    def refresh_from(self, model: ClusterModel, truth: Truth | None = None,
                     goal: frozenset[tuple[int, int]] = frozenset()) -> None:
        self.update(draw_lattice(model, truth, goal))


class LatticeLegend(Static):
    """Positions in words, the plant's last verdicts, the axes."""

    def refresh_from(self, model: ClusterModel, truth: Truth | None = None,
                     verdicts: Sequence[PlantVerdict] = (),
                     goal: frozenset[tuple[int, int]] = frozenset()) -> None:
        self.update(Text(lattice_legend(model, truth, verdicts, goal), style="dim"))
