"""``hexbot sweep report``: the summary tables (and a plot) of a results folder.

The kind's own tables when it has them (the ones docs/locomotion.md and
docs/planning.md show), else outcomes and mean figures per setting; then
the failed tasks with their reasons.
"""

from __future__ import annotations

from collections import Counter
from pathlib import Path

from hexbot.errors import HexBotError
from hexbot.extras import require
from hexbot.sweep.kinds import load_kind, registered
from hexbot.sweep.results import read_table, table_meta
from hexbot.sweep.summary import OUTCOMES, generic, group_keys

FAILURES_LISTED = 20


def load_rows(folder: str | Path) -> tuple[str, list[str], list[dict]]:
    table = read_table(folder)
    if table is None:
        raise HexBotError(f"{folder}: no results (expected a folder written by hexbot sweep)")
    kind, params = table_meta(table)
    return kind, params, table.to_pylist()


def _own_summary(kind: str):
    """The kind's summarize() and COUNT_BY, for registered kinds (a dotted-path
    kind's module may be absent where the report runs)."""
    if kind not in registered():
        return None, None
    k = load_kind(kind, check_ready=False)  # reading rows needs no trial function
    return k.summarize, k.count_by


def report(folder: str | Path) -> str:
    kind, params, rows = load_rows(folder)
    counts = Counter(r["outcome"] for r in rows)
    total_s = sum(r["seconds"] for r in rows)
    lines = [f"{folder}: {len(rows)} tasks of kind {kind}: "
             + ", ".join(f"{o} {counts[o]}" for o in OUTCOMES)
             + f"; {total_s:.1f} s of task time", ""]
    summarize, _ = _own_summary(kind)
    lines.append(summarize(rows) if summarize else generic(rows, params))
    failed = [r for r in rows if r["outcome"] != "ok"]
    if failed:
        lines += ["", f"failed tasks ({len(failed)}):"]
        keys = [p for p in params if len({str(r.get(p)) for r in rows}) > 1] or params
        for r in failed[:FAILURES_LISTED]:
            where = ", ".join(f"{k}={r.get(k)}" for k in keys)
            lines.append(f"  {where}: {r['outcome']}: {r['error']}")
        if len(failed) > FAILURES_LISTED:
            lines.append(f"  ... and {len(failed) - FAILURES_LISTED} more")
    return "\n".join(lines)


def plot(folder: str | Path, out: str | Path) -> Path:
    """Stacked bars: how many tasks of each setting ended how."""
    plt = require("matplotlib.pyplot", "plot", "hexbot sweep report --plot")
    kind, params, rows = load_rows(folder)
    _, count_by = _own_summary(kind)
    keys, column = count_by or (tuple(group_keys(rows, params)), "outcome")
    groups: dict[str, Counter] = {}
    for r in rows:
        label = ", ".join(f"{k}={r.get(k)}" for k in keys) or kind
        groups.setdefault(label, Counter())[str(r.get(column) or r["outcome"])] += 1
    values = sorted({v for c in groups.values() for v in c})
    labels = sorted(groups)
    fig, ax = plt.subplots(figsize=(max(6, 0.6 * len(labels) + 2), 4))
    bottom = [0] * len(labels)
    for v in values:
        heights = [groups[label][v] for label in labels]
        ax.bar(labels, heights, bottom=bottom, label=v)
        bottom = [b + h for b, h in zip(bottom, heights, strict=True)]
    ax.set_ylabel("tasks")
    ax.set_title(f"{Path(folder).name}: {column} per setting")
    ax.legend()
    ax.tick_params(axis="x", labelrotation=45)
    fig.tight_layout()
    fig.savefig(out)
    plt.close(fig)
    return Path(out)
