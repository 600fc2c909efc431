"""Figures of docs/planning.md, drawn from the code itself.

    .venv/bin/python -m hexbot.planning.figures docs/img

Each figure is computed by the same functions the planner uses, so the
documentation cannot drift from the behaviour.
"""

from __future__ import annotations

import sys
import time
from pathlib import Path

from hexbot.extras import require

require("matplotlib", "plot", "drawing the planning figures").use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from hexbot.planning.config_io import load_configuration  # noqa: E402
from hexbot.planning.configuration import (  # noqa: E402
    Configuration,
    articulation_points,
    linear_index,
)
from hexbot.planning.generate import parallelogram, random_blob  # noqa: E402
from hexbot.planning.hexlattice import (  # noqa: E402
    LETTER_CELLS,
    ROTATION_BY_KEY,
    cartesian,
    neighbor,
    vertices,
)
from hexbot.planning.plot import COLORS, draw_cells, frame, label_cells, plot_plan  # noqa: E402
from hexbot.planning.robust import plan_robust  # noqa: E402
from hexbot.planning.thesis.layers import find_ve, mobile_electrons, potential_voids  # noqa: E402
from hexbot.planning.thesis.mdp import mdp_states, value_iteration  # noqa: E402
from hexbot.planning.thesis.planner import plan_faithful  # noqa: E402
from hexbot.planning.thesis.voidprop import pair_voids, propagate  # noqa: E402

EXAMPLES = Path(__file__).resolve().parent / "examples"


def _ex(name: str) -> Configuration:
    return load_configuration(EXAMPLES / name)


def fig_lattice(out: Path) -> Path:
    """Sides, joints and Table 4-3 letters around a module; one rotation."""
    fig, axes = plt.subplots(1, 2, figsize=(9, 4.4))
    ax = axes[0]
    centre = (0, 0)
    draw_cells(ax, [centre], COLORS["module"])
    draw_cells(ax, [c for c in LETTER_CELLS.values()], "#eeeeee", lw=0.5)
    label_cells(ax, {c: letter for letter, c in LETTER_CELLS.items()}, 9)
    for side in range(1, 7):
        x0, y0 = cartesian(centre)
        x1, y1 = cartesian(neighbor(centre, side))
        ax.text(x0 + 0.42 * (x1 - x0), y0 + 0.42 * (y1 - y0), f"s{side}", color="blue",
                ha="center", va="center", fontsize=8)
    for j, (x, y) in enumerate(vertices(centre), start=1):
        ax.plot(x, y, "o", color="red", ms=3)
        ax.text(x * 1.25, y * 1.25, f"J{j}", color="red", ha="center", va="center", fontsize=8)
    ax.set_title("Fig. 4-9/4-30: sides s1..s6, joints J1..J6,\nneighbours A..F, ring G..L",
                 fontsize=9)
    frame(ax, LETTER_CELLS.values(), 0.3)
    ax = axes[1]
    rule = ROTATION_BY_KEY[(1, "CW")]
    sub, goal, swept = rule.at(centre)
    draw_cells(ax, LETTER_CELLS.values(), "#ffffff", lw=0.3)
    draw_cells(ax, [centre], COLORS["mover"])
    draw_cells(ax, [sub], COLORS["module"])
    draw_cells(ax, swept, "#bbdefb")
    draw_cells(ax, [goal], "none", fill=False, edge=COLORS["target"], lw=2)
    px, py = vertices(centre)[0]
    ax.plot(px, py, "o", color="red", ms=6)
    label_cells(ax, {centre: "mobile", sub: "substrate", goal: "goal",
                     **{c: "swept" for c in swept}}, 7)
    ax.set_title("Table 4-3, joint 1 CW: substrate A, empty D, E, K, goal F", fontsize=9)
    frame(ax, LETTER_CELLS.values(), 0.3)
    fig.tight_layout()
    path = out / "planning_lattice.png"
    fig.savefig(path, dpi=100)
    plt.close(fig)
    return path


def fig_articulation(out: Path) -> Path:
    cells = _ex("test_cg.txt").cells
    cut = articulation_points(cells)
    fig, ax = plt.subplots(figsize=(6, 4))
    draw_cells(ax, cells - cut, COLORS["mover"])
    draw_cells(ax, cut, COLORS["target"])
    label_cells(ax, {c: str(linear_index(c, 6)) for c in cells}, 8)
    ax.set_title("Figs. 4-19/4-21: articulation points (red) 20, 29, 35, 40", fontsize=9)
    frame(ax, cells)
    path = out / "planning_articulation.png"
    fig.savefig(path, dpi=100)
    plt.close(fig)
    return path


