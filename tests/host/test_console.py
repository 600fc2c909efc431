"""Pilot tests of the console: against the pty test double (fast) and
against the embedded simulator (the product path)."""

from __future__ import annotations

import pytest
from pilot_sync import sync
from textual.widgets import Label

from hexbot.host import cli_console
from hexbot.host.console.app import HexBotConsole
from hexbot.host.console.composer import Composer
from hexbot.host.console.connection import PortPanel
from hexbot.host.console.dialogs import PlanScreen
from hexbot.host.console.lattice import lattice_cells
from hexbot.host.console.modules_view import ModulesView
from hexbot.host.console.terminal import Terminal
from hexbot.host.host import IR, Host
from hexbot.host.link import LinkState, PortSettings
from hexbot.protocol import frames
from hexbot.protocol.simulation import Placement

# The simulator runs at a set speed against the console's reply time-outs and
# the waits below: `make test` runs these alone, after the parallel part.
pytestmark = pytest.mark.wallclock


async def until(pilot, pred, timeout=20.0, step=0.05):
    loops = int(timeout / step)
    for _ in range(loops):
        if pred():
            return True
        await pilot.pause(step)
    return pred()


async def booted(pilot, app: HexBotConsole) -> None:
    """Wait until the console's simulated cluster has booted."""
    assert await until(pilot, lambda: app.host is not None, timeout=60)
    assert await until(pilot, lambda: not app.busy, timeout=60)


def ir_text(app: HexBotConsole) -> str:
    return "\n".join(line.plain for line in app.query_one("#ir-term", Terminal).lines())


def modules_rows(app: HexBotConsole) -> list[list[str]]:
    table = app.query_one(ModulesView)
    return [[str(c) for c in table.get_row_at(i)] for i in range(table.row_count)]


def _app(responder, **kw) -> HexBotConsole:
    host = Host()
    host.add_port(IR, PortSettings(responder.path), retry_s=0.1)
    return HexBotConsole(host, **kw)


@sync
async def test_composer_sends_from_the_table_and_shows_the_ack(responder):
    app = _app(responder)
    async with app.run_test(size=(100, 30)) as pilot:
        assert await until(pilot, lambda: app.port_states.get(IR, (None,))[0]
                           is LinkState.CONNECTED)
        await pilot.press("2")  # composer tab
        await pilot.click("#fn-filter")
        await pilot.press(*"select", "enter")  # first match, focus its first argument
        assert await until(pilot, lambda: getattr(app.focused, "id", None) == "arg-0"), \
            app.focused
        composer = app.query_one(Composer)
        assert composer.function.name == "Select"
        await pilot.press("4")
        assert "2a 45 04 4e 4e 4e 4e 4e 4e 4e 23" in str(
            app.query_one("#fn-preview").render())
        await pilot.click("#fn-send")
        assert await until(pilot, lambda: "M04 ACK 69 Select" in ir_text(app))
        assert responder.received == [b"*E\x04NNNNNNN#"]
        assert await until(pilot, lambda: ["04", "M", "no", "-", "-", "69 Select", "-", "-"]
                           in modules_rows(app))
        assert composer.history and str(composer.history[0]) == "Select(4)"
        app.query_one("#fn-history").focus()
        await pilot.press("enter")  # re-send the history's first row
        assert await until(pilot, lambda: len(responder.received) == 2)
        assert responder.received[1] == b"*E\x04NNNNNNN#"


@sync
async def test_terminal_search_views_and_save(responder, tmp_path):
    app = _app(responder)
    async with app.run_test(size=(100, 30)) as pilot:
        await until(pilot, lambda: app.port_states.get(IR, (None,))[0] is LinkState.CONNECTED)
        app.select_modules([2, 5])
        assert await until(pilot, lambda: not app.busy and app.last_result)
        term = app.query_one("#ir-term", Terminal)
        # the terminal draws from posted messages: they may trail the workflow's end
        assert await until(pilot, lambda: term.last_ack == "M05 69 Select")
        assert term.bytes_out == 11 and term.bytes_in > 0
        await pilot.click("#ir-term .term-search")
        await pilot.press(*"m05")
        await pilot.pause()
        assert [line.plain.split(None, 1)[1] for line in term.lines()] == ["< M05 ACK 69 Select"]
        term.cycle_mode()  # text view: raw bytes with escapes
        term.query_text = ""
        raw = "".join(line.plain.split("< ", 1)[1] for line in term.lines() if "< " in line.plain)
        assert "\\n\\r\\n\\rM05: ACKE\\n\\r" in raw  # reads may split a reply
        term.cycle_mode()  # hex
        assert any("2a 45 02 05 4e" in line.plain for line in term.lines())
        path = term.save(tmp_path / "ir.txt")
        assert "2a 45 02 05 4e" in path.read_text()


