"""``hexbot locomotion``: run a rule set on a scenario, list what ships.

    hexbot locomotion run salvador-free flat --n 20 --until-advance 5 --json
    hexbot locomotion run salvador histogram-1 --n 10 --render run.gif
    hexbot locomotion list
    hexbot locomotion random salvador --seeds 0:300 --json
"""

from __future__ import annotations

import argparse
import json
import sys

from hexbot.cli_args import comma_list, count, image_file, one_of, whole_in
from hexbot.errors import UsageError
from hexbot.host.cli_progress import meter
from hexbot.planning.locomotion import render
from hexbot.planning.locomotion.scenarios import (
    MAX_MODULES,
    load_ruleset,
    load_scenario,
    ruleset_names,
    scenario_names,
    simulate,
)

#: ``--n``: modules in the strip (also the check of the sweep kind's ``n``).
strip_size = whole_in(1, MAX_MODULES)


def add_arguments(parser: argparse.ArgumentParser) -> None:
    sub = parser.add_subparsers(dest="action", metavar="ACTION", required=True)
    run = sub.add_parser("run", help="run RULESET on SCENARIO and report the outcome")
    run.add_argument("ruleset", help="salvador-free, salvador-pyramids, salvador, otero, or a file")
    run.add_argument("scenario", help="flat, a shipped map (see 'list'), or a .map file")
    run.add_argument("--n", type=strip_size, default=None,
                     help=f"modules in the strip (1..{MAX_MODULES:,})")
    run.add_argument("--rounds", type=count, default=10_000, help="round limit (10000)")
    run.add_argument(
        "--until-advance", type=count, default=None, metavar="K",
        help="stop when K modules have come to rest past the strip's initial cells",
    )
    run.add_argument("--json", action="store_true", help="print one JSON object")
    run.add_argument("--render", metavar="OUT", type=image_file((".png", ".gif")),
                     help="draw the run: .png (final) or .gif")
    run.add_argument(
        "--no-connectivity-check", action="store_true",
        help="skip the connectivity invariant (faster on huge runs)",
    )
    sub.add_parser("list", help="list the shipped rule sets and scenarios")
    bank = sub.add_parser("bank", help="run every scenario of the test bank for several n")
    bank.add_argument("--rulesets", default="salvador-pyramids,salvador",
                      help="comma-separated rule sets (default: salvador-pyramids,salvador)")
    bank.add_argument("--n", type=strip_sizes, default="5,10,20",
                      help="comma-separated strip sizes (5,10,20)")
    bank.add_argument("--rounds", type=count, default=3000, help="round limit per run (3000)")
    bank.add_argument("--directions", action="store_true",
                      help="also run the north, west and south versions of every map")
    bank.add_argument("--json", action="store_true", help="JSON instead of a Markdown table")
    rnd = sub.add_parser("random", help="run a rule set on random obstacle maps; report "
                         "every broken invariant (replay one with: run RULESET random-SEED)")
    rnd.add_argument("ruleset", help="salvador, otero, ... or a file")
    rnd.add_argument("--seeds", default="0:100", help="seed range FIRST:END (0:100)")
    rnd.add_argument("--n", type=strip_sizes, default="5,12,20",
                     help="comma-separated strip sizes (5,12,20)")
    rnd.add_argument("--rounds", type=count, default=2500, help="round limit per run (2500)")
    rnd.add_argument("--json", action="store_true", help="print one JSON object")
    tables = sub.add_parser("tables", help="our rounds next to Tables 1-5 of Salvador's thesis")
    tables.add_argument("--only", default=None, help="comma-separated: table1,...,table5")
    tables.add_argument("--json", action="store_true", help="JSON instead of Markdown")


def run(args: argparse.Namespace) -> int:
    if args.action == "list":
        print("rule sets:", " ".join(ruleset_names()))
        print("scenarios:", " ".join(scenario_names()))
        return 0
    if args.action == "bank":
        return _bank(args)
    if args.action == "tables":
        return _tables(args)
    if args.action == "random":
        return _random(args)
    rs = load_ruleset(args.ruleset)
    sc = load_scenario(args.scenario, args.n)
    rec = None
    if args.render:  # a GIF keeps 400 to 800 frames of a long run; a PNG the last one
        rec = render.Recorder(last_only=args.render.lower().endswith(".png"))
    result = simulate(
        rs, sc, rounds=args.rounds, until_advance=args.until_advance, on_round=rec,
        check_connectivity=not args.no_connectivity_check,
    )
    if rec is not None:
        render.save(args.render, rec, sc.obstacles + result.obstacles)
    if args.json:
        out = {"ruleset": rs.name, "scenario": sc.name, "n": len(sc.modules)}
        out.update(result.to_dict())
        print(json.dumps(out))
    else:
        print(f"rule set {rs.name}, scenario {sc.name}, n = {len(sc.modules)}")
        print(f"status: {result.status} after {result.rounds} rounds; advanced {result.advanced}")
        if result.violation:
            v = result.violation
            print(f"violation ({v.kind}) in round {v.round}: {v.message}")
            print(f"  cells: {v.cells}\n  rules: {'; '.join(v.rules)}")
        if result.deadlock:
            d = result.deadlock
            print(f"deadlock: {d.message}; modules not at rest: {d.moving_states}")
        print("moves per module:", " ".join(map(str, result.moves_per_module)))
        print(render.ascii_map(result.positions, result.states, result.obstacles))
    return run_status(result.status, has_goal=args.until_advance is not None
                      or sc.threshold is not None)


