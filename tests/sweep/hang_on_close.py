"""A nanny preload whose teardown never ends: Dask's own close of a cluster
with such nannies waits for ever (tests/sweep/test_sweep_close.py)."""

from __future__ import annotations

import asyncio


async def dask_teardown(nanny) -> None:  # noqa: ARG001 - Dask's preload signature
    await asyncio.Event().wait()