@sync
async def test_traffic_after_the_log_is_gone_is_kept_without_an_error(responder):
    # seen once on a fresh clone: the port's LOST state arrived while the app
    # was tearing the terminal down, and query_one(RichLog) raised NoMatches
    from textual.widgets import RichLog

    from hexbot.host.console.terminal import Entry

    app = _app(responder)
    async with app.run_test(size=(100, 30)) as pilot:
        term = app.query_one("#ir-term", Terminal)
        await term.query_one(RichLog).remove()
        await pilot.pause()
        term.add(Entry(1.0, "state", text="lost port closed"))
        assert "lost port closed" in ir_text(app)


@sync
async def test_replies_without_id_add_no_module(responder):
    """Issue 13, defect 2: before any Select every module answers ``M: ACK``
    at once; the console made a module row ``M`` and counted it."""
    app = _app(responder)
    async with app.run_test(size=(100, 30)) as pilot:
        await until(pilot, lambda: app.port_states.get(IR, (None,))[0] is LinkState.CONNECTED)
        app.send_command(frames.make("TurnOffAll"))
        assert await until(pilot, lambda: ir_text(app).count("M ACK 20 TurnOffAll") == 7)
        await pilot.pause(0.2)
        assert modules_rows(app) == []
        assert "0 modules, 0 placed" in str(app.query_one("#status").render())


@sync
async def test_keys_search_help_names_and_escape_leaves_inputs(responder):
    """Issue 13, defect 8: ``/`` was listed but unbound, help showed
    ``f1,question_mark``, escape did not leave a text input."""
    app = _app(responder)
    async with app.run_test(size=(100, 30)) as pilot:
        await pilot.press("2")
        await pilot.click("#fn-filter")
        await pilot.press("escape")  # leave the filter: keys act again
        await pilot.press("1")
        assert app.query_one("#tabs").active == "terminals"
        assert app.query_one("#fn-filter").value == ""
        await pilot.press("slash")
        assert app.focused is app.query_one("#ir-term .term-search")
        await pilot.press(*"ack", "escape", "c")  # c: wall-clock time stamps
        assert app.query_one("#ir-term", Terminal).stamps == "wall"
        await pilot.press("f1")
        help_text = app.screen.query_one("Markdown").source
        assert "`f1, ?` Help" in help_text and "question_mark" not in help_text
        assert "`/` Search" in help_text


@sync
async def test_composer_refuses_out_of_range_argument(responder):
    app = _app(responder)
    async with app.run_test(size=(100, 30)) as pilot:
        app.compose_function(1)  # JxOpen(i), i in 1..6
        await pilot.pause()
        await pilot.press("9")
        assert "must be 1..6, got 9" in str(app.query_one("#fn-preview").render())
        assert app.query_one("#fn-send").disabled
        await pilot.press("enter")
        await pilot.pause(0.2)
        assert responder.received == []


@sync
async def test_localize_workflow_fills_modules_and_lattice(responder):
    app = _app(responder)
    async with app.run_test(size=(100, 30)) as pilot:
        await until(pilot, lambda: app.port_states.get(IR, (None,))[0] is LinkState.CONNECTED)
        await pilot.press("l")  # asks for the reference id, default 1
        await pilot.press("enter")
        assert await until(pilot, lambda: not app.busy and app.last_result)
        assert "Localize: done" in app.last_result
        cells = lattice_cells(app.host.model)
        assert len(cells) == 7 and cells[(0, 0)][0] == "01"
        # the views redraw once per burst of replies
        assert await until(pilot, lambda: all(
            f"/{i:02d}\\" in str(app.query_one("#lattice-view").render()) for i in range(1, 8)))
        assert [r[0] for r in modules_rows(app)] == [f"{i:02d}" for i in range(1, 8)]


@sync
async def test_cancel_stops_a_long_operation(silent_responder):
    app = _app(silent_responder)
    app.reply_timeout = 30.0
    async with app.run_test(size=(100, 30)) as pilot:
        await until(pilot, lambda: app.port_states.get(IR, (None,))[0] is LinkState.CONNECTED)
        await pilot.press("t")
        assert await until(pilot, lambda: bool(app.busy))
        # issue 13, defect 9: a long wait shows replies, elapsed time and time-out
        status = app.query_one("#status")
        assert await until(pilot, lambda: "0 of 1 replied, " in str(status.render())
                           and " s of 30 s" in str(status.render()))
        await pilot.press("escape")
        assert await until(pilot, lambda: not app.busy, timeout=5)
        assert "cancelled" in app.last_result


@sync
async def test_help_palette_and_views(responder, tmp_path):
    app = _app(responder)
    async with app.run_test(size=(80, 24)) as pilot:
        await pilot.press("f1")
        assert app.screen.__class__.__name__ == "HelpScreen"
        await pilot.press("escape")
        await pilot.press("ctrl+p")
        await pilot.press(*"compose 21")
        await pilot.pause(0.5)
        await pilot.press("enter")
        await pilot.pause(0.3)
        assert app.query_one(Composer).function.name == "MCW"
        term = app.query_one("#ir-term", Terminal)
        assert term.cycle_mode() == "text" and term.cycle_mode() == "hex"


