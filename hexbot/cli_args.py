"""Argument types shared by the CLI commands (host, simulator, planners): a
bad value is a usage error (exit 2) before any port opens or any work
starts, not a surprise after the boot or at the end of a long run."""

from __future__ import annotations

import argparse
import os
from collections.abc import Callable, Iterable
from pathlib import Path
from typing import TypeVar

T = TypeVar("T")


def _at_least(low: float, strict: bool, unit: str = "",
              high: float | None = None) -> Callable[[str], float]:
    """An argparse type: a finite number above ``low`` (``strict``) or not below
    it, and at most ``high`` when given."""
    suffix = f" {unit}" if unit else ""
    bound = f"more than {low:g}{suffix}" if strict else f"{low:g} or more{suffix}"

    def check(text: str) -> float:
        value = _number(text)
        if value < low or (strict and value == low):
            raise argparse.ArgumentTypeError(f"must be {bound}, got {text}")
        if high is not None and value > high:
            raise argparse.ArgumentTypeError(f"must be at most {high:g}{suffix}, got {text}")
        return value
    return check


def seconds_up_to(high: float, zero: bool = False) -> Callable[[str], float]:
    """An argparse type: a duration more than 0 seconds (``zero``: 0 or more)
    and at most ``high`` (``must be at most 3600 seconds, got 1e300``)."""
    return _at_least(0, not zero, "seconds", high)


#: A duration that must be positive (a time-out, a quiet period).
seconds = _at_least(0, True, "seconds")
#: A duration that may be 0 (``--linger 0``: none).
seconds_or_zero = _at_least(0, False, "seconds")
#: A factor that must be more than 0 (a replay's ``--speed``).
positive = _at_least(0, True)
#: A speed factor that may be 0 (``--speed 0``: as fast as it goes).
rate = _at_least(0, False)
#: A share, 0..1 (a random blob's compactness).
fraction = _at_least(0, False, high=1)

#: The slowest simulator speed (``sim_speed``): slower, a simulated second
#: takes hours of wall time, and 1e-300 overflowed the loop's sleep.
MIN_SIM_SPEED = 1e-3


def sim_speed(text: str) -> float:
    """A simulator's speed, times real time (``hexbot sim --speed``,
    ``--sim-speed``): 0 (as fast as it goes) or at least :data:`MIN_SIM_SPEED`."""
    value = rate(text)
    if 0 < value < MIN_SIM_SPEED:
        raise argparse.ArgumentTypeError(
            f"must be 0 (as fast as it goes) or at least {MIN_SIM_SPEED:g}, got {text}")
    return value


def count(text: str) -> int:
    """A whole number of at least 1 (modules, rounds, steps, threads, a baud rate)."""
    value = _whole(text)
    if value < 1:
        raise argparse.ArgumentTypeError(f"must be at least 1, got {value}")
    return value


def whole_in(low: int, high: int) -> Callable[[str], int]:
    """An argparse type: a whole number in ``low..high``; the message gives
    the range (``must be 1..100,000, got 0``)."""

    def check(text: str) -> int:
        value = _whole(text)
        if not low <= value <= high:
            raise argparse.ArgumentTypeError(f"must be {low:,}..{high:,}, got {value}")
        return value
    return check


def comma_list(item: Callable[[str], T]) -> Callable[[str], list[T]]:
    """An argparse type: a comma-separated list of at least one value, each
    checked by the argparse type ``item`` (``--sizes 10,30``). An empty list
    (``--sizes ""``) or an empty item (``5,,10``) is refused, not skipped:
    taking ``""`` as "none given" ran the whole default list."""

    def check(text: str) -> list[T]:
        parts = [part.strip() for part in text.split(",")]
        if not text.strip():
            raise argparse.ArgumentTypeError("empty list (is the variable that should "
                                             "hold it set?)")
        if "" in parts:
            raise argparse.ArgumentTypeError(f"an empty item in {text!r}")
        return [item(part) for part in parts]
    return check


