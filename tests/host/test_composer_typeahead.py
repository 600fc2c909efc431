"""Keys typed right after Enter in the composer's filter belong to the form
that Enter opens: its first argument takes the focus only after a refresh,
and a key that came before that used to land in the filter (``693``: the
table emptied and the Select's argument stayed blank)."""

from __future__ import annotations

import pytest
from pilot_sync import settled, sync
from textual import events

from hexbot.host.console.app import HexBotConsole
from hexbot.host.console.composer import Composer
from hexbot.host.host import IR, Host
from hexbot.host.link import PortSettings

pytestmark = pytest.mark.wallclock  # a console against the pty double, as test_console.py


def console(responder) -> HexBotConsole:
    """A console on the pty double (it acknowledges what it gets)."""
    host = Host()
    host.add_port(IR, PortSettings(responder.path), retry_s=0.1)
    return HexBotConsole(host)


async def in_the_filter(pilot) -> None:
    await pilot.press("2")  # the composer's tab
    await pilot.click("#fn-filter")


def typed_at_once(app: HexBotConsole, *keys: tuple[str, str | None]) -> None:
    """Keys as a fast typist or a paste gives them: all queued before the
    console handles the first (the pilot's ``press`` waits after each)."""
    for key, char in keys:
        event = events.Key(key, char)
        event.set_sender(app)
        app._driver.send_message(event)  # what ``pilot.press`` does, without its waits


def focused_id(app: HexBotConsole) -> str | None:
    return getattr(app.focused, "id", None)


def form(app: HexBotConsole) -> tuple:
    """What a failure shows: the filter, the focus and the arguments typed."""
    return (app.query_one("#fn-filter").value, focused_id(app),
            [i.value for i in app.query(".arg-input")])


@sync
async def test_keys_typed_right_after_enter_go_to_the_first_argument(responder):
    app = console(responder)
    async with app.run_test(size=(100, 30)) as pilot:
        await in_the_filter(pilot)
        await pilot.press(*"69")
        typed_at_once(app, ("enter", "\r"), ("3", "3"), ("enter", "\r"))
        assert await settled(pilot, lambda: app.query_one(Composer).history), \
            form(app)
        assert app.query_one("#fn-filter").value == "69"
        assert str(app.query_one(Composer).history[0]) == "Select(3)"
        assert await settled(pilot, lambda: responder.received == [b"*E\x03NNNNNNN#"])


@sync
async def test_keys_typed_right_after_enter_on_a_function_without_arguments_are_not_lost(
        responder):
    # Ref has no argument: Enter focuses Send, and a second Enter sends it
    app = console(responder)
    async with app.run_test(size=(100, 30)) as pilot:
        await in_the_filter(pilot)
        await pilot.press(*"ref")
        typed_at_once(app, ("enter", "\r"), ("enter", "\r"))
        assert await settled(pilot, lambda: app.query_one(Composer).history), \
            form(app)
        assert str(app.query_one(Composer).history[0]) == "Ref()"
        assert app.query_one("#fn-filter").value == "ref"


@sync
async def test_keys_typed_after_an_enter_that_opens_nothing_stay_in_the_filter(responder):
    app = console(responder)
    async with app.run_test(size=(100, 30)) as pilot:
        await in_the_filter(pilot)
        await pilot.press(*"zzz")  # matches no function
        typed_at_once(app, ("enter", "\r"), ("q", "q"))
        assert await settled(pilot, lambda: app.query_one("#fn-filter").value == "zzzq"), \
            app.query_one("#fn-filter").value
        assert focused_id(app) == "fn-filter"
