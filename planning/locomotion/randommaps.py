"""Random obstacle maps: a robustness sweep beyond the hand-drawn bank.

The bank has sixteen drawings; the invariants must hold on any obstacle. A
random map is a floor with columns of random width and height (a histogram)
and a few floating blocks (overhangs, cavities, tunnels), with the strip of
modules at its foot. ``sweep`` runs a rule set on many of them and reports
each run that breaks an invariant, with the map, so it can be replayed:

    hexbot locomotion random salvador --seeds 0:300 --n 5,12,20
    hexbot locomotion run salvador random-153 --n 12      # replay one of them
"""

from __future__ import annotations

import random
from collections import Counter
from collections.abc import Callable, Iterable
from dataclasses import dataclass, field

from hexbot.planning.locomotion.rules import RuleSet
from hexbot.planning.locomotion.scenarios import Scenario, parse_map, simulate

WIDTH, HEIGHT = 30, 8  # the obstacle field; the strip starts in columns 1-4


def random_map(seed: int) -> str:
    """The map text for ``seed`` (same seed, same map)."""
    rng = random.Random(seed)
    grid = [["."] * WIDTH for _ in range(HEIGHT)]

    def put(x: int, y: int) -> None:  # y = 0 is the row on the floor
        if 6 <= x < WIDTH - 4:
            grid[HEIGHT - 1 - y][x] = "#"

    x = 6
    while x < WIDTH - 4:
        width, height = rng.randint(1, 3), rng.randint(0, 5)
        for column in range(x, x + width):
            for y in range(height):
                put(column, y)
        x += width
    for _ in range(rng.randint(0, 3)):
        bx, by = rng.randint(7, WIDTH - 6), rng.randint(2, HEIGHT - 2)
        for column in range(bx, bx + rng.randint(1, 4)):
            put(column, by)
    grid[HEIGHT - 1][1:5] = ["o"] * 4
    rows = ["".join(r) for r in grid] + ["#" * WIDTH]
    return f"title: random map, seed {seed}\n" + "\n".join(rows) + "\n"


def random_scenario(seed: int, n: int) -> Scenario:
    """The same as ``load_scenario(f"random-{seed}", n)``."""
    return parse_map(random_map(seed), f"random-{seed}", f"random seed {seed}", n=n)


@dataclass
class SweepReport:
    runs: int = 0
    outcomes: Counter[str] = field(default_factory=Counter)
    violations: list[dict] = field(default_factory=list)

    def to_dict(self) -> dict:
        return {"runs": self.runs, "outcomes": dict(self.outcomes),
                "violations": self.violations}


def sweep(
    ruleset: RuleSet,
    seeds: Iterable[int],
    ns: Iterable[int],
    rounds: int = 2500,
    progress: Callable[[int], None] | None = None,
) -> SweepReport:
    """Run ``ruleset`` on every random map x strip size; violations in full."""
    report = SweepReport()
    sizes = list(ns)
    for seed in seeds:
        for n in sizes:
            result = simulate(ruleset, random_scenario(seed, n), rounds=rounds)
            report.runs += 1
            report.outcomes[result.status] += 1
            if result.violation:
                report.violations.append(
                    {"seed": seed, "n": n, **result.violation.to_dict()})
        if progress:
            progress(seed)
    return report
