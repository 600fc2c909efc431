"""How rough the bench's shapes are for a rolling module: surface segments.

    hexbot bench surface                    # table: families x sizes, plus smooth references
    hexbot bench surface --sizes 100,1000 --json

For each configuration (the start and the goal of the planning bench's
pairs, ``hexbot bench planning``, and two smooth references) it counts the
border cells (empty cells touching a module), the segments they form for a
module rolling by Table 4-3 rotations with every other module fixed
(:func:`hexbot.planning.surface.surface_segments`), and the share of the
border in the largest segment. One segment = a module can roll all around.
"""

from __future__ import annotations

import argparse
import json

from hexbot.bench.planning import make_pair, module_count
from hexbot.cli_args import comma_list, count


def measure(label: str, n: int, cells) -> dict:
    from hexbot.planning.surface import surface_segments

    segments = surface_segments(cells)
    total = sum(len(s) for s in segments)
    return {
        "shape": label, "modules": n, "border": total, "segments": len(segments),
        "longer_than_one": sum(1 for s in segments if len(s) > 1),
        "largest": len(segments[0]) if segments else 0,
        "largest_share": round(len(segments[0]) / total, 3) if total else 1.0,
    }


def rows(sizes: list[int], seeds: int) -> list[dict]:
    from hexbot.planning.generate import parallelogram
    from hexbot.planning.middle import ball

    out = []
    for n in sizes:
        side = max(1, round(n ** 0.5))
        out.append(measure("parallelogram", n, parallelogram(side, max(1, n // side))))
        out.append(measure("ball", n, ball((0, 0), n)))
        for family in ("blob", "scramble"):
            for seed in range(seeds):
                initial, goal = make_pair(family, n, seed)
                out.append(measure(f"{family} {seed} start", n, initial))
                out.append(measure(f"{family} {seed} goal", n, goal))
    return out


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--sizes", type=comma_list(module_count), default="30,100,1000",
                        help="module counts")
    parser.add_argument("--seeds", type=count, default=2, help="pairs per family and size")
    parser.add_argument("--json", action="store_true", help="JSON lines instead of a table")


def run(args: argparse.Namespace) -> int:
    table = rows(args.sizes, args.seeds)
    if args.json:
        for r in table:
            print(json.dumps(r))
        return 0
    print("| shape | modules | border cells | segments | longer than one | largest | share |")
    print("|---|---:|---:|---:|---:|---:|---:|")
    for r in table:
        print(f"| {r['shape']} | {r['modules']} | {r['border']} | {r['segments']} | "
              f"{r['longer_than_one']} | {r['largest']} | {r['largest_share']:.2f} |")
    return 0