@sync
async def test_port_loss_is_shown_and_state_kept(responder):
    app = _app(responder)
    async with app.run_test(size=(100, 30)) as pilot:
        assert await until(pilot, lambda: app.port_states.get(IR, (None,))[0]
                           is LinkState.CONNECTED)
        app.select_modules([3])
        assert await until(pilot, lambda: not app.busy and app.last_result)
        responder.close()
        assert await until(pilot, lambda: app.port_states[IR][0] is LinkState.LOST)
        assert "lost" in ir_text(app)
        assert ["03", "M", "no", "-", "-", "69 Select", "-", "-"] in modules_rows(app)


# --- the embedded simulator -------------------------------------------------


@pytest.fixture
def pair_args(log_dir):
    return cli_console.parse(["--scenario", "pair", "--sim-speed", "5"])


@pytest.fixture
def sim_args(log_dir):
    return cli_console.parse(["--scenario", "flower7", "--sim-speed", "5"])


@sync
async def test_console_on_simulator_flower7(sim_args):
    """Connect, send Select(0) from the composer table, see the ACKs in the
    IR terminal and modules view, localize and see seven positions."""
    app = HexBotConsole(opener=cli_console.make_opener(sim_args))
    async with app.run_test(size=(120, 36)) as pilot:
        assert await until(pilot, lambda: app.host is not None, timeout=60)
        assert await until(pilot, lambda: app.port_states.get(IR, (None,))[0]
                           is LinkState.CONNECTED, timeout=30)
        assert await until(pilot, lambda: not app.busy, timeout=60)  # booted
        await pilot.press("2")
        await pilot.click("#fn-filter")
        await pilot.press(*"69", "enter")
        # the form's first field takes the focus after a refresh (keys typed
        # before wait in the filter: test_composer_typeahead.py)
        assert await until(pilot, lambda: getattr(app.focused, "id", None) == "arg-0"), \
            app.focused
        await pilot.press("0")
        assert await until(pilot, lambda: not app.query_one("#fn-send").disabled)
        await pilot.click("#fn-send")
        assert await until(pilot, lambda: ir_text(app).count("ACK 69 Select") == 7,
                           timeout=30), (app.last_result, ir_text(app)[-3000:], sim_story(app))
        # the modules view updates after the terminal line (under load, a
        # moment later): wait for it, as a user would
        assert await until(pilot, lambda: len(modules_rows(app)) == 7 and all(
            row[5] == "69 Select" for row in modules_rows(app)))
        app.localize(1)
        assert await until(pilot, lambda: not app.busy and app.last_result, timeout=120)
        assert "Localize: done" in app.last_result, app.last_result
        cells = lattice_cells(app.host.model)
        assert sorted(cells) == sorted([(0, 0), (-1, 1), (0, 1), (1, 0), (1, -1), (0, -1),
                                        (-1, 0)])
        assert {label for label, _, _ in cells.values()} == {f"{i:02d}" for i in range(1, 8)}
        assert cells[(0, 0)][1] == "S"


@sync
async def test_rotation_on_simulator_moves_module_in_lattice(pair_args):
    """Localize the pair, rotate module 2 CW about lattice joint 4 (Table
    3-1's example) from the rotate dialog: both ACK 67, the plant's verdict
    verifies the move, and the lattice shows where the plant put it."""
    app = HexBotConsole(opener=cli_console.make_opener(pair_args))
    async with app.run_test(size=(100, 30)) as pilot:
        assert await until(pilot, lambda: app.host is not None, timeout=60)
        assert await until(pilot, lambda: not app.busy, timeout=60)
        app.localize(1)
        assert await until(pilot, lambda: not app.busy and "Localize" in app.last_result,
                           timeout=120)
        assert app.host.model.module(2).position == (-1, 1)
        await pilot.press("w")
        await pilot.pause()
        screen = app.screen
        screen.query_one("#rot-joint").value = "4"
        screen.query_one("#rot-mobile").value = 2
        screen.query_one("#rot-substrate").value = 1
        await pilot.click("#rot-go")
        assert await until(pilot, lambda: not app.busy and "Rotate" in app.last_result,
                           timeout=30)
        assert "done" in app.last_result, app.last_result
        assert "module 2 moved at (0, 1) facing 2 (verified by plant)" in app.last_result
        assert "S01 ACK 67 CW" in ir_text(app) and "M02 ACK 67 CW" in ir_text(app)
        sent = [line for line in ir_text(app).splitlines() if "> CW(" in line]
        assert sent and sent[-1].endswith("> CW(4, 8, 4, 10, 4, 8, 5, 9)")
        assert app.host.simulator.placements()[2] == Placement((0, 1), 2)
        assert app.host.model.module(2).position == (0, 1)  # the verdict placed it
        assert await until(pilot, lambda: "module 2 moved (-1, 1) -> (0, 1)"
                           in str(app.query_one("#lattice-legend").render()))


