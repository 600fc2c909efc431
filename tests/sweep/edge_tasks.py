"""Dotted-path task functions of the sweep edge tests (workers import them by name)."""

from __future__ import annotations


def fail_on(seed: int, bad: int = -1, tag: str = "") -> dict:
    """Fails seed ``bad`` with a reason; every other seed sets ``failure`` to
    "" (empty: not a failure). ``tag`` only makes the task ids unique to a test."""
    return {"echo": seed, "failure": f"seed {seed} is bad" if seed == bad else ""}


def figure_named(seed: int, name: str = "seconds") -> dict:
    """A figure named like one of the row's own columns."""
    return {name: seed}
