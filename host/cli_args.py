"""Argument types of the host's CLI commands: a bad value is a usage error
(exit 2) before any port opens, not a surprise after the boot."""

from __future__ import annotations

import argparse


def seconds(text: str) -> float:
    """A duration that must be positive (a time-out, a quiet period)."""
    value = _number(text)
    if value <= 0:
        raise argparse.ArgumentTypeError(f"must be more than 0 seconds, got {text}")
    return value


def seconds_or_zero(text: str) -> float:
    """A duration that may be 0 (``--linger 0``: none)."""
    value = _number(text)
    if value < 0:
        raise argparse.ArgumentTypeError(f"must be 0 or more seconds, got {text}")
    return value


def _number(text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"not a number: {text!r}") from None
    if value != value or value in (float("inf"), float("-inf")):
        raise argparse.ArgumentTypeError(f"not a finite number: {text!r}")
    return value