def fig_void_propagation(out: Path) -> Path:
    initial = _ex("test_vp_initial.txt").cells
    goal = _ex("test_vp_goal.txt").cells
    voids, electrons = find_ve(initial, goal)
    mobile = mobile_electrons(electrons, initial)
    pvs = potential_voids(initial, goal, mobile)
    pairs = pair_voids(initial, goal)
    fig, axes = plt.subplots(1, len(pairs), figsize=(5 * len(pairs), 4), squeeze=False)
    every = initial | goal
    for ax, pair in zip(axes.flat, pairs, strict=True):
        draw_cells(ax, initial - set(mobile), COLORS["module"])
        draw_cells(ax, mobile, COLORS["mover"])
        draw_cells(ax, pvs, "#80deea")
        draw_cells(ax, voids - set(pvs), "none", fill=False, edge=COLORS["goal"])
        first_hit = propagate(initial, mobile, pair.void)[0]
        me_label = f"ME({linear_index(pair.electron, 5)})\nt={first_hit[1]}"
        label_cells(ax, {pair.void: f"PV({linear_index(pair.void, 5)})", pair.electron: me_label},
                    7)
        ax.set_title(f"Fig. 4-24: PV({linear_index(pair.void, 5)}) finds "
                     f"ME({linear_index(pair.electron, 5)}) after {pair.time} steps", fontsize=9)
        frame(ax, every)
    fig.tight_layout()
    path = out / "planning_void_propagation.png"
    fig.savefig(path, dpi=100)
    plt.close(fig)
    return path


def fig_values(out: Path) -> Path:
    initial, goal = _ex("test_all_p01_initial.txt"), _ex("test_all_p01_goal.txt").cells
    me, pv = (0, 0), (0, 2)
    values, sweeps = value_iteration(initial.cells, goal, me, pv)
    states = mdp_states(initial.cells, goal)
    fig, ax = plt.subplots(figsize=(6, 4))
    cmap = plt.get_cmap("RdYlGn")
    fixed = initial.cells - set(mobile_electrons(initial.cells - goal, initial.cells))
    draw_cells(ax, fixed, "#dddddd")
    for s in states:
        v = values.get(s, 0.0)
        draw_cells(ax, [s], cmap((v + 1) / 2))
    label_cells(ax, {s: f"{values.get(s, 0):.2f}" for s in states}, 7)
    ax.set_title(f"Fig. 4-28: normalised values for ME {me} -> PV {pv}, "
                 f"discount 0.7, {sweeps} sweeps", fontsize=9)
    frame(ax, initial.cells | goal | states)
    path = out / "planning_values.png"
    fig.savefig(path, dpi=100)
    plt.close(fig)
    return path


def fig_examples(out: Path) -> list[Path]:
    p01 = (_ex("test_all_p01_initial.txt"), _ex("test_all_p01_goal.txt").cells)
    p02 = (_ex("test_all_p01_goal.txt"), _ex("test_all_p01_initial.txt").cells)
    s02 = (_ex("test_all_s02_initial.txt"), _ex("test_all_s02_goal.txt").cells)
    return [
        plot_plan(plan_faithful(*p01, parallel=True), out / "planning_p01_parallel.png"),
        plot_plan(plan_faithful(*p02, parallel=True), out / "planning_p02_faithful.png"),
        plot_plan(plan_robust(*p02), out / "planning_p02_robust.png"),
        plot_plan(plan_faithful(*s02, parallel=False), out / "planning_s02_serial.png"),
    ]


def fig_performance(out: Path) -> Path:
    """Planning time and plan length / distance bound vs module count, for the
    benchmark's parallelogram family and its first random blob pair (seed 0)."""
    sizes = {10: (5, 2, 10, 1), 30: (6, 5, 10, 3), 100: (10, 10, 20, 5),
             300: (20, 15, 30, 10), 1000: (40, 25, 50, 20)}
    families = {
        "parallelogram": [(n, parallelogram(w, h), parallelogram(w2, h2))
                          for n, (w, h, w2, h2) in sizes.items()],
        "random blobs (seed 0)": [(n, random_blob(n, 0, 0.8), random_blob(n, 1, 0.8))
                                  for n in (10, 30, 100, 1000)],
    }
    fig, axes = plt.subplots(1, 2, figsize=(9, 3.6))
    for label, cases in families.items():
        ns, secs, ratios = [], [], []
        for n, a, b in cases:
            start = time.perf_counter()
            plan = plan_robust(Configuration.from_cells(a), b)
            secs.append(time.perf_counter() - start)
            ns.append(n)
            ratios.append(plan.move_count / max(1, plan.lower_bound or 1))
        axes[0].loglog(ns, secs, "o-", label=label)
        axes[1].loglog(ns, ratios, "o-", label=label)
    axes[0].set_xlabel("modules")
    axes[0].set_ylabel("planning time (s)")
    axes[0].set_title("robust planner", fontsize=9)
    axes[0].legend(fontsize=8)
    axes[1].set_xlabel("modules")
    axes[1].set_ylabel("moves / distance lower bound")
    axes[1].set_title("plan length vs bound", fontsize=9)
    axes[1].legend(fontsize=8)
    fig.tight_layout()
    path = out / "planning_performance.png"
    fig.savefig(path, dpi=100)
    plt.close(fig)
    return path


def main(argv: list[str] | None = None) -> int:
    args = sys.argv[1:] if argv is None else argv
    out = Path(args[0] if args else "docs/img")
    out.mkdir(parents=True, exist_ok=True)
    paths = [fig_lattice(out), fig_articulation(out), fig_void_propagation(out), fig_values(out),
             *fig_examples(out), fig_performance(out)]
    for p in paths:
        print(p)
    return 0


if __name__ == "__main__":
    sys.exit(main())