@sync
async def test_refused_and_unlocalized_rotations_fail_on_simulator(pair_args):
    """Issue 12, item 3: a rotation before localizing is refused (the
    orientations are unknown) and one the plant refuses (module 1 is the
    pair's fixed base) fails in red with the plant's reason; neither is
    ever "done"."""
    app = HexBotConsole(opener=cli_console.make_opener(pair_args))
    async with app.run_test(size=(100, 30)) as pilot:
        await booted(pilot, app)
        assert "Simulator: done" in app.last_result, app.last_result
        app.rotate("cw", 4, 2, 1)
        assert await until(pilot, lambda: not app.busy and "Rotate" in app.last_result)
        assert app.last_result.startswith("[red]") and "done" not in app.last_result
        assert "unknown: localize first" in app.last_result, app.last_result
        assert "> CW(" not in ir_text(app)  # refused before sending anything
        assert any(n.title == "Failed" for n in app._notifications)

        app.localize(1)
        assert await until(pilot, lambda: not app.busy and "Localize" in app.last_result,
                           timeout=120)
        assert "Localize: done" in app.last_result, app.last_result
        # module 1 as the mobile about lattice joint 1, module 2 (at (-1, 1)) the substrate
        app.rotate("cw", 1, 1, 2)
        assert await until(pilot, lambda: not app.busy and "Rotate" in app.last_result,
                           timeout=30)
        assert app.last_result.startswith("[red]") and "done" not in app.last_result
        assert "the plant refused: module 1 fixed to base" in app.last_result, app.last_result
        assert "M01 ACK 67 CW" in ir_text(app)  # the modules did what they were told
        assert await until(pilot, lambda: "Simulator: rotation refused"
                           in [n.title for n in app._notifications])
        # (notifications expire: check that none ever called the rotation done)
        assert not any(n.title == "Done" and "Rotate" in str(n.message)
                       for n in app._notifications)
        assert app.host.simulator.placements()[1] == Placement((0, 0), 0)  # never moved


@sync
async def test_console_reconnects_when_the_port_returns():
    from test_link import _Server

    server = _Server()
    host = Host()
    host.add_port(IR, PortSettings(f"socket://127.0.0.1:{server.port}"), retry_s=0.1)
    app = HexBotConsole(host)
    try:
        async with app.run_test(size=(100, 30)) as pilot:
            assert await until(pilot, lambda: "S01 ACK 65 Ref" in ir_text(app), timeout=5)
            server.stop()
            assert await until(pilot, lambda: app.port_states[IR][0] is LinkState.LOST)
            assert "Port lost" in [n.title for n in app._notifications]
            server = _Server(server.port)
            assert await until(pilot, lambda: app.port_states[IR][0] is LinkState.CONNECTED)
            assert await until(pilot, lambda: ir_text(app).count("S01 ACK 65 Ref") == 2)
            text = ir_text(app)
            assert text.index("-- lost") < text.rindex("-- connected")
    finally:
        server.stop()


@sync
async def test_set_role_from_the_palette(responder):
    app = _app(responder)
    async with app.run_test(size=(100, 30)) as pilot:
        await until(pilot, lambda: app.port_states.get(IR, (None,))[0] is LinkState.CONNECTED)
        app.select_modules([6])
        assert await until(pilot, lambda: not app.busy and app.last_result)
        await pilot.press("ctrl+p")
        await pilot.press(*"set role")
        await pilot.pause(0.5)
        await pilot.press("enter")  # the palette runs the workflow, which asks
        await pilot.pause(0.3)
        await pilot.press("backspace", "2", "enter")
        assert await until(pilot, lambda: "S06 ACK 71 SetRole" in ir_text(app))
        assert responder.received[-1] == b"*G\x02NNNNNNN#"
        assert ["06", "S"] == modules_rows(app)[0][:2]


@sync
async def test_replay_shows_a_recorded_session_and_cancels():
    """``hexbot console --replay``: the capture plays in real time into the
    terminals; escape stops it."""
    from pathlib import Path

    from hexbot.host.capture import read_capture

    records = list(read_capture(Path(__file__).parent / "data" / "flower7_session.hbcap"))
    app = HexBotConsole(Host(), replay=records, start_ports=False)
    async with app.run_test(size=(100, 30)) as pilot:
        assert await until(pilot, lambda: "ACK" in ir_text(app))
        assert app.busy.startswith("Replay")
        await pilot.press("escape")
        assert await until(pilot, lambda: not app.busy, timeout=5)
        assert "Replay: cancelled" in app.last_result


