"""The test bank: every scenario, several n, each rule set; and the thesis tables.

``run_bank`` gives one row per (rule set, scenario, n): outcome, rounds,
advance, moves per module. ``thesis_tables`` puts our rounds next to Tables
1-5 of 001 for our reconstructions of its obstacles.
"""

from __future__ import annotations

import math
from dataclasses import asdict, dataclass

from hexbot.planning.locomotion.scenarios import (
    load_ruleset,
    load_scenario,
    scenario_names,
    simulate,
)


@dataclass
class BankRow:
    ruleset: str
    scenario: str
    n: int
    status: str
    rounds: int
    advanced: int
    moves_min: int
    moves_mean: float
    moves_max: int
    detail: str = ""

    def to_dict(self) -> dict:
        return asdict(self)


def run_one(ruleset: str, scenario: str, n: int, rounds: int) -> BankRow:
    rs = load_ruleset(ruleset)
    sc = load_scenario(scenario, n)
    res = simulate(rs, sc, rounds=rounds)
    moves = res.moves_per_module
    detail = ""
    if res.violation:
        v = res.violation
        detail = f"{v.kind} in round {v.round} at {v.cells[:3]}"
    elif res.deadlock:
        detail = res.deadlock.message
    return BankRow(
        ruleset, sc.name, n, res.status, res.rounds, res.advanced,
        min(moves), round(sum(moves) / len(moves), 1), max(moves), detail,
    )


def run_bank(
    rulesets: list[str], ns: list[int], rounds: int, directions: bool = False
) -> list[BankRow]:
    rows = []
    for rs in rulesets:
        for sc in scenario_names(with_directions=directions):
            if sc.startswith("flat"):
                continue  # flat has no goal to reach; Table 1 covers it
            for n in ns:
                rows.append(run_one(rs, sc, n, rounds))
    return rows


# --- Tables 1-5 of 001, typed in from the text -------------------------------

# rows: k label -> {n: rounds}
THESIS = {
    "table1": {
        "title": "Table 1: no obstacles (salvador-free on flat)",
        "ruleset": "salvador-free", "scenario": "flat",
        "ks": [1, 2, 5, 10, 50], "ns": [5, 10, 20, 50, 100],
        "rounds": [[7, 12, 22, 52, 102], [11, 16, 26, 56, 106], [23, 28, 38, 68, 118],
                   [43, 48, 58, 88, 138], [203, 208, 218, 248, 298]],
    },
    "table2": {
        "title": "Table 2: symmetric pyramid of Figure 20 (salvador-pyramids on pyramid)",
        "ruleset": "salvador-pyramids", "scenario": "pyramid",
        "ks": [1, 2, 5, 10, 50, "k*"], "ns": [5, 10, 20, 50, 100], "kstar": 153,
        "rounds": [[6, 11, 21, 51, 101], [10, 15, 25, 55, 105], [20, 25, 35, 65, 115],
                   [39, 44, 54, 84, 134], [188, 193, 203, 233, 283],
                   [597, 622, 672, 822, 1072]],
    },
    "table3": {
        "title": "Table 3: obstacle of Figure 29 (salvador on wide-cavity-middle)",
        "ruleset": "salvador", "scenario": "wide-cavity-middle",
        "ks": ["k*/32", "k*/16", "k*/8", "k*/4", "k*/2", "k*"], "ns": [5, 10, 20, 50, 70, 90],
        "kstar": 32,
        "rounds": [[12, 17, 27, 66, 90, 110], [21, 26, 40, 74, 97, 120],
                   [29, 34, 47, 92, 115, 146], [43, 52, 68, 126, 160, 194],
                   [77, 86, 114, 200, 260, 320], [147, 172, 222, 374, 478, 578]],
    },
    "table4": {
        "title": "Table 4: obstacle of Figure 30 (salvador on wide-diagonal)",
        "ruleset": "salvador", "scenario": "wide-diagonal",
        "ks": ["k*/32", "k*/16", "k*/8", "k*/4", "k*/2", "k*"], "ns": [5, 10, 20, 35, 50, 70],
        "kstar": 41,
        "rounds": [[12, 17, 27, 42, 57, 84], [12, 24, 34, 49, 71, 91],
                   [26, 31, 48, 70, 92, 119], [47, 52, 76, 101, 127, 154],
                   [86, 94, 109, 161, 208, 268], [165, 191, 241, 320, 395, 495]],
    },
    "table5": {
        "title": "Table 5: obstacle of Figure 33 (salvador on irregular-right)",
        "ruleset": "salvador", "scenario": "irregular-right",
        "ks": ["k*/32", "k*/16", "k*/8", "k*/4", "k*/2", "k*"], "ns": [5, 10, 15, 35, 50, 70],
        "kstar": 120,
        "rounds": [[9, 18, 23, 43, 62, 82], [25, 34, 39, 63, 82, 106],
                   [57, 69, 74, 105, 127, 151], [120, 129, 138, 178, 209, 250],
                   [252, 263, 276, 334, 378, 428], [473, 498, 525, 638, 713, 813]],
    },
}


