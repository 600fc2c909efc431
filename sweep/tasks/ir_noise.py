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

PARAMS = [
    Param("framing", str, help="the link framing to test"),
    Param("ber", float, help="bit error rate on the IR link"),
    Param("seed", int, 0, "noise seed"),
    Param("commands", int, 100, "commands sent per trial"),
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
    return dict(_trial()(framing=framing, ber=ber, seed=seed, commands=commands))
