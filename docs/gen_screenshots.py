"""Regenerate the console screenshots of docs/console.md (SVG, by Textual).

    .venv/bin/python docs/gen_screenshots.py

The console shows a session recorded on the simulator
(tests/host/data/flower7_session.hbcap: select, ref, localize, status,
rotate, all off), so the pictures are the same on every run.
"""

from __future__ import annotations

import asyncio
from pathlib import Path

from hexbot.host.console.demo import demo_app, play

ROOT = Path(__file__).resolve().parents[1]
CAPTURE = ROOT / "tests" / "host" / "data" / "flower7_session.hbcap"
OUT = ROOT / "docs" / "img"

#: file name -> (terminal size, keys pressed after the replay)
SHOTS: dict[str, tuple[tuple[int, int], list[str]]] = {
    "console-terminals-80x24": ((80, 24), []),
    "console-terminals-wide": ((140, 36), []),
    "console-terminals-hex": ((100, 30), ["m", "m"]),
    "console-composer": ((110, 32), ["2", "tab", *"cw", "enter"]),
    "console-modules": ((100, 24), ["3"]),
    "console-lattice": ((100, 30), ["4"]),
    "console-ports": ((100, 32), ["5"]),
    "console-help": ((100, 36), ["f1"]),
}


async def shoot(name: str, size: tuple[int, int], keys: list[str]) -> Path:
    app = demo_app(CAPTURE)
    async with app.run_test(size=size) as pilot:
        await play(app, pilot)
        for key in keys:
            await pilot.press(key)
            await pilot.pause()
        await pilot.pause(0.3)
        return Path(app.save_screenshot(f"{name}.svg", path=str(OUT)))


async def shoot_boards(name: str = "console-boards") -> Path:
    """The Boards tab needs a live simulator (a recording has no pins): the
    flower7 cluster, module 1 with joint 3 open and its positive side LEDs on."""
    from hexbot.host import cli_console
    from hexbot.host.commands import parse_command
    from hexbot.host.console.app import HexBotConsole
    from hexbot.host.console.boards_view import BoardsView

    args = cli_console.parse(["--scenario", "flower7", "--sim-speed", "20", "--no-log"])
    app = HexBotConsole(opener=cli_console.make_opener(args))
    async with app.run_test(size=(110, 20)) as pilot:
        while app.host is None or app.busy:
            await pilot.pause(0.2)
        for words in (["Select", "1"], ["JxOpen", "3"], ["SideOnAllP"]):
            app.send_command(parse_command(words))
        await pilot.press("6")
        view = app.query_one(BoardsView)
        while not any(r[0] == "1" and r[4] == "··3···" and r[7] == "++++++"
                      for r in view.rows()):
            await pilot.pause(0.2)
        return Path(app.save_screenshot(f"{name}.svg", path=str(OUT)))


def main() -> None:
    OUT.mkdir(parents=True, exist_ok=True)
    for name, (size, keys) in SHOTS.items():
        print(asyncio.run(shoot(name, size, keys)))
    print(asyncio.run(shoot_boards()))


if __name__ == "__main__":
    main()
