"""Kind ``locomotion``: one rule set on one map (random by seed, or shipped) for one n.

The task is ``hexbot locomotion run`` without the drawing; on random maps it
is one run of ``hexbot locomotion random`` (same map for the same seed). A
broken invariant fails the task, with the command that replays it.
"""

from __future__ import annotations

from collections import Counter

from hexbot.cli_args import count
from hexbot.planning.locomotion.cli import map_seed, strip_size
from hexbot.planning.locomotion.randommaps import random_scenario
from hexbot.planning.locomotion.scenarios import load_ruleset, load_scenario, simulate
from hexbot.sweep.kinds import Param, cli_check
from hexbot.sweep.summary import markdown, sort_key

RANDOM = "random"  # the scenario value that draws randommaps.random_map(seed)


def _check_scenario(name: str) -> None:
    if name != RANDOM:
        load_scenario(name)


PARAMS = [
    Param("ruleset", str, help="shipped rule set or .rules file", path=True, check=load_ruleset),
    Param("scenario", str, RANDOM, "'random' (the map of the seed), a shipped map or .map file",
          path=True, check=_check_scenario),
    # the checks of `hexbot locomotion run --n, --rounds, --until-advance`
    Param("n", int, 12, "modules in the strip", check=cli_check(strip_size)),
    # `hexbot locomotion random --seeds`'s check: -1 ran, and its replay named random--1
    Param("seed", int, 0, "random map seed (scenario 'random')", check=cli_check(map_seed)),
    Param("round_limit", int, 2500, "rounds before giving up", check=cli_check(count)),
    Param("until_advance", int, None, "stop when K modules rest past the strip's cells",
          check=cli_check(count)),
]
COUNT_BY = (("ruleset", "n"), "result")
RESULT_ORDER = ("reached", "advanced", "rounds-exhausted", "deadlock", "violation")


def run(ruleset: str, scenario: str, n: int, seed: int, round_limit: int,
        until_advance: int | None) -> dict:
    rs = load_ruleset(ruleset)
    sc = random_scenario(seed, n) if scenario == RANDOM else load_scenario(scenario, n)
    result = simulate(rs, sc, rounds=round_limit, until_advance=until_advance)
    v = result.violation
    figures = {
        "result": result.status,
        "rounds": result.rounds,
        "advanced": result.advanced,
        "total_moves": int(sum(result.moves_per_module)),
        "violation": v.kind if v else None,
        "violation_round": v.round if v else None,
    }
    if v:
        replay = sc.name if scenario == RANDOM else scenario
        figures["failure"] = (f"{v.kind} in round {v.round}: {v.message} (replay: hexbot "
                              f"locomotion run {ruleset} {replay} --n {n})")
    return figures


def summarize(rows: list[dict]) -> str:
    """docs/locomotion.md's random-map table: outcomes per rule set, then per n."""
    results = [r for r in RESULT_ORDER
               if r == "violation" or any(row.get("result") == r for row in rows)]
    out = []
    for keys in (("ruleset",), ("ruleset", "n")):
        counts: dict[tuple, Counter] = {}
        for row in rows:
            counts.setdefault(tuple(row[k] for k in keys), Counter())[row.get("result")] += 1
        header = ["rule set" if k == "ruleset" else k for k in keys] + ["runs", *results]
        body = [[*key, sum(c.values()), *(c[r] for r in results)]
                for key, c in sorted(counts.items(), key=lambda kv: sort_key(kv[0]))]
        out.append(markdown(header, body))
    return "\n\n".join(out)