@sync
async def test_a_bad_scenario_file_stays_visible_and_fails_the_exit_status(log_dir, tmp_path):
    """Issue 13, defect 10: the status line cut the file:line error, and
    quitting exited 0."""
    bad = tmp_path / "bad.toml"
    bad.write_text('name = "bad"\nbase = 1\n\n[[module]]\nid = 1\nposition = [0, 0]\n'
                   'colour = "red"\n')
    args = cli_console.parse(["--scenario", str(bad), "--sim-speed", "5"])
    app = HexBotConsole(opener=cli_console.make_opener(args))
    async with app.run_test(size=(80, 24)) as pilot:
        alert = app.query_one("#alert")
        assert await until(pilot, lambda: alert.display, timeout=60)
        text = str(alert.render())
        assert f"{bad}:7:" in text.replace("\n", ""), text
        await pilot.press("3", "1")  # visible on every tab
        assert alert.display
    assert app.failure_status == 4


@sync
async def test_a_big_cluster_boots_though_its_boot_texts_collide(log_dir):
    """Beyond eight ids the boot slots are shared and the texts collide into
    wrong ids: the console said "no boot text from module(s) 2, 3, ..." of
    modules that were up. Those not heard whole answer a Status instead."""
    args = cli_console.parse(["--scenario", "blob:10", "--sim-speed", "10"])
    app = HexBotConsole(opener=cli_console.make_opener(args))
    async with app.run_test(size=(100, 30)) as pilot:
        assert await until(pilot, lambda: app.host is not None, timeout=60)
        assert await until(pilot, lambda: not app.busy and app.last_result, timeout=120)
        assert "Simulator: done: 10 modules booted" in app.last_result, app.last_result


@sync
async def test_a_stopped_simulator_is_said_and_restarted(pair_args):
    """Issue 13, defect 10: when the embedded simulator dies the console
    retried forever without saying so. Its core failing is simulated by
    making the cluster's ``run`` raise (a test double on the real path)."""
    app = HexBotConsole(opener=cli_console.make_opener(pair_args))
    async with app.run_test(size=(100, 30)) as pilot:
        await booted(pilot, app)
        cluster = app.host.simulator
        first_host = app.host

        def fault(seconds: float) -> None:
            raise RuntimeError("core fault at pc 0x1234")
        cluster.simulator.run = fault
        alert = app.query_one("#alert")
        assert await until(pilot, lambda: alert.display, timeout=30)
        assert ("the simulator stopped: RuntimeError: core fault at pc 0x1234; ctrl+r "
                "restarts it") in str(alert.render()).replace("\n", " ")
        assert app.port_states[IR][0] is LinkState.LOST
        assert app.failure_status == 4
        await pilot.pause(0.5)
        assert app.port_states[IR][0] is LinkState.LOST  # no silent new cluster
        await pilot.press("ctrl+r")
        assert await until(pilot, lambda: app.host is not None and app.host is not first_host
                           and app.port_states[IR][0] is LinkState.CONNECTED, timeout=60)
        assert await until(pilot, lambda: not app.busy, timeout=60)
        assert "Simulator: done: 2 modules booted" in app.last_result
        assert not alert.display and app.failure_status is None


@sync
async def test_replay_pauses_changes_speed_and_skips_ahead():
    """Issue 13: replay with speed, pause and seek (keys p, [ ], .)."""
    from pathlib import Path

    from hexbot.host.capture import read_capture

    records = list(read_capture(Path(__file__).parent / "data" / "flower7_session.hbcap"))
    app = HexBotConsole(Host(), replay=records, start_ports=False)
    async with app.run_test(size=(120, 30)) as pilot:
        assert await until(pilot, lambda: app.busy.startswith("Replay"))
        control = app.replay_control
        await pilot.press("p")
        assert control.paused
        held = control.position()
        shown = len(ir_text(app))
        await pilot.pause(0.5)
        assert control.position() == held and len(ir_text(app)) == shown
        assert "paused" in str(app.query_one("#status").render())
        await pilot.press("right_square_bracket", "right_square_bracket")
        assert control.speed == 4.0
        await pilot.press("left_square_bracket")
        assert control.speed == 2.0
        # Skipping while paused plays the skipped records at once: the Ref
        # sent at 5.8 s shows without waiting, and the replay stays paused.
        assert held < 5.0 and "Ref" not in ir_text(app)
        await pilot.press("full_stop")
        assert control.position() == held + 10.0 and control.paused
        assert await until(pilot, lambda: "Ref" in ir_text(app), timeout=5)
        assert f"{held + 10:.1f} s of 18.7 s, 2x, paused" in str(
            app.query_one("#status").render())
        await pilot.press("p")  # resume: the rest (to 18.7 s) is played, then done
        assert await until(pilot, lambda: not app.busy, timeout=10)
        assert f"{len(records)} records" in app.last_result


