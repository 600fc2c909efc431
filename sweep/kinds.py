"""Task kinds: what one task of a sweep runs, and which parameters it takes.

A kind is a module with ``PARAMS`` (a list of :class:`Param`), a pure
function ``run(**params) -> dict`` of figures (a ``failure`` entry, when
not empty, marks the task failed and says why) and, optionally,
``ready()`` (raises when the kind cannot run in this installation),
``check_task(params)`` (raises a HexBotError saying what is wrong with a
combination of values, e.g. a size the task's family does not have: a
``Param``'s ``check`` sees one value), ``summarize(rows) -> str`` and
``COUNT_BY`` for the report. Workers import
the module by name, so the same sweep runs on any cluster where hexbot is
installed.

A sweep file names its kind in one of three ways:

* a built-in name (:data:`BUILTIN`);
* a name that an installed package registers in the entry-point group
  ``hexbot.sweep_kinds`` (value: the module);
* a dotted path ``package.module:function`` to any pure function taking
  the grid's parameters as keywords (parameters unchecked, generic report).

Kinds are imported only when a sweep uses them, and an import failure is a
clear error that keeps its cause (:func:`load_kind`).
"""

from __future__ import annotations

import argparse
import importlib
from collections.abc import Callable
from dataclasses import dataclass, field
from importlib.metadata import entry_points
from types import ModuleType
from typing import Any

from hexbot.errors import ScenarioError

ENTRY_POINT_GROUP = "hexbot.sweep_kinds"
REQUIRED = object()  # a Param's default when the sweep file must give it

BUILTIN: dict[str, str] = {
    "locomotion": "hexbot.sweep.tasks.locomotion",
    "plan": "hexbot.sweep.tasks.plan",
    "hil-script": "hexbot.sweep.tasks.hil_script",
    "ir-noise": "hexbot.sweep.tasks.ir_noise",
}


@dataclass(frozen=True)
class Param:
    """One parameter of a kind. ``path``: a file or folder named relative to
    the sweep file (resolved there when it exists, else passed as written,
    e.g. a shipped name); or a function saying which values name a file
    (the hil-script scenario: ``hil_sim.scenario.is_scenario_file``): those
    are always resolved there, the others (built-in names) never, whatever
    files are there. ``check(value)`` raises a HexBotError whose text
    says what is wrong with a value, before anything runs."""

    name: str
    type: type
    default: Any = REQUIRED
    help: str = ""
    path: bool | Callable[[str], bool] = False
    check: Callable[[Any], None] | None = None

    @property
    def required(self) -> bool:
        return self.default is REQUIRED


@dataclass(frozen=True)
class Kind:
    name: str
    target: str  # "module:function", what a worker imports and calls
    params: dict[str, Param] | None  # None: a dotted-path kind, parameters unchecked
    module: ModuleType | None = field(default=None, compare=False)

    @property
    def summarize(self) -> Callable[[list[dict]], str] | None:
        return getattr(self.module, "summarize", None)

    @property
    def check_task(self) -> Callable[[dict[str, Any]], None] | None:
        """The kind's check of one task's parameters together (resolved, as
        ``run`` gets them), run for every task of the grid before any runs."""
        return getattr(self.module, "check_task", None) if self.params is not None else None

    @property
    def count_by(self) -> tuple[tuple[str, ...], str] | None:
        return getattr(self.module, "COUNT_BY", None)


def cli_check(argtype: Callable[[str], Any]) -> Callable[[Any], None]:
    """A :class:`Param` check made of a command's argparse type (``count``,
    ``hexbot locomotion run --n``'s ``strip_size``): the sweep refuses a value
    exactly when that command refuses it, in its words ("must be at least 1,
    got -1"), and a limit lives in one place."""

    def check(value: Any) -> None:
        try:
            argtype(str(value))
        except (argparse.ArgumentTypeError, ValueError) as exc:
            raise ScenarioError(str(exc) or f"{value!r} is refused") from None
    return check


def _import(module_name: str, what: str) -> ModuleType:
    try:
        return importlib.import_module(module_name)
    except ImportError as exc:
        raise ScenarioError(f"{what}: cannot import {module_name} ({exc})") from exc


def _from_module(name: str, module: ModuleType, check_ready: bool) -> Kind:
    ready = getattr(module, "ready", None)
    if ready is not None and check_ready:
        ready()
    params = {p.name: p for p in module.PARAMS}
    return Kind(name, f"{module.__name__}:run", params, module)


def registered() -> dict[str, str]:
    """Kind name -> module: the built-ins and the installed packages' entry points."""
    kinds = dict(BUILTIN)
    for ep in entry_points(group=ENTRY_POINT_GROUP):
        kinds.setdefault(ep.name, ep.value)
    return kinds


def load_kind(name: str, check_ready: bool = True) -> Kind:
    """The kind a sweep file names (a registered name or ``module:function``);
    ``check_ready``: also ask the kind whether it can run here."""
    kinds = registered()
    if name in kinds:
        return _from_module(name, _import(kinds[name], f"kind {name!r}"), check_ready)
    module_name, sep, function = name.partition(":")
    if not sep or not module_name or not function.isidentifier():
        raise ScenarioError(
            f"unknown kind {name!r}: use one of {', '.join(sorted(kinds))} "
            "or a dotted path package.module:function")
    module = _import(module_name, f"kind {name!r}")
    if not callable(getattr(module, function, None)):
        raise ScenarioError(f"kind {name!r}: {module_name} has no function {function!r}")
    return Kind(name, name, None, module)


def resolve_target(target: str) -> Callable[..., dict]:
    """The function behind ``module:function`` (on a worker)."""
    module_name, _, function = target.partition(":")
    return getattr(importlib.import_module(module_name), function)
