"""Markdown tables and the generic summary of a sweep's rows."""

from __future__ import annotations

from collections import Counter
from collections.abc import Sequence
from numbers import Number
from typing import Any

OUTCOMES = ("ok", "failed", "error")
ENGINE_COLUMNS = ("task", "kind", "outcome", "error", "seconds")


def cell(value: Any) -> str:
    if value is None:
        return "-"
    if isinstance(value, bool):
        return "yes" if value else "no"
    if isinstance(value, float):
        return f"{value:.3g}" if abs(value) < 1000 else f"{value:,.0f}"
    if isinstance(value, int):
        return f"{value:,}"
    return str(value).replace("|", "\\|")


def sort_key(values: Sequence[Any]) -> tuple:
    """Orders mixed rows: numbers by value, before text; None first."""
    return tuple((0, 0, "") if v is None else (1, v, "") if isinstance(v, Number)
                 else (2, 0, str(v)) for v in values)


def markdown(header: Sequence[str], rows: Sequence[Sequence[Any]]) -> str:
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(cell(v) for v in row) + " |" for row in rows]
    return "\n".join(lines)


def group_keys(rows: list[dict], params: Sequence[str]) -> list[str]:
    """The parameters that vary, except seeds (a seed is a repetition, not a setting)."""
    return [p for p in params if p != "seed" and len({str(r.get(p)) for r in rows}) > 1]


def figures(rows: list[dict], params: Sequence[str]) -> list[str]:
    """Numeric figure columns (not parameters), then the task's run time."""
    skip = set(params) | set(ENGINE_COLUMNS)
    names: dict[str, None] = {}
    for row in rows:
        for k, v in row.items():
            if k not in skip and isinstance(v, Number) and not isinstance(v, bool):
                names[k] = None
    return [*names, "seconds"]


def generic(rows: list[dict], params: Sequence[str]) -> str:
    """Outcomes and mean figures per setting (every varying parameter but the seed)."""
    keys = group_keys(rows, params)
    numeric = figures(rows, params)
    groups: dict[tuple, list[dict]] = {}
    for row in rows:
        groups.setdefault(tuple(row.get(k) for k in keys), []).append(row)
    body = []
    for key, members in sorted(groups.items(), key=lambda kv: sort_key(kv[0])):
        counts = Counter(r["outcome"] for r in members)
        means = []
        for name in numeric:
            values = [r[name] for r in members if isinstance(r.get(name), Number)]
            means.append(sum(values) / len(values) if values else None)
        body.append([*key, len(members), *(counts[o] for o in OUTCOMES), *means])
    header = [*keys, "runs", *OUTCOMES, *(f"mean {n}" for n in numeric)]
    return markdown(header, body)
