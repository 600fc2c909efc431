"""The rotate dialog's limits and the help screen's keys (session 35's
audit): Textual's pilot, the real screens."""

from __future__ import annotations

from pilot_sync import sync
from textual.app import App
from textual.widgets import Input, Label

from hexbot.host.console.app import HexBotConsole
from hexbot.host.console.dialogs import HelpScreen, RotateScreen
from hexbot.host.host import Host


async def rotate_with(pilot, app: App, joint: str, mobile, substrate) -> tuple[str, list]:
    """Fill the rotate dialog and press Rotate: (its complaint, what it returned)."""
    chosen: list = []
    app.push_screen(RotateScreen([1, 2]), chosen.append)
    await pilot.pause()
    dialog = app.screen
    dialog.query_one("#rot-joint", Input).value = joint
    if mobile is not None:
        dialog.query_one("#rot-mobile").value = mobile
    if substrate is not None:
        dialog.query_one("#rot-substrate").value = substrate
    await pilot.pause()
    dialog.query_one("#rot-go").press()
    await pilot.pause()
    complaint = str(dialog.query_one("#rot-error", Label).render()) if not chosen else ""
    if not chosen:
        app.pop_screen()
        await pilot.pause()
    return complaint, chosen


@sync
async def test_the_rotate_dialog_takes_joints_1_to_6_and_two_different_modules():
    app = App()
    async with app.run_test() as pilot:
        assert await rotate_with(pilot, app, "7", 2, 1) == ("joint must be 1..6", [])
        assert await rotate_with(pilot, app, "", 2, 1) == ("joint must be 1..6", [])
        assert await rotate_with(pilot, app, "3", 2, 2) == ("pick two different modules", [])
        assert await rotate_with(pilot, app, "3", None, 1) == ("pick two different modules", [])
        assert await rotate_with(pilot, app, "6", 2, 1) == ("", [("cw", 6, 2, 1)])


@sync
async def test_q_closes_the_help_and_leaves_the_console_running():
    app = HexBotConsole(Host(), start_ports=False)
    async with app.run_test(size=(100, 36)) as pilot:
        await pilot.press("f1")
        assert isinstance(app.screen, HelpScreen)
        await pilot.press("q")
        await pilot.pause()
        assert not isinstance(app.screen, HelpScreen)
        assert app.is_running
        await pilot.press("2")
        assert app.query_one("#tabs").active == "compose"
