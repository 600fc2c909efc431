"""The console's dialogs on their own (Textual's pilot, no session)."""

from pilot_sync import sync
from textual.app import App
from textual.widgets import Input, Label

from hexbot.host.console.dialogs import RotateScreen


@sync
async def test_the_rotate_dialogs_complaint_goes_when_the_value_is_mended():
    # (audit) "joint must be 1..6" stayed on screen after the joint was fixed
    app = App()
    async with app.run_test() as pilot:
        app.push_screen(RotateScreen([1, 2]))
        await pilot.pause()
        dialog = app.screen
        dialog.query_one("#rot-joint", Input).value = "9"
        await pilot.pause()
        dialog.query_one("#rot-go").press()
        await pilot.pause()
        error = dialog.query_one("#rot-error", Label)
        assert "joint must be 1..6" in str(error.render())
        dialog.query_one("#rot-joint", Input).value = "4"
        await pilot.pause()
        assert str(error.render()) == ""