def one_of(names: Iterable[str], what: str = "") -> Callable[[str], str]:
    """An argparse type: one of ``names`` (an item of :func:`comma_list`,
    where argparse's ``choices`` cannot check); ``what`` names the kind in the
    message (``unknown family 'rings' (known: ...)``)."""
    known = tuple(names)
    kind = f"{what} " if what else ""

    def check(text: str) -> str:
        if text not in known:
            raise argparse.ArgumentTypeError(
                f"unknown {kind}{text!r} (known: {', '.join(known)})")
        return text
    return check


def finite(text: str) -> float:
    """Any finite number (``nan``, ``inf`` and ``1e400`` refused)."""
    return _number(text)


def port_name(text: str) -> str:
    """A serial device or pyserial URL. An empty one (``--port "$PORT"`` with
    the variable unset) is a usage error: taking it as "no port given" would
    run the command on the embedded simulator and report its success."""
    if not text.strip():
        raise argparse.ArgumentTypeError("empty port name (is the variable that should "
                                         "hold it set?)")
    return text


def scenario_name(text: str) -> str:
    """A simulator scenario (a built-in name or a TOML file). An empty one
    (``--scenario "$SCENARIO"`` with the variable unset) is a usage error:
    taking it as "none given" ran the default scenario, or the script's."""
    if not text.strip():
        raise argparse.ArgumentTypeError("empty scenario name (is the variable that should "
                                         "hold it set?)")
    return text


def tcp_port(text: str) -> int:
    """A TCP port to listen on; 0 lets the system pick a free one."""
    value = _whole(text)
    if not 0 <= value <= 65535:
        raise argparse.ArgumentTypeError(f"a TCP port is 0..65535 (0: any free port), got {value}")
    return value


def output_file(text: str) -> str:
    """argparse type of a file to write: its folder must exist and the file
    must be writable now (usage error, exit 2), so the work is not done for a
    result that cannot be saved. Writable is tried, not guessed from the mode
    bits (root passes those, and /proc refuses anyway): a new file is created
    and removed at once, an existing regular file opened for appending."""
    path = Path(text)
    if not path.parent.exists():
        raise argparse.ArgumentTypeError(f"{text}: folder {path.parent} does not exist")
    if not path.parent.is_dir():
        raise argparse.ArgumentTypeError(f"{text}: {path.parent} is not a folder")
    if path.is_dir():
        raise argparse.ArgumentTypeError(f"{text}: is a folder, give a file name")
    try:
        if not os.path.lexists(path):
            os.close(os.open(path, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o644))
            path.unlink()
        elif not path.exists():  # a symlink to a file still to be made: make it there
            target = path.resolve()
            os.close(os.open(target, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o644))
            target.unlink()
        elif path.is_file():  # not a FIFO or a device: opening those may block
            with open(path, "ab"):
                pass
    except OSError as exc:
        raise argparse.ArgumentTypeError(
            f"{text}: cannot write: {exc.strerror or exc}") from None
    return text


def image_file(suffixes: tuple[str, ...]) -> Callable[[str], str]:
    """argparse type of a drawing to write (``--plot``, ``--render``): an
    :func:`output_file` whose name ends in one of ``suffixes`` (``(".png",
    ".gif")``, any case), since the suffix picks the format: a name without
    one, or with another, is a usage error before any work."""
    names = " or ".join(suffixes)

    def check(text: str) -> str:
        output_file(text)
        if not text.lower().endswith(tuple(s.lower() for s in suffixes)):
            raise argparse.ArgumentTypeError(f"{text}: the name must end in {names}")
        return text
    return check


def _whole(text: str) -> int:
    try:
        return int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"not a whole number: {text!r}") from None


def _number(text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"not a number: {text!r}") from None
    if value != value or value in (float("inf"), float("-inf")):
        raise argparse.ArgumentTypeError(f"not a finite number: {text!r}")
    return value
