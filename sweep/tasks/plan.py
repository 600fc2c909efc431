"""Kind ``plan``: one hex reconfiguration planned between a generated pair.

The pairs are ``hexbot bench planning``'s families, built the same way from
the same seeds (:mod:`hexbot.planning.generate`): ``blob`` (two compact
random blobs grown from (0, 0)), ``apart`` (the goal shifted clear of the
initial), ``parallelogram`` (the bench's fixed shapes; sizes 10, 30, 100,
300, 1000, checked with the other values of the grid by :func:`check_task`,
as ``hexbot bench planning --cases --sizes`` checks them). The planners are
called through their public entry points, ``plan_robust`` and
``plan_faithful``; the figures are the bench's row.
A plan that does not reach the goal fails the task with its reason.
"""

from __future__ import annotations

from hexbot.bench.planning import (
    PARALLELOGRAMS,
    apart,
    markdown_table,
    module_count,
    parallelogram_size,
    row,
    timed,
)
from hexbot.cli_args import fraction
from hexbot.errors import ScenarioError
from hexbot.planning.configuration import Configuration
from hexbot.planning.generate import parallelogram, random_blob
from hexbot.sweep.kinds import Param, cli_check
from hexbot.sweep.summary import generic

FAMILIES = ("blob", "apart", "parallelogram")
MODES = ("robust", "faithful-serial", "faithful-parallel")
TABLE_ROWS = 200  # the per-case table of docs/planning.md up to this many tasks


def _one_of(choices: tuple[str, ...]):
    def check(value: str) -> None:
        if value not in choices:
            raise ScenarioError(f"expected one of {', '.join(choices)}")
    return check


PARAMS = [
    Param("family", str, "blob", "blob, apart or parallelogram", check=_one_of(FAMILIES)),
    Param("modules", int, help="module count (hexbot bench planning --sizes's check)",
          check=cli_check(module_count)),
    Param("seed", int, 0, "pair seed (blob and apart)"),
    Param("mode", str, "robust", "robust, faithful-serial or faithful-parallel",
          check=_one_of(MODES)),
    Param("serial", bool, False, "robust mode: one move per time step"),
    Param("compact", float, 0.8, "blob compactness 0..1", check=cli_check(fraction)),
]
COUNT_BY = (("family", "modules", "mode"), "method")


_parallelogram_size = cli_check(parallelogram_size)


def check_task(params: dict) -> None:
    """A parallelogram task's size must be one the family has (two
    parameters together: the sweep checks it for every task of the grid)."""
    if params["family"] == "parallelogram":
        _parallelogram_size(params["modules"])


def pair(family: str, modules: int, seed: int, compact: float) -> tuple[frozenset, frozenset]:
    if family == "parallelogram":
        _parallelogram_size(modules)
        w, h, w2, h2 = PARALLELOGRAMS[modules]
        return parallelogram(w, h), parallelogram(w2, h2)
    a, b = random_blob(modules, 2 * seed, compact), random_blob(modules, 2 * seed + 1, compact)
    return (a, apart(a, b)) if family == "apart" else (a, b)


def run(family: str, modules: int, seed: int, mode: str, serial: bool, compact: float) -> dict:
    from hexbot.planning.robust import plan_robust
    from hexbot.planning.thesis.planner import plan_faithful

    a, b = pair(family, modules, seed, compact)
    initial = Configuration.from_cells(a)
    if mode == "robust":
        plan, seconds = timed(lambda: plan_robust(initial, b, parallel=not serial))
    else:
        plan, seconds = timed(lambda: plan_faithful(initial, b, parallel=mode.endswith("parallel")))
    figures = row(family, modules, plan, seconds, a, b)
    for name in ("family", "modules", "mode"):
        del figures[name]
    figures["plan_seconds"] = figures.pop("seconds")
    if not plan.reached:
        figures["failure"] = plan.reason or "goal not reached"
    return figures


def summarize(rows: list[dict]) -> str:
    """docs/planning.md's table, one line per task (small sweeps), and the
    mean figures per family, size and mode."""
    params = [p.name for p in PARAMS]
    parts = [generic(rows, params)]
    if len(rows) <= TABLE_ROWS:
        ordered = sorted(rows, key=lambda r: (r["family"], r["modules"], r["mode"], r["seed"]))
        parts.insert(0, markdown_table([_bench_row(r) for r in ordered]))
    return "\n\n".join(parts)


def _bench_row(r: dict) -> dict:
    case = r["family"] if r["family"] == "parallelogram" else f"{r['family']} seed {r['seed']}"
    if r["mode"] != "robust":
        case += f" {r['mode']}"
    return {**r, "family": case, "seconds": r["plan_seconds"] or 0.0,
            "reached": bool(r["reached"]), "method": r.get("method") or ""}
