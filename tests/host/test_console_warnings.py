"""The console shows the host's warnings, which `hexbot send` prints as
`warning: ...`: firmware built from another protocol, a module that
restarted on its own. It used to drop them."""

from __future__ import annotations

import pytest
from pilot_sync import sync
from test_console import booted, ir_text, until

from hexbot.host import cli_console
from hexbot.host.console.app import HexBotConsole

pytestmark = pytest.mark.wallclock  # the simulator runs paced against the console


@sync
async def test_images_and_modules_of_another_protocol_are_said(old_schema_images, log_dir):
    args = cli_console.parse(["--port", f"hexbot-sim://pair?speed=5&firmware={old_schema_images}"])
    app = HexBotConsole(opener=cli_console.make_opener(args))
    async with app.run_test(size=(120, 36)) as pilot:
        await booted(pilot, app)
        image = (f"!! warning: {old_schema_images / 'comm.elf'}: it was built from protocol "
                 "schema 0badf00d")
        assert await until(pilot, lambda: image in ir_text(app))
        await pilot.press("s")  # Select: asks for the ids
        await pilot.press("2", "enter")
        assert await until(pilot, lambda: not app.busy and "Select" in app.last_result)
        await pilot.press("t")  # Status of the selection: the module says its schema
        running = "!! warning: module 2: module firmware speaks protocol schema 0badf00d"
        assert await until(pilot, lambda: running in ir_text(app)), ir_text(app)
