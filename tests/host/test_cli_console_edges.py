"""``hexbot console`` as the shell sees it (session 35's audit): its exit
status after a session that could not start, and ``--replay`` of a session
folder. The console runs headless; a pilot quits it with ``q``."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from hexbot.cli import main
from hexbot.host.capture import read_capture
from hexbot.host.console.app import HexBotConsole
from hexbot.host.session_log import CAPTURE_NAME

CAPTURE = Path(__file__).parent / "data" / "flower7_session.hbcap"


def headless(monkeypatch, ready) -> list[HexBotConsole]:
    """Run the console headless; quit it with q once ``ready(app)``."""
    started: list[HexBotConsole] = []
    run = HexBotConsole.run

    def quit_when_ready(self, *args, **kwargs):
        started.append(self)

        async def pilot_run(pilot) -> None:
            for _ in range(1200):  # a bound against a hang, not a measurement
                if ready(self):
                    break
                await pilot.pause(0.05)
            await pilot.press("q")
        return run(self, headless=True, size=(100, 30), auto_pilot=pilot_run)

    monkeypatch.setattr(HexBotConsole, "run", quit_when_ready)
    return started


_BAD_SCENARIO = ('name = "bad"\nbase = 1\n\n[[module]]\nid = 1\nposition = [0, 0]\n'
                 'colour = "red"\n')


def test_a_session_that_could_not_start_exits_4_when_quit(tmp_path, monkeypatch, log_dir):
    # the UI's own net, for a scenario that went bad after the check at start
    from hexbot.host import endpoints

    monkeypatch.setattr(endpoints, "check_scenario", lambda ends: None)
    bad = tmp_path / "bad.toml"
    bad.write_text(_BAD_SCENARIO)
    started = headless(monkeypatch, lambda app: app.failure_status is not None)
    assert main(["console", "--scenario", str(bad), "--sim-speed", "5"]) == 4
    assert started and started[0].failure_status == 4


@pytest.mark.parametrize("scenario, reason", [
    ("nosuchscenario", "unknown scenario 'nosuchscenario': built-in ones are "),
    ("bad.toml", "bad.toml:7: unknown key 'colour' in [module]"),
    ("nosuch.toml", "nosuch.toml: no such scenario file"),
    ("nofw.toml", "comm image /nonexistent/comm.elf does not exist"),
])
def test_a_scenario_that_cannot_load_is_refused_before_the_console_opens(
        tmp_path, monkeypatch, log_dir, cli_status, scenario, reason):
    # (fuzz, session 37) it opened, said "cannot open" on the screen and
    # stayed until quit, while send, run and monitor exit 4 at once with the
    # reason: the console now does the same, before its UI starts
    (tmp_path / "bad.toml").write_text(_BAD_SCENARIO)
    (tmp_path / "nofw.toml").write_text(_BAD_SCENARIO.replace(
        'colour = "red"', 'firmware = { comm = "/nonexistent/comm.elf" }'))
    monkeypatch.chdir(tmp_path)
    started = headless(monkeypatch, lambda app: True)
    code, err = cli_status("console", "--scenario", scenario)
    assert code == 4 and not started
    (line,) = err.splitlines()
    assert line.startswith("hexbot console: error: cannot open hexbot-sim://") and reason in line
    assert not log_dir.exists()


def test_replay_of_a_session_folder_plays_its_capture(tmp_path, monkeypatch):
    folder = tmp_path / "session"
    folder.mkdir()
    shutil.copy(CAPTURE, folder / CAPTURE_NAME)
    started = headless(monkeypatch, lambda app: app.replay_control is not None)
    assert main(["console", "--replay", str(folder)]) == 0
    (app,) = started
    assert app.replay_records == list(read_capture(CAPTURE))
