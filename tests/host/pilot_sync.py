"""Run async tests without an asyncio plugin. A module of its own: with
several test folders in one run, ``from conftest import ...`` resolves to
whichever folder's conftest.py was loaded last."""

from __future__ import annotations

import asyncio
import functools


def sync(fn):
    """Run an async test (Textual's Pilot) without an asyncio plugin."""

    @functools.wraps(fn)
    def wrapper(*args, **kwargs):
        return asyncio.run(fn(*args, **kwargs))

    return wrapper


async def settled(pilot, pred, limit_s: float = 20.0) -> bool:
    """Whether ``pred()`` holds, giving the app up to ``limit_s`` to get
    there (a bound against a hang, not a measurement)."""
    for _ in range(int(limit_s / 0.05)):
        if pred():
            return True
        await pilot.pause(0.05)
    return pred()
