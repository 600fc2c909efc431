"""The paper's measurements, reproduced (Section VI).

- Figs. 12-13: four modules, one pocket behind a 3-cell opening whose
  perimeter grows; time steps and module moves with the 3-bridge, without
  any bridge (the paper's blue line: the modules traverse the whole
  pocket) and with only the 1- and 2-cell bridges inside it.
- SINGLE bridges: one dent in a flat surface, n modules, with and without
  bridges: the paper says each SINGLE bridge adds 2 time steps and saves
  n - 1 moves.
"""

from __future__ import annotations

import argparse
import json
from typing import Any

from hexbot.errors import ScenarioError, UsageError
from hexbot.planning.traversal.bank import Feature, build
from hexbot.planning.traversal.bridges import find_bridge_cells
from hexbot.planning.traversal.engine import traverse

SWEEP_DEPTHS = tuple(range(2, 11))  # the block is DEPTH rows deep
SINGLE_N = (3, 4, 5, 6, 8, 10)


def pocket_sweep(depths=SWEEP_DEPTHS, n: int = 4) -> list[dict[str, Any]]:
    rows = []
    for depth in depths:
        surface = build([Feature("THREE", depth)], n, name=f"three-deep{depth}")
        bmap = find_bridge_cells(surface)
        three = [g for g in bmap.groups if g.kind == "THREE"]
        if not three:
            raise ScenarioError(f"depth {depth}: no 3-bridge found")
        row: dict[str, Any] = {"pocket": three[0].pocket_length, "depth": depth}
        # the paper's blue line: "modules must traverse the entire pocket" (no
        # bridge at all); "small": no 3-bridge, but the 1-2 bridges inside it
        for label, options in (("with", {}), ("without", {"bridges": False}),
                               ("small", {"three": False})):
            result = traverse(find_bridge_cells(surface, **options))
            row[label] = {"status": result.status, "time_steps": result.time_steps,
                          "moves": result.moves}
        rows.append(row)
    return rows


def crossover(sweep: list[dict[str, Any]]) -> int | None:
    """The smallest pocket perimeter from which the 3-bridge is faster than
    traversing the pocket, for every larger one too (None: never)."""
    faster = [r["with"]["time_steps"] < r["without"]["time_steps"] for r in sweep]
    for k in range(len(sweep)):
        if all(faster[k:]):
            return sweep[k]["pocket"]
    return None


def single_effect(ns=SINGLE_N) -> list[dict[str, Any]]:
    rows = []
    for n in ns:
        surface = build([Feature("SINGLE", 1)], n, name=f"single-1-n{n}")
        bridged = traverse(find_bridge_cells(surface))
        bare = traverse(find_bridge_cells(surface, bridges=False))
        rows.append({"n": n, "bridged": [bridged.time_steps, bridged.moves],
                     "bare": [bare.time_steps, bare.moves],
                     "extra_time": bridged.time_steps - bare.time_steps,
                     "saved_moves": bare.moves - bridged.moves,
                     "status": [bridged.status, bare.status]})
    return rows


def table(sweep: list[dict[str, Any]], singles: list[dict[str, Any]]) -> str:
    lines = ["| pocket perimeter | time steps with 3-bridge | without bridges | 1-2 bridges "
             "only | moves with | without | 1-2 bridges only |",
             "|---:|---:|---:|---:|---:|---:|---:|"]
    for row in sweep:
        w, wo, sm = row["with"], row["without"], row["small"]
        lines.append(f"| {row['pocket']} | {w['time_steps']} | {wo['time_steps']} | "
                     f"{sm['time_steps']} | {w['moves']} | {wo['moves']} | {sm['moves']} |")
    lines.append(f"\ntime crossover (3-bridge faster from this pocket perimeter on): "
                 f"{crossover(sweep)}")
    lines += ["", "| n | time with SINGLE bridge | without | extra time | moves with | "
              "without | moves saved (n - 1) |", "|---:|---:|---:|---:|---:|---:|---:|"]
    for row in singles:
        lines.append(f"| {row['n']} | {row['bridged'][0]} | {row['bare'][0]} | "
                     f"{row['extra_time']} | {row['bridged'][1]} | {row['bare'][1]} | "
                     f"{row['saved_moves']} ({row['n'] - 1}) |")
    return "\n".join(lines)


