"""The terminals' text and hex views: a continuous stream, not one line per
read (issue 13, defect 6); time stamps since start or wall clock."""

from __future__ import annotations

import datetime as dt

from pilot_sync import sync
from textual.app import App, ComposeResult

from hexbot.host.console.stream import ByteStream
from hexbot.host.console.terminal import Entry, Terminal
from hexbot.protocol import parser

REPLY = b"\n\r\n\rM02: ACKD\n\r"  # one ACK 68 from module 2, as the firmware sends it


def chunks(data: bytes, sizes=(1, 3, 8, 2, 5)) -> list[bytes]:
    """Split like a 300-baud port's reads (1-8 bytes)."""
    out, i, n = [], 0, 0
    while i < len(data):
        size = sizes[n % len(sizes)]
        out.append(data[i:i + size])
        i, n = i + size, n + 1
    return out


def test_text_stream_breaks_lines_after_lf_cr_not_per_read():
    stream = ByteStream("text")
    done = []
    for k, part in enumerate(chunks(REPLY)):
        done += stream.feed("rx", 1.0 + k / 10, None, part)
    assert [bytes(x.data) for x in done] == [b"\n\r", b"\n\r", b"M02: ACKD\n\r"]
    assert [x.offset for x in done] == [0, 2, 4]
    assert done[2].t == 1.2  # the time of the line's first byte
    assert stream.pending is None


def test_hex_stream_has_16_bytes_a_line_offsets_and_a_pending_tail():
    stream = ByteStream("hex")
    data = REPLY * 2  # 30 bytes
    done = [x for part in chunks(data) for x in stream.feed("rx", 0.0, None, part)]
    assert [len(x.data) for x in done] == [16]
    assert stream.pending is not None and len(stream.pending.data) == 14
    assert stream.pending.offset == 16
    # a write closes the pending read line: the order of events stays visible
    (closed,) = stream.feed("tx", 0.5, None, b"*F")[:1]
    assert closed.direction == "rx" and len(closed.data) == 14
    assert stream.pending.direction == "tx" and stream.pending.offset == 0


class _One(App[None]):
    def compose(self) -> ComposeResult:
        yield Terminal("IR", "ir", id="t")


def _plain(term: Terminal) -> list[str]:
    return [line.plain for line in term.lines()]


@sync
async def test_terminal_views_show_the_stream_with_session_or_wall_stamps():
    app = _One()
    wall = dt.datetime(2026, 11, 23, 14, 5, 6, 789000).timestamp()
    async with app.run_test(size=(100, 20)) as pilot:
        term = app.query_one(Terminal)
        term.add(Entry(0.5, "tx", data=b"*E\x02NNNNNNN#", wall=wall - 1))
        for k, part in enumerate(chunks(REPLY)):
            term.add(Entry(1.0 + k / 100, "rx", data=part, wall=wall))
        for ev in parser.parse_all(REPLY):
            term.add(Entry(1.05, "event", event=ev))
        assert _plain(term) == ["    0.500 > Select(2)", "    1.050 < M02 ACK 68 CCW"]
        term.cycle_mode()  # text
        await pilot.pause()
        assert _plain(term) == ["    0.500 > *E\\x02NNNNNNN#",
                                "    1.000 < \\n\\r", "    1.010 < \\n\\r",
                                "    1.020 < M02: ACKD\\n\\r"]
        term.cycle_mode()  # hex
        await pilot.pause()
        assert _plain(term) == [
            "    0.500 > 00000000  2a 45 02 4e 4e 4e 4e 4e  4e 4e 23" + " " * 17 + "|*E.NNNNNNN#|",
            "    1.000 < 00000000  0a 0d 0a 0d 4d 30 32 3a  20 41 43 4b 44 0a 0d     "
            "|....M02: ACKD..|"]
        # the reply's last line is still filling: shown under the scroll-back
        term.add(Entry(2.0, "rx", data=b"\n\r\n\rM01", wall=wall))
        await pilot.pause()
        pending = app.query_one(".term-pending")
        assert pending.display and "00000010  0d 0a 0d 4d 30 31" in str(pending.render())
        term.cycle_stamps()
        await pilot.pause()
        assert _plain(term)[1].startswith(
            dt.datetime.fromtimestamp(wall).strftime("%H:%M:%S.789 < 00000000"))
