"""Animated GIF of a traversal run (matplotlib + Pillow, the ``plot`` extra).

Colours as Fig. 1 and Fig. 11: surface red, layer1 light grey, layer2 dark
grey, bridge cells yellow, goal cells green, modules blue; a round counter
in the title.
"""

from __future__ import annotations

from pathlib import Path

from hexbot.errors import ScenarioError
from hexbot.extras import require
from hexbot.planning.traversal.bridges import BridgeMap
from hexbot.planning.traversal.engine import Result

require("matplotlib", "plot", "rendering traversals").use("Agg")
require("PIL", "plot", "writing GIF files")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.animation import FuncAnimation, PillowWriter  # noqa: E402
from matplotlib.patches import Patch  # noqa: E402

from hexbot.planning.plot import draw_cells, frame  # noqa: E402

COLORS = {"surface": "#d62728", "layer1": "#dddddd", "layer2": "#999999",
          "bridge": "#ffd700", "goal": "#2ca02c", "module": "#1f77b4"}


def positions(result: Result) -> list[dict[int, tuple[int, int]]]:
    """Module cells before the first round and after each round."""
    cells = dict(result.initial)
    out = [dict(cells)]
    for moves in result.rounds:
        for m in moves:
            cells[m.module] = m.dst
        out.append(dict(cells))
    return out


def render_gif(bmap: BridgeMap, result: Result, path: str | Path, fps: int = 4,
               max_frames: int = 400) -> Path:
    frames = positions(result)[:max_frames]
    surface = bmap.surface
    bridge_cells = {c for g in bmap.groups for c in g.cells}
    every = set(surface.cells()) | set(bmap.layer1.cells) | set(bmap.layer2.cells)
    fig, ax = plt.subplots(figsize=(10, 4))

    def draw(k: int) -> None:
        ax.clear()
        draw_cells(ax, set(bmap.layer2.cells) - set(bmap.layer1.cells), COLORS["layer2"],
                   edge="#777777")
        draw_cells(ax, bmap.layer1.cells, COLORS["layer1"], edge="#aaaaaa")
        draw_cells(ax, surface.goals, COLORS["goal"], alpha=0.6)
        draw_cells(ax, bridge_cells, COLORS["bridge"])
        draw_cells(ax, surface.surface, COLORS["surface"])
        draw_cells(ax, frames[k].values(), COLORS["module"])
        frame(ax, every)
        ax.set_title(f"{surface.name}: round {k}/{len(frames) - 1} ({result.status})")
        ax.legend(handles=[Patch(color=COLORS[key], label=key) for key in COLORS],
                  loc="upper left", fontsize=7, ncol=6)

    animation = FuncAnimation(fig, draw, frames=len(frames))
    path = Path(path)
    try:
        animation.save(str(path), writer=PillowWriter(fps=fps))
    except OSError as exc:
        raise ScenarioError(f"--render: cannot write {path}: {exc.strerror or exc}") from None
    finally:
        plt.close(fig)
    return path
