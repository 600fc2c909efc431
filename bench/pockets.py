"""How deep the holes of the planning bench's pairs are walled in.

    hexbot bench pockets                         # table: holes pairs of 100, 300, 1,000
    hexbot bench pockets --families holes,blob --sizes 300 --seeds 4 --json

A hole of the start that the goal fills can be entered only once a dig from
the surface has opened it, and a hole of the goal that the start fills can be
left only so (docs/planning.md, "Shapes with holes"). For each such cell
this counts its *closure* in the goal's (or, for an end, the start's) peel
from the outside in (:func:`hexbot.planning.dig.goal_peel`: the cell and
every cell built after it that its build needs): the modules a dig by that
peel moves. The union of the closures, as a share of the modules, says how
much of the shape the holes' digs move in all: near 1, filling the holes is
a rebuild of the whole shape, whatever order the digs take. The peel is
greedy (each cell keeps the trio with the fewest cells behind it), so a
closure is what our digs would move, not a proven minimum.
"""

from __future__ import annotations

import argparse
import json
import statistics

from hexbot.bench.planning import make_pair
from hexbot.cli_args import comma_list, count, whole_in


def closures(cells: frozenset, targets: set) -> list[frozenset]:
    from hexbot.planning import dig

    _, closure, _ = dig.goal_peel(cells)
    dig.forget()
    # a cell the peel never reaches needs the whole shape moved
    return [closure.get(t, cells) for t in sorted(targets)]


def measure(family: str, n: int, seed: int) -> dict:
    from hexbot.planning.bounds import move_lower_bound
    from hexbot.planning.surface import enclosed

    initial, goal = make_pair(family, n, seed)
    to_fill = enclosed(initial) & goal
    to_empty = enclosed(goal) & initial
    fill, empty = closures(goal, to_fill), closures(initial, to_empty)
    sizes = sorted(len(c) for c in fill + empty)
    return {
        "family": family, "modules": n, "seed": seed,
        "move_bound": move_lower_bound(initial, goal).value,
        "to_fill": len(to_fill), "to_empty": len(to_empty),
        "closure_median": statistics.median(sizes) if sizes else 0,
        "closure_max": sizes[-1] if sizes else 0,
        "fill_union_share": round(len(frozenset().union(*fill)) / n, 2),
        "empty_union_share": round(len(frozenset().union(*empty)) / n, 2),
    }


def add_arguments(parser: argparse.ArgumentParser) -> None:
    from hexbot.bench.planning import MAX_MODULES, family_list

    parser.add_argument("--families", type=family_list, default="holes",
                        help="comma-separated: holes, blob, scramble")
    parser.add_argument("--sizes", type=comma_list(whole_in(7, MAX_MODULES)),
                        default="100,300,1000", help="module counts, at least 7")
    parser.add_argument("--seeds", type=count, default=3, help="pairs per family and size")
    parser.add_argument("--json", action="store_true", help="JSON lines instead of a table")


def run(args: argparse.Namespace) -> int:
    families, sizes = args.families, args.sizes
    table = [measure(f, n, s) for f in families for n in sizes for s in range(args.seeds)]
    if args.json:
        for r in table:
            print(json.dumps(r))
        return 0
    print("| family | modules | seed | move bound | holes to fill | holes to empty "
          "| closure median | closure max | fill closures' union | empty closures' union |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for r in table:
        print(f"| {r['family']} | {r['modules']:,} | {r['seed']} | {r['move_bound']:,} | "
              f"{r['to_fill']} | {r['to_empty']} | {r['closure_median']:g} | "
              f"{r['closure_max']} | {r['fill_union_share']:.2f} | "
              f"{r['empty_union_share']:.2f} |")
    return 0
