"""Edges of the console a user meets (session 35's audit of the console):
the emergency stop while a workflow runs, what is refused while busy or
mis-addressed, the prompts' id lists, ctrl+r after a failed start, the Ports
tab's buttons, saving the terminals twice, the replay keys after the end.

A console on the pty test double (it answers at once) or on no port at
all; the waits are bounds against a hang, never measurements, so these run
with the parallel part of the suite (no ``wallclock`` mark)."""

from __future__ import annotations

from pilot_sync import settled, sync

from hexbot.host import cli_console
from hexbot.host.console.app import HexBotConsole
from hexbot.host.console.connection import MAX_BAUD, PortPanel
from hexbot.host.console.messages import SimEvent
from hexbot.host.console.terminal import Entry, Terminal
from hexbot.host.host import IR, Host
from hexbot.host.link import LinkState, PortSettings
from hexbot.host.session import select
from hexbot.protocol import frames
from hexbot.protocol.parser import parse_all
from hexbot.protocol.simulation import Moved

TURN_OFF_ALL = frames.encode_pc(frames.make("TurnOffAll"))


def on_pty(responder) -> HexBotConsole:
    host = Host()
    host.add_port(IR, PortSettings(responder.path), retry_s=0.1)
    return HexBotConsole(host)


def portless(**kw) -> HexBotConsole:
    """A console whose host has no port: nothing can be sent."""
    return HexBotConsole(Host(), start_ports=False, **kw)


def connected(app: HexBotConsole) -> bool:
    return app.port_states.get(IR, (None,))[0] is LinkState.CONNECTED


def toasts(app: HexBotConsole) -> list[str]:
    return [str(n.message) for n in app._notifications]


def status_line(app: HexBotConsole) -> str:
    return str(app.query_one("#status").render())


def long_step(app: HexBotConsole):
    """A step that waits for a cancel and then returns as if it ended well
    (the boot wait does: "boot wait cancelled")."""
    def step() -> str:
        assert app.session is not None
        app.session.sleep(60.0)
        return "stopped waiting"
    step.__name__ = "waiting"
    return step


async def ask(pilot, app: HexBotConsole, key: str, text: str) -> None:
    """A workflow's prompt (key), answered with ``text``."""
    await pilot.press(key)
    assert await settled(pilot, lambda: bool(app.screen.query("#prompt-input")))
    app.screen.query_one("#prompt-input").value = text
    await pilot.press("enter")


@sync
async def test_all_off_while_a_workflow_runs_cancels_it_then_turns_everything_off_once(
        responder):
    app = on_pty(responder)
    async with app.run_test(size=(100, 30)) as pilot:
        assert await settled(pilot, lambda: connected(app))
        app.start_operation("Long", [long_step(app)])
        assert await settled(pilot, lambda: app.busy.startswith("Long: waiting"))
        await pilot.press("o")
        assert await settled(pilot, lambda: app.last_result == "[red]Long: cancelled[/]")
        # (the three exchanges wait for the replies of seven modules in legacy mode)
        assert await settled(pilot, lambda: "All off" in app.last_result, limit_s=60), \
            app.last_result
        # the emergency stop ran once, all of it, and the console is free again
        assert app.busy == "" and not app.all_off_next, app.busy
        assert responder.received == [TURN_OFF_ALL, frames.encode_pc(select(0)), TURN_OFF_ALL]


@sync
async def test_escape_during_a_step_that_returns_afterwards_is_cancelled_not_done():
    app = portless()
    async with app.run_test(size=(100, 30)) as pilot:
        app.start_operation("Long", [long_step(app)])
        assert await settled(pilot, lambda: app.busy.startswith("Long: waiting"))
        await pilot.press("escape")
        assert await settled(pilot, lambda: not app.busy)
        assert app.last_result == "[red]Long: cancelled[/]"
        assert "Long: cancelled" in toasts(app)


