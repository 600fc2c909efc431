"""Snapshot tests of the console's screens (pytest-textual-snapshot).

The console replays a session recorded on the simulator, so nothing in the
pictures depends on the clock or on pty names. After an intended layout
change: ``pytest tests/host/test_snapshots.py --snapshot-update`` and look
at the report before committing.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from hexbot.host.console.demo import demo_app, play

CAPTURE = Path(__file__).parent / "data" / "flower7_session.hbcap"

SCREENS = {
    "terminals_80x24": ((80, 24), []),
    "terminals_wide": ((140, 36), []),
    "terminals_hex": ((100, 30), ["m", "m"]),
    "composer_cw": ((110, 32), ["2", "tab", *"cw", "enter"]),
    "modules": ((100, 24), ["3"]),
    "lattice": ((100, 30), ["4"]),
    "ports": ((100, 32), ["5"]),
    "help": ((100, 36), ["f1"]),
}


@pytest.mark.parametrize("name", list(SCREENS))
def test_screen(name, snap_compare):
    size, keys = SCREENS[name]

    async def before(pilot):
        await play(pilot.app, pilot)

    assert snap_compare(demo_app(CAPTURE), press=keys, terminal_size=size, run_before=before)
