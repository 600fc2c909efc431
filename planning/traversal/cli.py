"""``hexbot traverse MAP``: cross a surface with bridges (layering algorithm).

MAP is a text map (planning/traversal/maps/*.txt or any file), the name of
a map of the bank (``fig14``, ``left-5``) or ``random:SEED``. Exit status
0 when every module reached its goal; 1 (reason on stderr) on a deadlock,
a broken invariant, a bad map or a failed execution.
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path
from typing import Any

from hexbot.errors import ScenarioError
from hexbot.planning.traversal.bridges import BridgeMap, find_bridge_cells
from hexbot.planning.traversal.engine import Result, traverse
from hexbot.planning.traversal.motion import MODELS
from hexbot.planning.traversal.surface import Surface, load_map


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("map", nargs="?", help="text map, bank name or random:SEED")
    parser.add_argument("--motion", choices=MODELS, default="deformable",
                        help="motion model: the paper's deformable modules (default) or "
                             "HexBot's rotations of Table 4-3")
    parser.add_argument("--no-bridges", action="store_true", help="form no bridge at all")
    parser.add_argument("--no-3-bridges", action="store_true", help="only 1- and 2-cell bridges")
    parser.add_argument("--json", action="store_true", help="print one JSON object")
    parser.add_argument("--render", metavar="OUT.gif", help="animate the rounds (plot extra)")
    parser.add_argument("--sweep", action="store_true",
                        help="instead of a map: the paper's Figs. 12-13 experiment (and the "
                             "SINGLE-bridge one), a table or --json")
    parser.add_argument("--plot", metavar="OUT.png", help="with --sweep: draw the figures")


def resolve_map(text: str) -> Surface:
    if text.startswith("random:"):
        from hexbot.planning.traversal.bank import random_surface

        try:
            seed = int(text.split(":", 1)[1])
        except ValueError as exc:
            raise ScenarioError(f"{text}: expected random:SEED with an integer seed") from exc
        return random_surface(seed)
    path = Path(text)
    if not path.exists():
        from hexbot.planning.traversal.bank import MAPS

        candidate = MAPS / f"{text}.txt"
        if candidate.exists():
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
    lines.append(f"{result.status}: {result.time_steps} time steps, {result.moves} moves")
    return "\n".join(lines)


def run(args: argparse.Namespace) -> int:
    if args.sweep:
        from hexbot.planning.traversal.experiments import run_sweep

        return run_sweep(args)
    if not args.map:
        raise ScenarioError("give a MAP (or --sweep)")
    surface = resolve_map(args.map)
    bmap = find_bridge_cells(surface, args.motion, bridges=not args.no_bridges,
                             three=not args.no_3_bridges)
    result = traverse(bmap)
    if args.render:
        from hexbot.planning.traversal.render import render_gif

        render_gif(bmap, result, args.render)
    print(json.dumps(result_json(bmap, result)) if args.json else summary(bmap, result))
    if result.status != "reached":
        print(f"hexbot traverse: {result.status}: {result.reason}", file=sys.stderr)
        return 1
    return 0
