"""Benchmark of the traversal (layering algorithm); prints one JSON object.

    hexbot bench traversal            # preprocessing on 1e3, 1e4, 1e5 perimeter cells,
                                      # the round engine with 1,000 modules
    hexbot bench traversal --quick    # 1e3 and 1e4 cells, 100 modules

FINDBRIDGECELLS runs on a long surface with a BASIC pocket every 12 columns
(the perimeter grows with the width); the engine runs n modules across a
flat surface 2n + 40 cells long.
"""

from __future__ import annotations

import argparse
import json
import platform
import time

from hexbot.planning.traversal.bridges import find_bridge_cells
from hexbot.planning.traversal.engine import traverse
from hexbot.planning.traversal.surface import Surface


def pocketed_surface(width: int, n: int = 4) -> Surface:
    """A floor three rows deep with a two-cell-wide pocket every 12 columns."""
    cells = {(x, y) for x in range(width) for y in range(-3, 1)}
    for x in range(n + 8, width - n - 8, 12):
        cells -= {(x, 0), (x + 1, 0), (x + 1, -1), (x, -1), (x + 1, -2)}
    modules = frozenset((x, 1) for x in range(1, 1 + n))
    goals = frozenset((x, 1) for x in range(width - 1 - n, width - 1))
    return Surface(frozenset(cells), modules, goals, f"pocketed-{width}")


def preprocessing(perimeter: int) -> dict:
    width = int(perimeter / 1.3)  # each pocket adds four perimeter cells per 12 columns
    surface = pocketed_surface(width)
    start = time.perf_counter()
    bmap = find_bridge_cells(surface)
    seconds = time.perf_counter() - start
    return {"perimeter_cells": len(bmap.layer1), "surface_cells": len(surface.surface),
            "bridges": len(bmap.groups), "seconds": round(seconds, 3),
            "us_per_perimeter_cell": round(1e6 * seconds / len(bmap.layer1), 2)}


def random_preprocessing(width: int) -> dict:
    """FINDBRIDGECELLS on a long random surface (every bridge kind, 3-bridges
    next to other bridges: the checks of docs/traversal.md, "Rules beyond
    the paper"), a dug pocket every 7.5 columns."""
    from hexbot.planning.traversal.bank import random_surface

    surface = random_surface(7, width=width, pockets=width * 2 // 15)
    start = time.perf_counter()
    bmap = find_bridge_cells(surface)
    seconds = time.perf_counter() - start
    return {"perimeter_cells": len(bmap.layer1), "bridges": len(bmap.groups),
            "three_bridges": sum(g.kind == "THREE" for g in bmap.groups),
            "seconds": round(seconds, 3),
            "us_per_perimeter_cell": round(1e6 * seconds / len(bmap.layer1), 2)}


def rounds(n: int) -> dict:
    width = 2 * n + 40
    cells = {(x, y) for x in range(width) for y in range(-1, 1)}
    surface = Surface(frozenset(cells), frozenset((x, 1) for x in range(1, 1 + n)),
                      frozenset((x, 1) for x in range(width - 1 - n, width - 1)), f"flat-{n}")
    bmap = find_bridge_cells(surface)
    start = time.perf_counter()
    result = traverse(bmap)
    seconds = time.perf_counter() - start
    return {"modules": n, "status": result.status, "time_steps": result.time_steps,
            "moves": result.moves, "seconds": round(seconds, 3),
            "module_rounds_per_s": round(n * len(result.rounds) / seconds)}


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--quick", action="store_true", help="small cases only")


def run(args: argparse.Namespace) -> int:
    sizes = (1_000, 10_000) if args.quick else (1_000, 10_000, 100_000)
    out = {"python": platform.python_version(), "machine": platform.machine(),
           "preprocessing": [preprocessing(m) for m in sizes],
           "random_preprocessing": [random_preprocessing(w) for w in
                                    ((300, 3_000) if args.quick else (300, 3_000, 30_000))],
           "engine": [rounds(100 if args.quick else 1000)]}
    print(json.dumps(out, indent=1))
    return 0 if all(r["status"] == "reached" for r in out["engine"]) else 1