@sync
async def test_nothing_else_starts_or_is_sent_while_a_workflow_runs(responder):
    app = on_pty(responder)
    async with app.run_test(size=(100, 30)) as pilot:
        assert await settled(pilot, lambda: connected(app))
        app.start_operation("Long", [long_step(app)])
        assert await settled(pilot, lambda: app.busy.startswith("Long: waiting"))
        app.send_command(frames.make("Status"))  # the composer's Send
        await pilot.pause()
        assert "busy: Long: waiting (escape cancels it)" in toasts(app)
        await pilot.press("t")  # a second workflow
        await pilot.pause()
        assert app.busy.startswith("Long"), app.busy
        assert "busy: Long: waiting" in toasts(app)
        await pilot.press("escape")
        assert await settled(pilot, lambda: not app.busy)
        await pilot.pause(0.2)
        assert responder.received == []


@sync
async def test_ref_after_select_all_is_refused_before_anything_is_sent(responder):
    # every module that runs Ref becomes (0, 0): two origins
    app = on_pty(responder)
    async with app.run_test(size=(100, 30)) as pilot:
        assert await settled(pilot, lambda: connected(app))
        await ask(pilot, app, "s", "0")
        assert await settled(pilot, lambda: not app.busy and "Select 0" in app.last_result)
        assert "sel all" in status_line(app)
        await pilot.press("r")
        await pilot.pause()
        assert any("select exactly one module" in t for t in toasts(app)), toasts(app)
        assert responder.received == [frames.encode_pc(select(0))]


@sync
async def test_select_takes_ids_with_commas_and_localize_exactly_one_reference(responder):
    app = on_pty(responder)
    async with app.run_test(size=(100, 30)) as pilot:
        assert await settled(pilot, lambda: connected(app))
        await ask(pilot, app, "s", "2,5")
        assert await settled(pilot, lambda: not app.busy and app.last_result)
        assert responder.received == [frames.encode_pc(select(2, 5))]
        assert "sel 2,5" in status_line(app)
        await ask(pilot, app, "l", "2 5")  # it used to take 2 and drop 5
        await pilot.pause()
        assert any("one reference module" in t for t in toasts(app)), toasts(app)
        assert not app.busy and len(responder.received) == 1


@sync
async def test_rotate_needs_two_known_modules(responder):
    app = on_pty(responder)
    async with app.run_test(size=(100, 30)) as pilot:
        assert await settled(pilot, lambda: connected(app))
        app.select_modules([3])  # module 3 answers: the one module known
        assert await settled(pilot, lambda: not app.busy and app.last_result)
        assert app.known_ids() == [3]
        await pilot.press("w")
        await pilot.pause()
        assert "need two known modules: localize first (l)" in toasts(app)
        assert not app.screen.query("#rot-go")


@sync
async def test_ctrl_r_after_a_failed_start_clears_the_alert_and_opens_anew(
        responder, tmp_path):
    bad = tmp_path / "bad.toml"
    bad.write_text('name = "bad"\nbase = 1\n\n[[module]]\nid = 1\nposition = [0, 0]\n'
                   'colour = "red"\n')
    attempts = [cli_console.parse(["--scenario", str(bad), "--no-log"]),
                cli_console.parse(["--port", responder.path, "--no-log"])]

    def opener(listeners):  # the first start fails, the second finds the port
        return cli_console.make_opener(attempts.pop(0))(listeners)

    app = HexBotConsole(opener=opener)
    async with app.run_test(size=(100, 30)) as pilot:
        alert = app.query_one("#alert")
        assert await settled(pilot, lambda: alert.display, limit_s=60)
        assert app.failure_status == 4
        # the start failed: nothing runs any more, the status line says so
        assert app.busy == "" and "cannot open session" in status_line(app)
        await pilot.press("ctrl+r")
        assert await settled(pilot, lambda: connected(app))
        assert not alert.display and app.failure_status is None
    assert app.failure_status is None  # `hexbot console` exits 0 after quitting now