@sync
async def test_composer_sends_raw_hex_and_text_bytes(responder):
    """Issue 13: raw send from the composer, parsed as `send --raw` parses."""
    from textual.widgets import Input

    app = _app(responder)
    async with app.run_test(size=(100, 30)) as pilot:
        assert await until(pilot, lambda: app.port_states.get(IR, (None,))[0]
                           is LinkState.CONNECTED)
        await pilot.press("2")
        raw = app.query_one("#raw-input", Input)
        raw.focus()
        await pilot.press(*"2A 45 04 4E 4E 4E 4E 4E 4E 4E 23", "enter")
        assert await until(pilot, lambda: "M04 ACK 69 Select" in ir_text(app))
        assert responder.received == [b"*E\x04NNNNNNN#"] and raw.value == ""
        raw.value = '"*E\\x04NNNNNNN#"'  # text with an escape, in quotes
        await pilot.press("enter")
        assert await until(pilot, lambda: len(responder.received) == 2)
        assert responder.received[1] == b"*E\x04NNNNNNN#"
        composer = app.query_one(Composer)
        assert composer.history[0] == b"*E\x04NNNNNNN#"
        assert "raw: Select(4)" in str(app.query_one("#fn-history").get_row_at(0)[1])
        raw.value = "2A 4"  # odd hex: refused, kept for correction, nothing sent
        await pilot.press("enter")
        await pilot.pause(0.3)
        assert raw.value == "2A 4" and len(responder.received) == 2


@sync
async def test_boards_tab_shows_joints_magnets_and_leds_live(pair_args):
    """The Boards tab (key 6) shows each simulated module's pins as they
    change: a joint opened and positive side LEDs lit from the console appear
    within a poll, and closing them clears the marks again."""
    from hexbot.host.commands import parse_command
    from hexbot.host.console.boards_view import BoardsView

    app = HexBotConsole(opener=cli_console.make_opener(pair_args))
    async with app.run_test(size=(120, 30)) as pilot:
        assert await until(pilot, lambda: app.host is not None, timeout=60)
        assert await until(pilot, lambda: not app.busy, timeout=60)
        await pilot.press("6")
        view = app.query_one(BoardsView)
        assert await until(pilot, lambda: [r[0] for r in view.rows()] == ["1", "2"])
        idle = {r[0]: r for r in view.rows()}
        assert idle["1"][4] == "······" and idle["1"][5] == "······"
        assert idle["2"][1] == "(-1,+1)"  # the plant's cell of the pair's module 2
        app.send_command(parse_command(["Select", "1"]))
        app.send_command(parse_command(["JxOpen", "3"]))
        app.send_command(parse_command(["SideOnAllP"]))

        def module1() -> tuple[str, ...]:
            return next(r for r in view.rows() if r[0] == "1")
        assert await until(pilot, lambda: module1()[4] == "··3···"
                           and module1()[7] == "++++++", timeout=30), module1()
        assert next(r for r in view.rows() if r[0] == "2")[4] == "······"  # not selected
        app.send_command(parse_command(["JxClose", "3"]))
        app.send_command(parse_command(["SideOffAllP"]))
        assert await until(pilot, lambda: module1()[4] == "······"
                           and module1()[7] == "······", timeout=30), module1()


async def _boards_tab(app, pilot):
    """The Boards tab once the IR port is connected (on the pty test double)."""
    from hexbot.host.console.boards_view import BoardsView

    assert await until(pilot, lambda: app.port_states.get(IR, (None,))[0]
                       is LinkState.CONNECTED)
    await pilot.press("6")
    return app.query_one(BoardsView)


@sync
async def test_boards_tab_says_unavailable_on_a_real_port(responder):
    from hexbot.host.console.boards_view import UNAVAILABLE, BoardsView

    app = _app(responder)
    async with app.run_test(size=(100, 30)) as pilot:
        view = await _boards_tab(app, pilot)
        assert isinstance(view, BoardsView)
        assert await until(pilot, lambda: view.note == UNAVAILABLE)
        assert view.rows() == []


@sync
async def test_a_boards_refresh_while_the_view_is_torn_down_is_skipped(responder):
    # The poll is a timer: it can fire after the view's table has gone while the
    # app closes (seen once in CI: NoMatches from inside the timer stopped the app).
    from textual.widgets import DataTable

    from hexbot.host.console.boards_view import BoardsView

    app = _app(responder)
    async with app.run_test(size=(100, 30)) as pilot:
        view = await _boards_tab(app, pilot)
        await view.query_one(DataTable).remove()
        app.refresh_boards()  # must not raise
        await pilot.pause()
        assert app.query_one(BoardsView) is view


def sim_story(app, last: int = 40) -> list[dict]:
    """The embedded simulator's last events (collisions, dropped bytes,
    verdicts): what a failed exchange's assertion shows."""
    return app.host.simulator.simulator.events[-last:]


def plan_shown(app) -> bool:
    """The plan screen is pushed and composed (on a loaded machine its widgets
    come a frame after the screen: querying them at once failed)."""
    return isinstance(app.screen, PlanScreen) and bool(app.screen.query("#plan-summary"))


