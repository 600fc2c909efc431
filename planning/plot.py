"""Drawings of configurations and plans (matplotlib, Agg backend, files only).

matplotlib is the optional ``plot`` extra: importing this module without it
raises MissingExtraError.
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from pathlib import Path

from hexbot.extras import require
from hexbot.planning.hexlattice import Cell, cartesian, neighbors, vertices
from hexbot.planning.plan import Plan

require("matplotlib", "plot", "drawing plans").use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.animation import FuncAnimation, PillowWriter  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402
from matplotlib.patches import Patch  # noqa: E402

COLORS = {
    "module": "#f2d04b",  # the thesis' yellow
    "mover": "#4caf50",  # green: mobile electron
    "target": "#e53935",  # red: its void
    "goal": "#1e88e5",
    "state": "#d81b8c",  # magenta: MDP states
}


def draw_cells(ax, cells: Iterable[Cell], color: str, alpha: float = 1.0, edge: str = "k",
               fill: bool = True, lw: float = 1.0) -> None:
    # One collection, not a patch per cell: add_patch recomputes the data
    # limits per call, which made a 160-frame traversal GIF take minutes.
    polygons = [vertices(cell) for cell in cells]
    if polygons:
        ax.add_collection(PolyCollection(polygons, closed=True,
                                         facecolors=color if fill else "none",
                                         edgecolors=edge, alpha=alpha, linewidths=lw))


def label_cells(ax, labels: dict[Cell, str], size: float = 7) -> None:
    for cell, text in labels.items():
        x, y = cartesian(cell)
        ax.text(x, y, text, ha="center", va="center", fontsize=size)


def frame(ax, cells: Iterable[Cell], margin: float = 1.0) -> None:
    pts = [p for c in cells for p in vertices(c)]
    xs, ys = [p[0] for p in pts], [p[1] for p in pts]
    ax.set_xlim(min(xs) - margin, max(xs) + margin)
    ax.set_ylim(min(ys) - margin, max(ys) + margin)
    ax.set_aspect("equal")
    ax.axis("off")


def plot_plan(plan: Plan, path: str | Path, max_panels: int = 60, ids: bool = True) -> Path:
    """One panel per time step, like Figs. 5-8/5-9: the configuration before the
    step with its movers in green, their destinations outlined in red, the
    goal outlined in blue; a last panel shows the final configuration."""
    configs = plan.configurations()
    panels = list(range(len(plan.steps) + 1))
    if len(panels) > max_panels:  # keep the first and last steps readable
        keep = max_panels - 1
        panels = panels[: keep // 2] + panels[-(keep - keep // 2):]
    cols = min(4, len(panels))
    rows = math.ceil(len(panels) / cols)
    every = set().union(*(c.cells for c in configs), plan.goal)
    fig, axes = plt.subplots(rows, cols, figsize=(3.2 * cols, 3.0 * rows), squeeze=False)
    for ax in axes.flat:
        ax.axis("off")
    small = len(every) <= 80
    for ax, t in zip(axes.flat, panels, strict=False):
        config = configs[t]
        moves = plan.steps[t].moves if t < len(plan.steps) else []
        movers = {m.src for m in moves}
        draw_cells(ax, config.cells - movers, COLORS["module"], lw=0.6 if small else 0.2)
        draw_cells(ax, movers, COLORS["mover"], lw=0.6 if small else 0.2)
        draw_cells(ax, plan.goal, "none", fill=False, edge=COLORS["goal"], lw=1.2 if small else 0.4)
        draw_cells(ax, {m.dst for m in moves}, "none", fill=False, edge=COLORS["target"], lw=1.6)
        for m in moves:
            (x0, y0), (x1, y1) = cartesian(m.src), cartesian(m.dst)
            ax.annotate("", (x1, y1), (x0, y0), arrowprops={"arrowstyle": "->", "lw": 0.8})
        if ids and small:
            label_cells(ax, {c: str(mod.id) for c, mod in config.items()}, 6)
        title = f"time step {t + 1}" + (f": {len(moves)} move(s)" if moves else " (final)")
        ax.set_title(title, fontsize=8)
        frame(ax, every)
    state = "reached" if plan.reached else "NOT reached"
    fig.suptitle(f"{plan.mode}: goal {state} in {plan.time_steps} step(s), "
                 f"{plan.move_count} move(s)", fontsize=10)
    fig.tight_layout()
    path = Path(path)
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


GRID_EDGE = "#cccccc"


def render_plan(plan: Plan, path: str | Path, fps: int = 2, max_frames: int = 400) -> Path:
    """An animated GIF of the plan: one frame per time step on the lattice grid
    (every cell the plan touches and their neighbours), movers in green with
    arrows to their destinations, the goal outlined, a step counter and a legend."""
    configs = plan.configurations()[:max_frames]
    every = set().union(*(c.cells for c in configs), plan.goal)
    grid = every | {n for c in every for n in neighbors(c)}
    small = len(every) <= 80
    lw = 0.6 if small else 0.2
    fig, ax = plt.subplots(figsize=(7, 6))
    legend = [Patch(facecolor=COLORS["module"], edgecolor="k", label="module"),
              Patch(facecolor=COLORS["mover"], edgecolor="k", label="moves this step"),
              Patch(facecolor="none", edgecolor=COLORS["target"], label="its destination"),
              Patch(facecolor="none", edgecolor=COLORS["goal"], label="goal cell"),
              Patch(facecolor="none", edgecolor=GRID_EDGE, label="lattice")]

    def draw(t: int) -> None:
        ax.clear()
        config = configs[t]
        moves = plan.steps[t].moves if t < len(plan.steps) else []
        movers = {m.src for m in moves}
        draw_cells(ax, grid, "none", fill=False, edge=GRID_EDGE, lw=0.4)
        draw_cells(ax, config.cells - movers, COLORS["module"], lw=lw)
        draw_cells(ax, movers, COLORS["mover"], lw=lw)
        draw_cells(ax, plan.goal, "none", fill=False, edge=COLORS["goal"], lw=1.2 if small else 0.4)
        draw_cells(ax, {m.dst for m in moves}, "none", fill=False, edge=COLORS["target"], lw=1.6)
        for m in moves:
            (x0, y0), (x1, y1) = cartesian(m.src), cartesian(m.dst)
            ax.annotate("", (x1, y1), (x0, y0), arrowprops={"arrowstyle": "->", "lw": 0.8})
        if small:
            label_cells(ax, {c: str(mod.id) for c, mod in config.items()}, 6)
        frame(ax, grid)
        ax.set_title(f"{plan.mode}: time step {t}/{len(configs) - 1}, "
                     f"{len(moves)} move(s) next", fontsize=9)
        ax.legend(handles=legend, loc="upper left", fontsize=7, ncol=3,
                  bbox_to_anchor=(0.0, 0.0), frameon=False)

    animation = FuncAnimation(fig, draw, frames=len(configs))
    path = Path(path)
    animation.save(str(path), writer=PillowWriter(fps=fps))
    plt.close(fig)
    return path
