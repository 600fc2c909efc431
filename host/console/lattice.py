"""The cluster drawn on the hexagonal lattice, from localization and status.

Coordinates as in Table 4-1: +y is side 2 (up), +x is side 3 (up-right).
Each module is two text rows: ``/id\\`` over ``\\role arrow/``; the arrow
points along the module's body side 1 in the lattice (global side
Yref + 1), so orientation is visible at a glance. Neighbours in y are two
rows apart, neighbours in x one row and five columns.
"""

from __future__ import annotations

from rich.text import Text
from textual.widgets import Static

from hexbot.host.cluster import ClusterModel

CELL_W = 5
ARROWS = {1: "\u2196", 2: "\u2191", 3: "\u2197", 4: "\u2198", 5: "\u2193", 6: "\u2199"}
STYLE = {"S": "bold cyan", "M": "bold green"}
NEIGHBOURS = ((-1, 1), (0, 1), (1, 0), (1, -1), (0, -1), (-1, 0))


def lattice_cells(model: ClusterModel) -> dict[tuple[int, int], tuple[str, str, int | None]]:
    """(x, y) -> (label, role, yref) for every module with a position."""
    cells: dict[tuple[int, int], tuple[str, str, int | None]] = {}
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


def draw_lattice(model: ClusterModel) -> Text:
    cells = lattice_cells(model)
    if not cells:
        return Text("no positions yet: localize the cluster (key l)", style="dim")
    empty = {(x + dx, y + dy) for (x, y) in cells for dx, dy in NEIGHBOURS} - set(cells)
    every = set(cells) | empty
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
    for (x, y), (label, role, yref) in sorted(cells.items()):
        r, c = -(x + 2 * y) - top, x * CELL_W - left
        style = STYLE.get(role, "bold yellow")
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


def lattice_legend(model: ClusterModel) -> str:
    cells = lattice_cells(model)
    if not cells:
        return ""
    parts = [f"{label} ({x:+d},{y:+d}) yref {'?' if yref is None else yref}"
             for (x, y), (label, _, yref) in sorted(cells.items(), key=lambda kv: kv[1][0])]
    return (f"{len(cells)} placed: " + ", ".join(parts)
            + "\n+x = side 3 (up-right), +y = side 2 (up); arrow = body side 1")


class LatticeView(Static):
    def refresh_from(self, model: ClusterModel) -> None:
        text = draw_lattice(model)
        legend = lattice_legend(model)
        if legend:
            text.append("\n\n")
            text.append(legend, style="dim")
        self.update(text)
