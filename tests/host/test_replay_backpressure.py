"""A replay never runs ahead of the screen (session 36): on a loaded machine
the replay thread had posted the whole capture while the terminals still
lagged, so Escape and pause, queued behind it, found the replay over.

The capture's records are stamped 0 s: with no pacing the replay would post
them all at once, the worst case of a screen that lags. No wall-clock
measurement: the waits are bounds against a hang."""

from __future__ import annotations

import dataclasses
import threading
from pathlib import Path

from pilot_sync import settled, sync

from hexbot.host.capture import read_capture
from hexbot.host.console.app import HexBotConsole
from hexbot.host.console.terminal import Terminal
from hexbot.host.host import Host
from hexbot.host.replay_control import ReplayControl

CAPTURE = Path(__file__).parent / "data" / "flower7_session.hbcap"


def at_once() -> list:
    return [dataclasses.replace(r, t=0.0) for r in read_capture(CAPTURE)]


def test_the_replay_calls_back_after_each_record_once_its_events_are_out():
    records = at_once()
    heard: list[object] = []
    host = Host()
    host.add_listener(heard.append)
    after: list[int] = []  # events heard when each call came
    played = host.replay(records, control=ReplayControl(end=0.0), cancel=threading.Event(),
                         after_record=lambda: after.append(len(heard)))
    assert played == len(after) == len(records)
    # a record's own events (its bytes, a state change) went out before its call
    before = [0, *after[:-1]]
    assert all(n > b for r, b, n in zip(records, before, after, strict=True)
               if r.kind in ("rx", "tx", "state"))


@sync
async def test_escape_stops_a_replay_the_screen_has_not_caught_up_with():
    records = at_once()
    app = HexBotConsole(Host(), replay=records, start_ports=False)
    async with app.run_test(size=(100, 30)) as pilot:
        assert await settled(pilot, lambda: "ACK" in ir_text(app))
        await pilot.press("escape")
        assert await settled(pilot, lambda: not app.busy)
        # queued behind the whole capture, Escape came after its end: "done"
        assert "Replay: cancelled" in app.last_result, app.last_result
        assert "ACK 20 TurnOffAll" not in ir_text(app)  # the capture's last replies


def ir_text(app: HexBotConsole) -> str:
    return "\n".join(line.plain for line in app.query_one("#ir-term", Terminal).lines())