@sync
async def test_plan_to_a_goal_file_is_shown_then_executed_and_verified(pair_args, tmp_path):
    """The plan workflow (key g): a goal the cluster cannot take fails red
    with the planner's reason and sends no rotation; a goal it can take is
    planned from the cluster as localized, shown with its lower bounds,
    discarded once (nothing sent), then executed: the plant moves module 2
    and the goal is claimed after a last localization."""
    bad, goal = tmp_path / "three.toml", tmp_path / "goal.toml"
    bad.write_text("cells = [[0, 0], [0, 1], [1, 0]]\n")
    goal.write_text("cells = [[0, 0], [0, 1]]\n")
    app = HexBotConsole(opener=cli_console.make_opener(pair_args))
    async with app.run_test(size=(120, 36)) as pilot:
        await booted(pilot, app)

        async def plan_to(path) -> None:
            await pilot.press("g")
            await pilot.pause()
            app.screen.query_one("#prompt-input").value = str(path)
            await pilot.press("enter")

        await plan_to(tmp_path / "missing.toml")  # a file that is not there: no operation
        assert await until(pilot, lambda: any(n.title == "Goal not loaded"
                                              for n in app._notifications))
        assert not app.busy
        await plan_to(f"{goal} reference one")  # a bad option: no operation either
        assert await until(pilot, lambda: any("reference must be a module id" in str(n.message)
                                              for n in app._notifications))
        assert not app.busy
        await plan_to(bad)
        assert await until(pilot, lambda: not app.busy and "Plan" in app.last_result,
                           timeout=120)
        assert app.last_result.startswith("[red]") and "no plan" in app.last_result
        assert "the initial configuration has 2 modules, the goal 3 cells" in app.last_result
        assert not isinstance(app.screen, PlanScreen)

        await plan_to(goal)
        assert await until(pilot, lambda: plan_shown(app), timeout=120), (app.busy, app.last_result)
        # planned is not done: the operation's result says nothing moved yet
        assert "1 move(s) in 1 time step(s) planned, not executed" in app.last_result
        assert "goal reached" not in app.last_result
        summary = str(app.screen.query_one("#plan-summary").render())
        assert "goal reached, 1 time step(s), 1 move(s)" in summary, summary
        assert "lower bounds: 1 move(s), 1 time step(s)" in summary, summary
        assert "step 1: module 2 (-1, 1) -> (0, 1), joint 4 CW on module 1" in str(
            app.screen.query_one("#plan-moves").render())
        # the goal's empty cell is outlined in the lattice while the plan is shown
        legend = app.query_one("#lattice-legend")
        assert "goal: 1 of 2 cells filled" in str(legend.render())
        assert "/  \\" in str(app.query_one("#lattice-view").render())
        await pilot.press("escape")  # discard: nothing is sent
        await pilot.pause()
        assert "goal:" not in str(legend.render())
        assert not isinstance(app.screen, PlanScreen) and not app.busy
        assert app.last_result == "Plan: discarded, nothing executed"
        assert "> CW(" not in ir_text(app)
        assert app.host.simulator.placements()[2] == Placement((-1, 1), 0)

        await plan_to(f"{goal} reference 1 verify plant")
        assert await until(pilot, lambda: plan_shown(app), timeout=120), (app.busy, app.last_result)
        await pilot.pause()
        await pilot.press("e")  # the dialog's Execute
        assert await until(pilot, lambda: not app.busy and "Execute plan" in app.last_result,
                           timeout=120), (app.busy, app.last_result, app.screen)
        assert "goal reached (localized): 1 of 1 moves" in app.last_result, (
            app.last_result, ir_text(app)[-2000:], sim_story(app))
        assert not app.last_result.startswith("[red]")
        assert app.host.simulator.placements()[2] == Placement((0, 1), 2)
        assert "S01 ACK 67 CW" in ir_text(app) and "M02 ACK 67 CW" in ir_text(app)
        assert await until(pilot, lambda: "goal: 2 of 2 cells filled" in str(legend.render()))
        assert "/  \\" not in str(app.query_one("#lattice-view").render())


@sync
async def test_escape_cancels_a_running_plan_and_claims_nothing(pair_args, tmp_path):
    """Escape while a plan runs (here during its last localization, after
    the move): the operation ends red as cancelled and the goal is never
    claimed, though the plant did move module 2."""
    goal = tmp_path / "goal.toml"
    goal.write_text("cells = [[0, 0], [0, 1]]\n")
    app = HexBotConsole(opener=cli_console.make_opener(pair_args))
    async with app.run_test(size=(120, 36)) as pilot:
        await booted(pilot, app)
        await pilot.press("g")
        await pilot.pause()
        app.screen.query_one("#prompt-input").value = str(goal)
        await pilot.press("enter")
        assert await until(pilot, lambda: plan_shown(app), timeout=120), (app.busy, app.last_result)
        await pilot.pause()
        await pilot.press("e")
        assert await until(pilot, lambda: app.host.simulator.placements()[2]
                           == Placement((0, 1), 2), timeout=60)
        assert app.busy.startswith("Execute plan")  # the last localization is running
        await pilot.press("escape")
        assert await until(pilot, lambda: not app.busy, timeout=60)
        assert app.last_result == "[red]Execute plan: cancelled[/]", app.last_result
        # the plan's own "goal reached" toast may still show; the run's is the cancel
        runs = [str(n.message) for n in app._notifications
                if str(n.message).startswith("Execute plan")]
        assert runs == ["Execute plan: cancelled"], runs
        # the last localization was cut short wherever Escape reached it (at its
        # Localize, or sooner on a loaded machine): its Status never went out
        await pilot.pause(1.0)
        sent = [line.split("> ", 1)[1] for line in ir_text(app).splitlines() if "> " in line]
        move = max(i for i, c in enumerate(sent) if c.startswith(("CW(", "CCW(")))
        after = sent[move + 1:]
        last_localization = ["Select(1)", "Ref()", "Select(0)", "Localize()"]
        assert after and after == last_localization[:len(after)], sent
        assert sent.count("Status()") == 1, sent


