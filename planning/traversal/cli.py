"""``hexbot traverse MAP``: cross a surface with bridges (layering algorithm).

MAP is a text map (planning/traversal/maps/*.txt or any file), the name of
a map of the bank (``fig14``, ``left-5``) or ``random:SEED``. Exit status
0 when every module reached its goal; 1 (reason on stderr) on a deadlock,
a broken invariant, a bad map or a failed execution. ``--execute`` runs
the rounds on a cluster (:mod:`.execute`), by default the embedded
simulator with a scenario written from the map.
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path
from typing import Any

from hexbot.cli_args import image_file
from hexbot.errors import ScenarioError, UsageError
from hexbot.host.endpoints import add_port_arguments
from hexbot.host.workflows import Verify
from hexbot.planning.traversal.bridges import BridgeMap, find_bridge_cells
from hexbot.planning.traversal.engine import Result, traverse
from hexbot.planning.traversal.motion import MODELS
from hexbot.planning.traversal.surface import Surface, load_map

#: What matplotlib writes for ``--plot`` (the suffix picks the format).
PLOT_SUFFIXES = (".png", ".svg", ".pdf")


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("map", nargs="?", help="text map, bank name or random:SEED")
    parser.add_argument("--motion", choices=MODELS, default=None,
                        help="motion model: the paper's deformable modules (default) or "
                             "HexBot's rotations of Table 4-3 (the only one with --execute: "
                             "the modules are rigid)")
    parser.add_argument("--no-bridges", action="store_true", help="form no bridge at all")
    parser.add_argument("--no-3-bridges", action="store_true", help="only 1- and 2-cell bridges")
    parser.add_argument("--json", action="store_true", help="print one JSON object")
    parser.add_argument("--render", metavar="OUT.gif", type=image_file((".gif",)),
                        help="animate the rounds (plot extra)")
    parser.add_argument("--sweep", action="store_true",
                        help="instead of a map: the paper's Figs. 12-13 experiment (and the "
                             "SINGLE-bridge one), a table or --json")
    parser.add_argument("--plot", metavar="OUT.png", type=image_file(PLOT_SUFFIXES),
                        help="with --sweep: draw the figures (.png, .svg or .pdf)")
    parser.add_argument("--random", metavar="FIRST..LAST",
                        help="instead of a map: run random:SEED for every seed in the range "
                             "and count reached/deadlock/violation (exit 1 unless all reached)")
    hil = parser.add_argument_group(
        "execution (on the embedded simulator by default, or on --port: real modules or a pty)")
    hil.add_argument("--execute", action="store_true",
                     help="run the rounds on a cluster of the map's surface modules and movers "
                          "(without --port/--scenario: a scenario written from the map), "
                          "localized first, every move verified")
    hil.add_argument("--verify", choices=[v.value for v in Verify], default="auto",
                     help="how each move is checked (see hexbot plan --help)")
    add_port_arguments(parser, debug=False)


def resolve_map(text: str) -> Surface:
    if text.startswith("random:"):
        from hexbot.planning.traversal.bank import random_surface

        try:
            seed = int(text.split(":", 1)[1])
        except ValueError as exc:
            raise ScenarioError(f"{text}: expected random:SEED with an integer seed") from exc
        if seed < 0:
            raise ScenarioError(f"{text}: the seed is a whole number from 0")
        return random_surface(seed)
    path = Path(text)
    if not path.exists():
        from hexbot.planning.traversal.bank import MAPS

        candidate = MAPS / f"{text}.txt"
        if not candidate.exists():
            names = ", ".join(sorted(p.stem for p in MAPS.glob("*.txt")))
            raise ScenarioError(f"{text}: neither a map file nor a shipped map "
                                f"(shipped: {names}; or random:SEED)")
        path = candidate
    return load_map(path)


def result_json(bmap: BridgeMap, result: Result) -> dict[str, Any]:
    """The ``--json`` object (cells in the axial coordinates of ``hexbot plan``)."""
    out: dict[str, Any] = {
        "map": bmap.surface.name,
        "motion": bmap.model,
        "status": result.status,
        "time_steps": result.time_steps,
        "moves": result.moves,
        "modules": bmap.surface.n,
        "start_holds": list(result.holds),
        "bridges": [g.as_json() for g in bmap.groups]
        + ([{"kind": "FILL", "cells": [list(c) for c in bmap.fills]}] if bmap.fills else []),
        "rounds": [{"moves": [m.as_json() for m in moves]} for moves in result.rounds],
    }
    if result.violation is not None:
        out["violation"] = result.violation.as_json()
    if result.reason:
        out["reason"] = result.reason
    return out


def summary(bmap: BridgeMap, result: Result) -> str:
    lines = [f"{bmap.surface.name}: {bmap.surface.n} modules, {bmap.model} motion, "
             f"layer1 {len(bmap.layer1)} cells, {len(bmap.bis)} BI, "
             f"{len(bmap.groups)} bridge(s)"]
    for group in bmap.groups:
        extra = f" {group.shape}" if group.shape else ""
        support = (f", TempSupport {group.temp_support}, Support {group.support}"
                   if group.temp_support else "")
        lines.append(f"  {group.kind}{extra}: Bridge {list(group.bridge)}{support}, "
                     f"pocket length {group.pocket_length}")
    if bmap.fills:
        lines.append(f"  FILL (hexbot model, held for good): {[list(c) for c in bmap.fills]}")
    held = [f"module {k}: {h}" for k, h in enumerate(result.holds, start=1) if h]
    if held:
        lines.append(f"  start held back (rounds; their ways fold back): {', '.join(held)}")
    lines.append(f"{result.status}: {result.time_steps} time steps, {result.moves} moves")
    return "\n".join(lines)


def refuse_ignored_options(args: argparse.Namespace) -> None:
    """Options that do not fit together stop here (exit 2), before any work,
    instead of being silently ignored."""
    if args.plot and not args.sweep:
        raise UsageError("--plot draws the --sweep figures: give --sweep too "
                         "(--render animates one map)")
    if args.map and (args.sweep or args.random):
        raise UsageError("--sweep and --random run their own maps: give no MAP with them")
    if args.sweep or args.random:
        given = "--sweep" if args.sweep else "--random"
        if args.execute:
            raise UsageError(f"--execute runs one map on a cluster: not with {given}")
        if args.render:
            raise UsageError(f"--render animates one map: not with {given}"
                             + (" (--plot draws its figures)" if args.sweep else ""))
    if args.sweep:
        if args.no_bridges or args.no_3_bridges:
            raise UsageError("--sweep compares the runs with and without bridges itself: "
                             "no --no-bridges or --no-3-bridges")
        if args.motion == "hexbot":
            raise UsageError("--sweep reproduces the paper's figures, deformable motion only "
                             "(rigid modules form no 3-bridge)")
    if args.execute and args.motion == "deformable":
        raise UsageError("--execute runs rigid modules, which cannot make deformable moves: "
                         "--motion hexbot (the default with --execute)")


def run(args: argparse.Namespace) -> int:
    refuse_ignored_options(args)
    if args.sweep:
        from hexbot.planning.traversal.experiments import run_sweep

        return run_sweep(args)
    if args.random:
        from hexbot.planning.traversal.experiments import run_random

        return run_random(args)
    if not args.map:
        raise UsageError("give a MAP (or --sweep or --random FIRST..LAST)")
    surface = resolve_map(args.map)
    if args.execute:
        return run_execute(args, surface)
    bmap = find_bridge_cells(surface, args.motion or "deformable", bridges=not args.no_bridges,
                             three=not args.no_3_bridges)
    result = traverse(bmap)
    print(json.dumps(result_json(bmap, result)) if args.json else summary(bmap, result))
    if args.render:  # after the result: a drawing that fails does not lose it
        from hexbot.planning.traversal.render import render_gif

        render_gif(bmap, result, args.render)
    if result.status != "reached":
        print(f"hexbot traverse: {result.status}: {result.reason}", file=sys.stderr)
        return 1
    return 0


def run_execute(args: argparse.Namespace, surface: Surface) -> int:
    """Compute the rounds on the map, then run them on the cluster."""
    import tempfile

    from hexbot.host.cli_common import session
    from hexbot.planning.execute import execute
    from hexbot.planning.traversal.execute import cluster_of, rounds_plan, scenario_toml

    cluster = cluster_of(surface)
    bmap = find_bridge_cells(cluster.surface, args.motion or "hexbot",
                             bridges=not args.no_bridges, three=not args.no_3_bridges)
    result = traverse(bmap)
    if result.status != "reached":
        print(f"hexbot traverse: {result.status}, nothing executed: {result.reason}",
              file=sys.stderr)
        return 1
    plan = rounds_plan(cluster, result)
    with tempfile.TemporaryDirectory(prefix="hexbot-traverse-") as folder:
        if not args.port and not args.scenario:
            path = Path(folder) / f"traverse-{surface.name}.toml"
            path.write_text(scenario_toml(cluster, result.initial), encoding="utf-8")
            args.scenario = str(path)
        with session(args) as sess:
            if not args.json:
                print(summary(bmap, result))
                print(f"executing through {sess.host.channel().settings.url}: "
                      f"{plan.move_count} moves, verify {args.verify}")
            report = execute(plan, sess, cluster.reference, verify=Verify(args.verify),
                             log=None if args.json else print)
    if args.json:
        print(json.dumps({**result_json(bmap, result), "execution": report.as_json()}))
    else:
        print(report.line(plan.move_count))
    if args.render:
        from hexbot.planning.traversal.render import render_gif

        render_gif(bmap, result, args.render)
    if not report.reached:
        reason = report.failure.splitlines()[0] if report.failure else "not reached"
        print(f"hexbot traverse: execution stopped: {reason}", file=sys.stderr)
        return report.exit_status or 1
    return 0