def run_status(status: str, *, has_goal: bool) -> int:
    """The exit status of a run (docs/console.md, Exit statuses): 0 the goal
    was reached (or, without a goal, the rounds ran out as asked); 1 the
    rules failed (deadlock, broken invariant); 3 the rounds ran out before
    the goal, as a time-out does."""
    if status in ("advanced", "reached"):
        return 0
    if status == "rounds-exhausted":
        return 3 if has_goal else 0
    return 1


#: ``--n`` of ``bank`` and ``random``: comma-separated strip sizes.
strip_sizes = comma_list(strip_size)


def _bank(args: argparse.Namespace) -> int:
    from hexbot.planning.locomotion import bank

    rulesets = [r.strip() for r in args.rulesets.split(",") if r.strip()]
    if not rulesets:
        raise UsageError(f"--rulesets: give at least one rule set, not {args.rulesets!r}")
    for r in rulesets:
        load_ruleset(r)  # fail early on a misspelt name
    rows = bank.run_bank(rulesets, args.n, args.rounds, args.directions)
    if args.json:
        print(json.dumps([r.to_dict() for r in rows]))
    else:
        print(bank.bank_markdown(rows))
    # the bank reproduces the theses' tables: deadlocks and broken invariants
    # are results in the table (the pyramid rules break some by design), so
    # the run succeeds; stderr names them, where a reader of the exit
    # status alone would miss them
    broken = [r for r in rows if r.status == "violation"]
    if broken:
        print(f"{len(broken)} of {len(rows)} runs broke an invariant, e.g. {broken[0].ruleset} "
              f"on {broken[0].scenario}, n = {broken[0].n}: {broken[0].detail}", file=sys.stderr)
    return 0


def map_seed(text: str) -> int:
    """argparse type of a random map's seed: a whole number 0 or more (the
    ends of ``random --seeds``, the sweep kind's ``seed``). A map is named
    ``random-SEED``, and ``random--1`` names no map a replay can load."""
    if not text.strip().isdecimal() or int(text) > sys.maxsize:
        raise argparse.ArgumentTypeError(f"a map seed is a whole number 0..{sys.maxsize}, "
                                         f"got {text!r}")
    return int(text)


def _seed_range(text: str) -> range:
    first, sep, end = text.partition(":")
    try:
        if not sep:
            raise argparse.ArgumentTypeError
        low, high = map_seed(first), map_seed(end)
    except argparse.ArgumentTypeError:
        raise UsageError(f"--seeds: expected FIRST:END (e.g. 0:100), not {text!r}") from None
    if high <= low:
        raise UsageError(f"--seeds: {text!r} is empty (END must be above FIRST)")
    return range(low, high)


def _random(args: argparse.Namespace) -> int:
    from hexbot.planning.locomotion import randommaps

    seeds = _seed_range(args.seeds)
    rs = load_ruleset(args.ruleset)
    sizes = args.n
    report, done = randommaps.SweepReport(), 0
    # One seed at a time: a bar on the terminal, and Ctrl-C keeps what finished.
    with meter(f"random maps, {rs.name}", len(seeds)) as bar:
        try:
            for seed in seeds:
                part = randommaps.sweep(rs, [seed], sizes, args.rounds)
                report.runs += part.runs
                report.outcomes.update(part.outcomes)
                report.violations += part.violations
                done += 1
                bar.advance()
        except KeyboardInterrupt:
            pass
    finished = f"{seeds.start}:{seeds.start + done}"
    interrupted = done < len(seeds)
    if args.json:
        print(json.dumps({"ruleset": rs.name, "seeds": finished, "interrupted": interrupted,
                          **report.to_dict()}))
    else:
        counts = ", ".join(f"{k} {v}" for k, v in sorted(report.outcomes.items()))
        print(f"rule set {rs.name}, random maps {finished}: {report.runs} runs: {counts}")
        for v in report.violations:
            print(f"  random-{v['seed']} n = {v['n']}: {v['kind']} in round {v['round']} "
                  f"at {[tuple(c) for c in v['cells'][:3]]} ({'; '.join(v['rules'])})")
    if interrupted:
        print(f"interrupted: {done} of {len(seeds)} seeds done (results above are theirs)",
              file=sys.stderr)
        return 130
    return 1 if report.violations else 0


def _tables(args: argparse.Namespace) -> int:
    from hexbot.planning.locomotion import bank

    try:
        keys = (list(bank.THESIS) if args.only is None
                else comma_list(one_of(bank.THESIS))(args.only))
    except argparse.ArgumentTypeError as exc:
        raise UsageError(f"--only: {exc}") from None
    tabs = [bank.thesis_table(k) for k in keys]
    if args.json:
        print(json.dumps(tabs))
    else:
        print("\n\n".join(bank.table_markdown(t) for t in tabs))
    return 0