@sync
async def test_the_console_refuses_what_would_mislead_and_survives_a_bug(pair_args):
    """Session 27's audit: Ref with no single selection (every module would
    become the origin), re-opening the simulator's port by hand, a bug in a
    step (it used to kill the console), and ctrl+r in the middle of a wait
    (it was reported done)."""
    app = HexBotConsole(opener=cli_console.make_opener(pair_args))
    async with app.run_test(size=(120, 36)) as pilot:
        await booted(pilot, app)
        assert app.selection_text() == "none"  # no Select has been sent
        await pilot.press("r")
        await pilot.pause()
        assert any("select exactly one module" in str(n.message) for n in app._notifications)
        assert "> Ref()" not in ir_text(app)

        settings = app.host.channels[IR].link.settings
        app.post_message(PortPanel.Apply(IR, settings))
        assert await until(pilot, lambda: any(n.title == "Not changed"
                                              for n in app._notifications))

        def broken() -> str:
            raise KeyError(0)
        app.start_operation("Broken", [broken])
        assert await until(pilot, lambda: not app.busy and "Broken" in app.last_result)
        assert app.last_result.startswith("[red]") and "internal error: KeyError" in app.last_result

        app.localize(1)  # about 50 s of localization: restart in the middle
        assert await until(pilot, lambda: app.busy.startswith("Localize"))
        await pilot.pause(1.0)
        await pilot.press("ctrl+r")

        def localize_toasts() -> list[str]:
            return [str(n.message) for n in app._notifications
                    if str(n.message).startswith("Localize")]
        assert await until(pilot, lambda: localize_toasts(), timeout=60)
        assert localize_toasts() == ["Localize: cancelled"]


@sync
async def test_the_console_refuses_more_that_would_mislead(pair_args):
    """Session 28's audit: a Status with no Select (every module answers at
    once: a garbled failure), the plan prompt's "[reference ID]" eaten as
    markup, Disconnect on the simulator's port (it closed the cluster), and
    a module drawn twice after localizing from a module that is not the
    scenario's base (the plant's cells were not in the localization's frame)."""
    app = HexBotConsole(opener=cli_console.make_opener(pair_args))
    async with app.run_test(size=(120, 36)) as pilot:
        await booted(pilot, app)
        await pilot.press("t")
        await pilot.pause()
        assert any("select first" in str(n.message) for n in app._notifications)
        assert "> Status()" not in ir_text(app)

        await pilot.press("g")
        await pilot.pause()
        assert "[reference ID]" in str(app.screen.query_one(Label).render())
        await pilot.press("escape")
        await pilot.pause()

        app.post_message(PortPanel.Apply(IR, None))  # Disconnect
        assert await until(pilot, lambda: any(n.title == "Not changed"
                                              for n in app._notifications))
        assert app.host.channels[IR].link.state is LinkState.CONNECTED

        app.localize(2)  # module 2 becomes (0, 0); the base module 1 is at (1, -1)
        assert await until(pilot, lambda: not app.busy and "Localize" in app.last_result,
                           timeout=120)
        assert not app.last_result.startswith("[red]"), app.last_result
        drawn = str(app.query_one("#lattice-view").render())
        assert drawn.count("02") == 1 and drawn.count("01") == 1, drawn


@sync
async def test_a_wait_that_ticks_while_the_console_exits_is_no_crash(responder):
    """CI, session 33: the wait's timer ticked while the app tore its main
    screen down at exit (busy, a session open) and its query for the
    progress bar raised NoMatches: the exit ended in a traceback. A worker's
    last step or its end, arriving then, is the same."""
    app = _app(responder)
    async with app.run_test(size=(100, 30)) as pilot:
        assert await until(pilot, lambda: app.session is not None)
        app.busy = "Localize"
        await app.screen_stack[0].remove_children()  # what the exit does first
        app._show_wait()
        app._progress(1, "Localize: step")
        app._finished("Localize: cancelled", False, 3)
        assert app.busy == ""
