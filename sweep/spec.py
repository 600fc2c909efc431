"""Sweep files: a task kind and its parameter grid, checked before anything runs.

::

    kind = "locomotion"                   # a built-in kind, or package.module:function
    description = "Salvador's rules on random maps"
    output = "salvador-random"            # optional; the --out folder, relative to this file

    [grid]                                # one axis per list or range, scalars are fixed
    ruleset = ["salvador", "otero"]
    n = [5, 12, 20]
    seed = { start = 0, stop = 300 }      # range(0, 300); optional step = K
    rounds = 2500

The tasks are every combination of the axes (the first axis varies
slowest), each with the kind's defaults for what the grid leaves out. An
axis holds each value once and values of one type (ints and floats mix,
as floats); a grid of more than ``MAX_TASKS`` tasks is refused, its size
computed before any task is built. A kind's ``check_task``, when it has
one, checks each task's values together (the error names the task, at the
``[grid]`` line). A task's id is a hash of its kind and parameters: the same task has the same
id in every run, which is what ``--resume`` and a retried task rely on.

Every error names the file and the line: tomllib's own for syntax, the
key's line (found by :class:`~hexbot.toml_lines.TomlLines`) for the rest.
"""

from __future__ import annotations

import hashlib
import itertools
import json
import math
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from hexbot.errors import HexBotError, ScenarioError
from hexbot.files import load_toml, read_text
from hexbot.sweep.kinds import Kind, Param, load_kind
from hexbot.sweep.summary import ENGINE_COLUMNS
from hexbot.toml_lines import TomlLines, unknown_key

MAX_TASKS = 1_000_000  # a bigger grid is refused (split it into several sweep files)
TOP_KEYS = {"kind", "description", "output", "grid"}
RANGE_KEYS = {"start", "stop", "step"}


@dataclass(frozen=True)
class Task:
    id: str
    params: dict[str, Any]  # as written in the sweep file: the row's columns
    call: dict[str, Any]  # what the kind's function gets (paths resolved)


@dataclass
class Spec:
    path: Path
    kind: Kind
    description: str
    output: Path | None
    axes: dict[str, list[Any]]  # parameter -> its values (one value: fixed)

    @property
    def param_names(self) -> list[str]:
        """The grid's parameters, then the kind's defaults the grid leaves out."""
        return list(self.axes) + [n for n in self.kind.params or {} if n not in self.axes]

    def tasks(self) -> list[Task]:
        """Every task of the grid, in a fixed order."""
        return [Task(task_id(self.kind.name, params), params, self._call(params))
                for params in self._combinations()]

    def _combinations(self) -> Iterator[dict[str, Any]]:
        """Each task's parameters as written, the kind's defaults included."""
        defaults: dict[str, Any] = {}
        if self.kind.params:
            defaults = {n: p.default for n, p in self.kind.params.items() if n not in self.axes}
        for combo in itertools.product(*self.axes.values()):
            yield {**dict(zip(self.axes, combo, strict=True)), **defaults}

    def _call(self, params: dict[str, Any]) -> dict[str, Any]:
        if not self.kind.params:
            return dict(params)
        return {n: _resolve(self.path, self.kind.params[n], v) for n, v in params.items()}


def task_id(kind: str, params: dict[str, Any]) -> str:
    # repr: what JSON has no type for, a TOML date or time (a dotted-path kind's value)
    text = json.dumps({"kind": kind, "params": params}, sort_keys=True, default=repr)
    return hashlib.sha256(text.encode()).hexdigest()[:16]


def _resolve(spec_path: Path, param: Param, value: Any) -> Any:
    """A path parameter's value, relative to the sweep file (Param.path)."""
    if not param.path or not isinstance(value, str):
        return value
    if callable(param.path):  # it says which values are files
        return str((spec_path.parent / value).resolve()) if param.path(value) else value
    candidate = spec_path.parent / value
    return str(candidate.resolve()) if candidate.exists() else value


def load_spec(path: str | Path) -> Spec:
    """Read and check a sweep file; ScenarioError ``file:line: problem``."""
    path = Path(path)
    text = read_text(path, "the sweep file")
    return parse_spec(load_toml(text, path), text, path)