def plot(sweep: list[dict[str, Any]], path: str) -> None:
    from hexbot.extras import require

    require("matplotlib", "plot", "drawing figures").use("Agg")
    import matplotlib.pyplot as plt

    xs = [r["pocket"] for r in sweep]
    fig, axes = plt.subplots(1, 2, figsize=(10, 3.6))
    for ax, key, title in ((axes[0], "time_steps", "Fig. 12: time steps"),
                           (axes[1], "moves", "Fig. 13: module moves")):
        ax.plot(xs, [r["without"][key] for r in sweep], "o-", color="#1f77b4",
                label="traverse the pocket")
        ax.plot(xs, [r["small"][key] for r in sweep], "^--", color="#7f7f7f",
                label="1-2 bridges only")
        ax.plot(xs, [r["with"][key] for r in sweep], "s-", color="#d62728",
                label="3-module bridge")
        ax.set_xlabel("pocket perimeter (cells)")
        ax.set_title(title)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
    fig.tight_layout()
    try:
        fig.savefig(path, dpi=110)
    except OSError as exc:
        raise ScenarioError(f"--plot: cannot write {path}: {exc.strerror or exc}") from None
    finally:
        plt.close(fig)


def run_sweep(args: argparse.Namespace) -> int:
    sweep, singles = pocket_sweep(), single_effect()
    if args.json:
        print(json.dumps({"pocket_sweep": sweep, "single": singles}))
    else:
        print(table(sweep, singles))
    if args.plot:
        plot(sweep, args.plot)
    bad = [r for r in sweep if r["with"]["status"] != "reached"]
    return 1 if bad else 0


def random_runs(seeds: range, model: str = "deformable", *, bridges: bool = True,
                three: bool = True) -> dict[str, Any]:
    """Every ``random:SEED`` of ``seeds``: how many are reached, deadlock or break
    an invariant, and why each failure did (docs/traversal.md, random surfaces).
    ``bridges``, ``three``: as :func:`find_bridge_cells`."""
    from hexbot.planning.traversal.bank import random_surface

    counts = dict.fromkeys(("reached", "deadlock", "violation", "refused"), 0)
    failures = []
    for seed in seeds:
        try:
            result = traverse(find_bridge_cells(random_surface(seed), model, bridges=bridges,
                                                three=three))
        except ScenarioError as exc:  # the map cannot be crossed under this model
            counts["refused"] += 1
            failures.append({"seed": seed, "status": "refused", "reason": str(exc)})
            continue
        counts[result.status] += 1
        if result.status != "reached":
            failures.append({"seed": seed, "status": result.status, "reason": result.reason})
    return {"seeds": [seeds.start, seeds.stop - 1], "motion": model,
            "bridges": "none" if not bridges else "all" if three else "1-2", **counts,
            "failures": failures}


def run_random(args: argparse.Namespace) -> int:
    first, sep, last = args.random.partition("..")
    try:
        seeds = range(int(first), int(last if sep else first) + 1)
    except ValueError:
        raise UsageError(f"--random {args.random}: expected FIRST..LAST seeds") from None
    if not seeds:
        raise UsageError(f"--random {args.random}: the range is empty (LAST below FIRST)")
    report = random_runs(seeds, args.motion or "deformable", bridges=not args.no_bridges,
                         three=not args.no_3_bridges)
    if args.json:
        print(json.dumps(report))
    else:
        bridges = "" if report["bridges"] == "all" else f", bridges: {report['bridges']}"
        print(f"random:{seeds.start}..{seeds.stop - 1} ({report['motion']}{bridges}): "
              + ", ".join(f"{report[k]} {k}" for k in ("reached", "deadlock", "violation",
                                                       "refused")))
        for f in report["failures"]:
            print(f"  random:{f['seed']}: {f['status']}: {f['reason']}")
    return 0 if report["reached"] == len(seeds) else 1
