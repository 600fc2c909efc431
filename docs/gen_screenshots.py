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


def main() -> None:
    OUT.mkdir(parents=True, exist_ok=True)
    for name, (size, keys) in SHOTS.items():
        print(asyncio.run(shoot(name, size, keys)))


if __name__ == "__main__":
    main()
