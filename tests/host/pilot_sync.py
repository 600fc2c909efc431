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
