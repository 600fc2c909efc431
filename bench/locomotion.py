"""Benchmark of the locomotion engine; prints one JSON object.

    hexbot bench locomotion            # the 10,000 x 10,000 case and smaller ones
    hexbot bench locomotion --quick    # small cases only

Each case runs a rule set on a flat strip of n modules for R rounds, or on a
map of the bank until the goal (at most R rounds), with the connectivity
check on as in every normal run, and reports the wall time, rounds per
second and module-rounds per second.
"""

from __future__ import annotations

import argparse
import json
import platform
import sys
import time

from hexbot.planning.locomotion import flat_scenario, load_ruleset, load_scenario, simulate
from hexbot.planning.locomotion.cli import run_status


def case(ruleset: str, n: int, rounds: int, scenario: str = "flat") -> dict:
    rs = load_ruleset(ruleset)
    sc = flat_scenario(n) if scenario == "flat" else load_scenario(scenario, n)
    start = time.perf_counter()
    result = simulate(rs, sc, rounds=rounds)
    seconds = time.perf_counter() - start
    return {
        "ruleset": ruleset,
        "scenario": scenario,
        "n": n,
        "rounds": result.rounds,
        "status": result.status,
        # as `hexbot locomotion run` judges it: a map's goal reached, no
        # deadlock or broken invariant (a flat strip has no goal)
        "ok": run_status(result.status, has_goal=sc.threshold is not None) == 0,
        "advanced": result.advanced,
        "total_moves": int(sum(result.moves_per_module)),
        "seconds": round(seconds, 3),
        "rounds_per_s": round(result.rounds / seconds, 1),
        "module_rounds_per_s": round(n * result.rounds / seconds),
    }


def add_arguments(ap: argparse.ArgumentParser) -> None:
    ap.add_argument("--quick", action="store_true", help="skip the 10,000 x 10,000 case")


def run(args: argparse.Namespace) -> int:
    cases = [("salvador-free", 100, 2000), ("salvador-pyramids", 1000, 2000),
             # obstacles: corks, openers and the `looped` search at work, to the goal
             ("salvador", 90, 3000, "histogram-3"), ("salvador", 90, 3000, "maze"),
             ("otero", 90, 3000, "wide-cavity-middle"), ("otero", 90, 3000, "maze")]
    if not args.quick:
        cases += [
            ("salvador-free", 10_000, 10_000),
            ("salvador-pyramids", 10_000, 10_000),
            ("salvador", 10_000, 10_000),
            ("otero", 10_000, 10_000),
        ]
    out = {
        "python": sys.version.split()[0],
        "machine": platform.machine(),
        "cases": [case(*c) for c in cases],
    }
    print(json.dumps(out, indent=2))
    failed = [f"{c['ruleset']} on {c['scenario']} ({c['n']}): {c['status']}"
              for c in out["cases"] if not c["ok"]]
    if failed:
        print("not ok: " + "; ".join(failed), file=sys.stderr)
    return 1 if failed else 0