def _k_value(label, kstar: int) -> int:
    if isinstance(label, int):
        return label
    if label == "k*":
        return kstar
    return max(1, math.ceil(kstar / int(label.split("/")[1])))


def thesis_table(key: str, rounds_limit: int = 20_000) -> dict:
    """Our rounds next to the thesis' for one table.

    Our k* is the advance at which every module has passed our obstacle; the
    thesis' k* (its obstacle) is printed beside it.
    """
    t = THESIS[key]
    rs = load_ruleset(t["ruleset"])
    cols = []
    for j, n in enumerate(t["ns"]):
        sc = load_scenario(t["scenario"], n)
        reach, our_kstar = None, None
        if "kstar" in t:  # run to the goal first, to learn our k*
            reach = simulate(rs, sc, rounds=rounds_limit)
            our_kstar = reach.advanced if reach.status == "reached" else None
        kmax = max(
            _k_value(k, our_kstar or 1) if isinstance(k, int) or our_kstar else 1 for k in t["ks"]
        )
        run = simulate(rs, sc, rounds=rounds_limit, until_advance=kmax)
        cells = []
        for i, k in enumerate(t["ks"]):
            thesis = t["rounds"][i][j]
            if not isinstance(k, int) and our_kstar is None:
                cells.append({"k": None, "ours": None, "thesis": thesis})
                continue
            kk = _k_value(k, our_kstar or 0)
            ours = run.advance_rounds[kk - 1] if kk <= len(run.advance_rounds) else None
            if k == "k*" and reach is not None:
                ours = reach.rounds
            cells.append({"k": kk, "ours": ours, "thesis": thesis})
        cols.append({
            "n": n, "our_status": reach.status if reach else run.status,
            "our_kstar": our_kstar,
            "thesis_kstar": t["kstar"] + n if "kstar" in t else None, "cells": cells,
        })
    return {"key": key, "title": t["title"], "ks": [str(k) for k in t["ks"]], "columns": cols}


def table_markdown(tab: dict) -> str:
    head = "| k | " + " | ".join(f"n={c['n']}" for c in tab["columns"]) + " |"
    lines = [f"**{tab['title']}** — cells: ours / thesis", "", head,
             "|---" * (len(tab["columns"]) + 1) + "|"]
    for i, k in enumerate(tab["ks"]):
        row = [k]
        for c in tab["columns"]:
            cell = c["cells"][i]
            ours = "—" if cell["ours"] is None else str(cell["ours"])
            kk = "" if cell["k"] is None or k.isdigit() else f" (k={cell['k']})"
            mark = " ✓" if cell["ours"] == cell["thesis"] else ""
            row.append(f"{ours} / {cell['thesis']}{kk}{mark}")
        lines.append("| " + " | ".join(row) + " |")
    if any(c["thesis_kstar"] for c in tab["columns"]):
        lines.append("")
        lines.append("k*: " + ", ".join(
            f"n={c['n']}: ours {c['our_kstar']} ({c['our_status']}), thesis {c['thesis_kstar']}"
            for c in tab["columns"]))
    return "\n".join(lines)


def bank_markdown(rows: list[BankRow]) -> str:
    lines = [
        "| rule set | scenario | n | outcome | rounds | advanced"
        " | moves/module min / mean / max | detail |",
        "|---|---|---|---|---|---|---|---|",
    ]
    for r in rows:
        lines.append(
            f"| {r.ruleset} | {r.scenario} | {r.n} | {r.status} | {r.rounds} | {r.advanced} | "
            f"{r.moves_min} / {r.moves_mean} / {r.moves_max} | {r.detail} |"
        )
    return "\n".join(lines)
