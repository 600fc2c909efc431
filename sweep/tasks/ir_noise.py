"""Kind ``ir-noise``: one IR link trial at a bit error rate, for a framing.

The trial itself is ``hexbot.bench.ir_noise.trial(framing, ber, seed,
commands) -> dict`` (the IR noise work of issue #14); this kind only puts
it on the grid. It is imported when a sweep uses the kind, and a build
without it stops the sweep before anything runs, saying what is missing.
"""

from __future__ import annotations

import importlib

from hexbot.errors import HexBotError
from hexbot.sweep.kinds import Param

TRIAL = "hexbot.bench.ir_noise"



def _check_framing(value: str) -> None:
    known = getattr(importlib.import_module(TRIAL), "FRAMINGS", None)
    if known is not None and value not in known:
        raise HexBotError(f"framing {value!r} is not one of {', '.join(known)}")


def _check_ber(value: float) -> None:
    if not 0.0 <= value <= 1.0:
        raise HexBotError(f"a bit error rate is 0..1, got {value:g}")


def _check_commands(value: int) -> None:
    if value < 1:
        raise HexBotError(f"a trial sends at least 1 command, got {value}")


PARAMS = [
    Param("framing", str, help="the link framing to test", check=_check_framing),
    Param("ber", float, help="bit error rate on the IR link", check=_check_ber),
    Param("seed", int, 0, "noise seed"),
    Param("commands", int, 100, "commands sent per trial", check=_check_commands),
]
COUNT_BY = (("framing", "ber"), "outcome")


def _trial():
    try:
        module = importlib.import_module(TRIAL)
    except ImportError as exc:
        raise HexBotError(f"kind ir-noise needs {TRIAL}.trial(framing, ber, seed, commands), "
                          f"which this installation lacks ({exc})") from exc
    trial = getattr(module, "trial", None)
    if not callable(trial):
        raise HexBotError(f"kind ir-noise needs {TRIAL}.trial(framing, ber, seed, commands); "
                          f"{TRIAL} has no such function")
    return trial


def ready() -> None:
    _trial()


def run(framing: str, ber: float, seed: int, commands: int) -> dict:
    figures = _trial()(framing=framing, ber=ber, seed=seed, commands=commands)
    # the trial echoes its inputs; the table has them as the task's columns
    return {key: value for key, value in figures.items()
            if key not in {p.name for p in PARAMS}}