def parse_spec(data: dict[str, Any], text: str, path: Path) -> Spec:
    lines = TomlLines(text)

    def fail(line: int, problem: str) -> ScenarioError:
        return ScenarioError(f"{path}:{line}: {problem}")

    for key in sorted(set(data) - TOP_KEYS):
        raise fail(lines.find("", -1, key), unknown_key(key, TOP_KEYS))
    kind_name = data.get("kind")
    if not isinstance(kind_name, str):
        raise fail(lines.find("", -1, "kind"), "kind must name a task kind, e.g. "
                   'kind = "locomotion"')
    try:
        kind = load_kind(kind_name)
    except HexBotError as exc:
        raise fail(lines.find("", -1, "kind"), str(exc)) from exc
    description = data.get("description", "")
    if not isinstance(description, str):
        raise fail(lines.find("", -1, "description"), "description must be a string")
    output = data.get("output")
    if output is not None and not isinstance(output, str):
        raise fail(lines.find("", -1, "output"), "output must be a folder name (a string)")
    grid = data.get("grid")
    if not isinstance(grid, dict) or not grid:
        raise fail(lines.find("grid"), "a sweep needs a [grid] table with the kind's parameters")

    sizes = {}
    for name, raw in grid.items():
        size = _size(raw)
        if size > MAX_TASKS:
            raise fail(lines.find("grid", -1, name), f"{name}: {size:,} values; a sweep "
                       f"has at most {MAX_TASKS:,} tasks")
        sizes[name] = size
    total = math.prod(sizes.values())
    if total > MAX_TASKS:
        raise fail(lines.find("grid"), f"the grid has {total:,} tasks "
                   f"({' x '.join(f'{sizes[n]:,} {n}' for n in sizes if sizes[n] > 1)}); "
                   f"a sweep has at most {MAX_TASKS:,}")

    axes: dict[str, list[Any]] = {}
    for name, raw in grid.items():
        line = lines.find("grid", -1, name)
        if name in ENGINE_COLUMNS:  # the row's own column would overwrite it, or it that
            raise fail(line, f"{name}: the results table has a column of that name "
                       f"({', '.join(ENGINE_COLUMNS)} are the sweep's own): rename the "
                       "parameter")
        values = _values(raw, lambda problem, name=name, line=line:
                         fail(line, f"{name}: {problem}"))
        if isinstance(raw, list) and kind.params is None:  # a kind's Param checks the type
            values = _one_type(values, lambda problem, name=name, line=line:
                               fail(line, f"{name}: {problem}"))
        if kind.params is not None:
            param = kind.params.get(name)
            if param is None:
                raise fail(line, f"kind {kind.name} has no parameter {name!r} (it takes "
                           f"{', '.join(kind.params)})")
            values = [_checked(param, v, path, lambda p, line=line: fail(line, p))
                      for v in values]
        if isinstance(raw, list):
            _once_each(values, lambda problem, name=name, line=line:
                       fail(line, f"{name}: {problem}"))
        axes[name] = values
    if kind.params is not None:
        missing = [n for n, p in kind.params.items() if p.required and n not in axes]
        if missing:
            raise fail(lines.find("grid"), f"kind {kind.name} needs {', '.join(missing)} "
                       "in [grid]")
    spec = Spec(path, kind, description, (path.parent / output) if output else None, axes)
    if kind.check_task is not None:
        for params in spec._combinations():
            try:
                kind.check_task(spec._call(params))
            except HexBotError as exc:
                task = ", ".join(f"{n} = {params[n]!r}" for n in axes)
                raise fail(lines.find("grid"), f"the task {task}: {exc}") from exc
    return spec


def _size(raw: Any) -> int:
    """How many values an axis has, without building a range (0: let _values say why)."""
    if isinstance(raw, list):
        return len(raw)
    if isinstance(raw, dict):
        bounds = [raw.get("start", 0), raw.get("stop"), raw.get("step", 1)]
        if all(isinstance(b, int) and not isinstance(b, bool) for b in bounds) and bounds[2] > 0:
            start, stop, step = bounds
            return max(0, -(-(stop - start) // step))  # len(range()) overflows past 2**63
        return 0
    return 1


def _one_type(values: list[Any], fail) -> list[Any]:
    """A list axis's values, all of one type; ints among floats become floats."""
    types = {type(v) for v in values}
    if types == {int, float}:
        return [float(v) for v in values]
    if len(types) > 1:
        names = ", ".join(sorted(t.__name__ for t in types))
        raise fail(f"values of one type, please (this list mixes {names}: "
                   f"{_short(values)})")
    return values


def _once_each(values: list[Any], fail) -> None:
    seen: set[str] = set()
    for value in values:
        key = json.dumps(value, sort_keys=True, default=str)
        if key in seen:
            raise fail(f"{value!r} is in the list twice (a task runs once: "
                       "drop the repeat)")
        seen.add(key)


def _short(values: list[Any]) -> str:
    text = ", ".join(repr(v) for v in values[:6])
    return f"[{text}{', ...' if len(values) > 6 else ''}]"


def _values(raw: Any, fail) -> list[Any]:
    """An axis: a non-empty list, a range table, or one fixed value."""
    if isinstance(raw, list):
        if not raw:
            raise fail("an empty list gives no tasks")
        return raw
    if isinstance(raw, dict):
        unknown = set(raw) - RANGE_KEYS
        if unknown or "stop" not in raw:
            raise fail("a range is { start = A, stop = B } with optional step = K, "
                       f"not {sorted(raw)}")
        bounds = [raw.get("start", 0), raw["stop"], raw.get("step", 1)]
        if not all(isinstance(b, int) and not isinstance(b, bool) for b in bounds):
            raise fail("range bounds must be integers")
        if bounds[2] < 1:
            raise fail("range step must be at least 1")
        values = list(range(*bounds))
        if not values:
            raise fail(f"range {bounds[0]}..{bounds[1]} is empty (stop must be above start)")
        return values
    return [raw]


def _checked(param: Param, value: Any, spec_path: Path, fail) -> Any:
    if param.type is float and isinstance(value, int) and not isinstance(value, bool):
        value = float(value)
    if not isinstance(value, param.type) or (param.type is int and isinstance(value, bool)):
        raise fail(f"{param.name} must be {param.type.__name__}, not {value!r}")
    if param.check is not None:
        try:
            param.check(_resolve(spec_path, param, value))
        except HexBotError as exc:
            raise fail(f"{param.name} = {value!r}: {exc}") from exc
    return value
