"""A terminal's search and views at their edges (session 35's audit): the
search ignores case, hides the line still filling, and a save writes what
the search shows; state changes stay in the stream views; DEL is escaped."""

from __future__ import annotations

from pilot_sync import sync
from textual.app import App, ComposeResult

from hexbot.host.console.stream import escape_bytes
from hexbot.host.console.terminal import Entry, Terminal
from hexbot.protocol import parser

REPLY = b"\n\rM02: ACKE\n\r"  # module 2 acknowledges a Select


class _One(App[None]):
    def compose(self) -> ComposeResult:
        yield Terminal("IR", "ir", id="t")


def plain(term: Terminal) -> list[str]:
    return [line.plain for line in term.lines()]


def fed(term: Terminal) -> None:
    term.add(Entry(0.5, "tx", data=b"*E\x02NNNNNNN#"))
    term.add(Entry(1.0, "rx", data=REPLY))
    for ev in parser.parse_all(REPLY):
        term.add(Entry(1.0, "event", event=ev))


@sync
async def test_search_ignores_case_and_a_save_writes_only_what_it_shows(tmp_path):
    app = _One()
    async with app.run_test(size=(100, 20)) as pilot:
        term = app.query_one(Terminal)
        fed(term)
        await pilot.click(".term-search")
        await pilot.press(*"ack")
        await pilot.pause()
        assert plain(term) == ["    1.000 < M02 ACK 69 Select"]
        path = term.save(tmp_path / "ir.txt")
        assert path.read_text() == "    1.000 < M02 ACK 69 Select\n"
        info = str(term.query_one(".term-info").render())
        assert "ACK M02 69 Select" in info, info


@sync
async def test_the_line_still_filling_hides_when_the_search_does_not_match_it():
    app = _One()
    async with app.run_test(size=(100, 20)) as pilot:
        term = app.query_one(Terminal)
        term.cycle_mode()  # text
        term.add(Entry(2.0, "rx", data=b"\n\rM01"))  # a reply's start: the pending line
        await pilot.pause()
        pending = app.query_one(".term-pending")
        assert pending.display
        term.query_text = "zzz"
        await pilot.pause()
        assert not pending.display
        term.query_text = "m01"
        await pilot.pause()
        assert pending.display and "M01" in str(pending.render())


@sync
async def test_a_port_state_change_shows_in_the_text_and_hex_views():
    app = _One()
    async with app.run_test(size=(100, 20)) as pilot:
        term = app.query_one(Terminal)
        term.cycle_mode()  # text
        term.add(Entry(1.0, "rx", data=b"M0"))
        term.add(Entry(2.0, "state", text="lost port closed"))
        await pilot.pause()
        assert plain(term) == ["    1.000 < M0", "    2.000 -- lost port closed"]
        term.cycle_mode()  # hex
        await pilot.pause()
        assert plain(term)[-1] == "    2.000 -- lost port closed"


def test_del_and_other_control_bytes_are_escaped_in_the_text_view():
    assert escape_bytes(b"A\x7f~ \x00") == "A\\x7f~ \\x00"