@sync
async def test_disconnect_and_connect_on_the_ports_tab(responder):
    app = on_pty(responder)
    async with app.run_test(size=(100, 40)) as pilot:
        assert await settled(pilot, lambda: connected(app))
        await pilot.press("5")
        await pilot.click("#ir-disconnect")
        assert await settled(pilot, lambda: app.port_states[IR][0] is LinkState.CLOSED)
        assert "closed" in str(app.query_one("#ir-state").render())
        await pilot.click("#ir-connect")
        assert await settled(pilot, lambda: connected(app))


@sync
async def test_a_baud_rate_out_of_range_is_refused_and_the_port_stays(responder):
    app = on_pty(responder)
    async with app.run_test(size=(100, 40)) as pilot:
        assert await settled(pilot, lambda: connected(app))
        await pilot.press("5")
        panel = app.query_one(f"#port-{IR}", PortPanel)
        baud = app.query_one("#ir-baud")
        baud.value = str(MAX_BAUD)
        assert panel.read_settings().baud == MAX_BAUD  # the top is allowed
        baud.value = "0"
        await pilot.click("#ir-connect")
        await pilot.pause()
        assert f"baud must be 1..{MAX_BAUD}, got '0'" in toasts(app)
        assert connected(app)


@sync
async def test_two_saves_in_a_row_keep_both_files(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)  # no session log: the current folder
    app = portless()
    async with app.run_test(size=(100, 30)) as pilot:
        term = app.query_one("#ir-term", Terminal)
        term.add(Entry(0.5, "tx", data=frames.encode_pc(frames.make("Status"))))
        await pilot.press("ctrl+s")
        term.cycle_mode()  # the text view, saved a moment later
        await pilot.press("ctrl+s")
        await pilot.pause()
    saved = list(tmp_path.glob("terminal-ir-*.txt"))
    assert len(saved) == 2, saved
    assert {p.read_text() for p in saved} == {"    0.500 > Status()\n",
                                              "    0.500 > *FNNNNNNNN#\n"}
    assert len(list(tmp_path.glob("terminal-debug-*.txt"))) == 2


@sync
async def test_the_search_key_on_another_tab_shows_the_terminals():
    app = portless()
    async with app.run_test(size=(100, 30)) as pilot:
        await pilot.press("2", "slash")
        assert app.query_one("#tabs").active == "terminals"
        assert app.focused is app.query_one("#ir-term .term-search")


@sync
async def test_clear_resets_the_counters_and_the_last_ack():
    app = portless()
    async with app.run_test(size=(100, 30)) as pilot:
        term = app.query_one("#ir-term", Terminal)
        term.add(Entry(0.5, "tx", data=frames.encode_pc(select(2))))
        term.add(Entry(0.9, "rx", data=b"\n\rM02: ACKE\n\r"))
        for ev in parse_all(b"\n\rM02: ACKE\n\r"):
            term.add(Entry(0.9, "event", event=ev))
        info = term.query_one(".term-info")
        assert str(info.render()) == "decoded | in 13 B | out 11 B | ACK M02 69 Select"
        await pilot.press("ctrl+l")
        assert str(info.render()) == "decoded | in 0 B | out 0 B"
        assert term.lines() == []


@sync
async def test_the_replay_keys_after_the_replay_ended_say_so():
    app = HexBotConsole(Host(), replay=[], start_ports=False)
    async with app.run_test(size=(100, 30)) as pilot:
        assert await settled(pilot, lambda: not app.busy and "Replay" in app.last_result)
        await pilot.press("p")
        await pilot.pause()
        assert "no replay is playing" in toasts(app)
        assert app.replay_control is not None and not app.replay_control.paused


@sync
async def test_the_lattice_legend_lists_the_plants_newest_verdicts():
    app = portless()
    async with app.run_test(size=(100, 30)) as pilot:
        for k in range(5):
            app.post_message(SimEvent(Moved(float(k), 2, (k, 0), (k + 1, 0), 0, 4)))
        def legend() -> str:  # redrawn once per burst of events
            return str(app.query_one("#lattice-legend").render())
        assert await settled(pilot, lambda: "module 2 moved (4, 0) -> (5, 0)" in legend()), \
            legend()
        assert "module 2 moved (0, 0) -> (1, 0)" not in legend()
