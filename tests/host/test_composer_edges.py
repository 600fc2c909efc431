"""The composer's edges (session 35's audit): which function Enter opens
for a typed code or a name's start, a gap in the arguments, Enter in a form
that is not complete. A console on no port: nothing here sends."""

from __future__ import annotations

from pilot_sync import settled, sync

from hexbot.host.console.app import HexBotConsole
from hexbot.host.console.composer import Composer
from hexbot.host.host import Host


def portless() -> HexBotConsole:
    return HexBotConsole(Host(), start_ports=False)


async def filter_for(pilot, text: str) -> None:
    await pilot.press("2")
    await pilot.click("#fn-filter")
    await pilot.press(*text)


def preview(app: HexBotConsole) -> str:
    return str(app.query_one("#fn-preview").render())


@sync
async def test_a_typed_code_opens_that_function_not_one_whose_name_holds_the_digit():
    app = portless()
    async with app.run_test(size=(110, 32)) as pilot:
        await filter_for(pilot, "1")  # JxOpen is code 1; LFlash1 has a 1 in its name
        await pilot.press("enter")
        assert await settled(pilot, lambda: getattr(app.focused, "id", None) == "arg-0")
        assert app.query_one(Composer).function.name == "JxOpen"
        assert str(app.query_one("#fn-title").render()).startswith("1 JxOpen(")


@sync
async def test_names_that_start_with_the_filter_come_before_names_that_contain_it():
    app = portless()
    async with app.run_test(size=(110, 32)) as pilot:
        await filter_for(pilot, "mc")
        table = app.query_one("#fn-table")
        firsts = [str(table.get_row_at(i)[1]) for i in range(2)]
        assert firsts[0].startswith("MCW("), firsts  # before LMCW, which contains "mc"


@sync
async def test_a_gap_in_the_arguments_is_named_and_nothing_can_be_sent():
    app = portless()
    async with app.run_test(size=(110, 32)) as pilot:
        app.compose_function(67)  # CW: eight arguments
        await pilot.pause()
        app.query_one("#arg-0").value = "4"
        app.query_one("#arg-2").value = "4"  # the second left empty
        await pilot.pause()
        assert "fill in every argument up to the last one used" in preview(app), preview(app)
        assert app.query_one("#fn-send").disabled


@sync
async def test_enter_in_an_incomplete_form_moves_on_and_stops_at_the_last_field():
    app = portless()
    async with app.run_test(size=(110, 32)) as pilot:
        app.compose_function(1)  # JxOpen(i): one argument
        await pilot.pause()
        assert await settled(pilot, lambda: getattr(app.focused, "id", None) == "arg-0")
        await pilot.press("enter")  # nothing typed: the last field, nowhere to go
        await pilot.pause()
        assert app.focused is app.query_one("#arg-0")
        assert app.query_one(Composer).history == []
        app.compose_function(67)  # CW: Enter in its first field goes to the second
        await pilot.pause()
        assert await settled(pilot, lambda: getattr(app.focused, "id", None) == "arg-0")
        await pilot.press("4", "enter")
        assert await settled(pilot, lambda: getattr(app.focused, "id", None) == "arg-1")


@sync
async def test_the_history_lists_the_newest_first_and_enter_resends_it(responder):
    from hexbot.host.host import IR
    from hexbot.host.link import LinkState, PortSettings
    from hexbot.host.session import select
    from hexbot.protocol import frames

    host = Host()
    host.add_port(IR, PortSettings(responder.path), retry_s=0.1)
    app = HexBotConsole(host)
    async with app.run_test(size=(110, 32)) as pilot:
        composer = app.query_one(Composer)
        assert await settled(pilot, lambda: app.port_states.get(IR, (None,))[0]
                             is LinkState.CONNECTED)
        app.send_command(select(2))
        assert await settled(pilot, lambda: len(composer.history) == 1)
        app.send_command(frames.make("Status"))
        assert await settled(pilot, lambda: len(composer.history) == 2)
        await pilot.press("2")
        table = app.query_one("#fn-history")
        rows = [[str(c) for c in table.get_row_at(i)[:2]] for i in range(table.row_count)]
        assert rows == [["2", "Status()"], ["1", "Select(2)"]]
        table.focus()
        await pilot.press("enter")  # the first row: the newest
        assert await settled(pilot, lambda: len(responder.received) == 3)
        assert responder.received[2] == frames.encode_pc(frames.make("Status"))
