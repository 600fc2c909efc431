"""A port's terminal: time-stamped lines, decoded/text/hex views, search,
scroll-back, save. Replaces the VB GUI's IR and UART1 text boxes, with the
last ACK (and, for UART1, the last decoded MSG) shown in the title bar.

The decoded view shows one line per parsed event; the text and hex views
show the bytes as a continuous stream (:mod:`.stream`): complete lines go
to the scroll-back, the line still filling shows below it. Time stamps are
seconds since the session started, or the PC's wall clock when the bytes
arrived (``stamps``)."""

from __future__ import annotations

import datetime as dt
from dataclasses import dataclass
from pathlib import Path

from rich.text import Text
from textual import on
from textual.app import ComposeResult
from textual.containers import Horizontal, Vertical
from textual.reactive import reactive
from textual.widgets import Input, Label, RichLog, Static

from hexbot.host.console.stream import ByteStream, StreamLine, escape_bytes, hex_columns
from hexbot.host.describe import code_name, describe_event, describe_tx
from hexbot.protocol.parser import Ack, ControlMessage, ErrorReply, Event, Garbage
from hexbot.protocol.parser import Text as TextEv

MODES = ("decoded", "text", "hex")
STAMPS = ("session", "wall")
MAX_LINES = 5000

_STYLE = {Ack: "bold green", ErrorReply: "bold red", Garbage: "dim red",
          ControlMessage: "bold cyan", TextEv: "yellow"}
_ARROW = {"tx": ("> ", "bold blue"), "rx": ("< ", "")}


@dataclass(frozen=True)
class Entry:
    t: float
    kind: str  # tx | rx | event | state | warning (the host's: text)
    data: bytes = b""
    event: Event | None = None
    text: str = ""
    wall: float | None = None  # time.time() when it arrived (tx/rx/state)


def stamp(t: float, wall: float | None, stamps: str = "session") -> str:
    if stamps == "wall" and wall is not None:
        return dt.datetime.fromtimestamp(wall).strftime("%H:%M:%S.%f")[:-3] + " "
    return f"{t:9.3f} "


def _line(head: str, body: str, style: str) -> Text:
    return Text.assemble((head, "dim"), (body, style))


def render_entry(e: Entry, mode: str, stamps: str = "session") -> Text | None:
    """The decoded view's line for an entry (None: it shows no such entry);
    in the stream views, the line of a state change."""
    head = stamp(e.t, e.wall, stamps)
    if e.kind == "state":
        return _line(head, f"-- {e.text}", "bold magenta")
    if e.kind == "warning":
        return _line(head, f"!! warning: {e.text}", "bold yellow")
    if mode != "decoded":
        return None
    if e.kind == "tx":
        return _line(head, f"> {describe_tx(e.data)}", "bold blue")
    if e.kind == "event":
        assert e.event is not None
        return _line(head, f"< {describe_event(e.event)}", _STYLE.get(type(e.event), ""))
    return None


def render_stream_line(line: StreamLine, mode: str, stamps: str = "session") -> Text:
    arrow, style = _ARROW[line.direction]
    body = hex_columns(line) if mode == "hex" else escape_bytes(bytes(line.data))
    return _line(stamp(line.t, line.wall, stamps), arrow + body, style)


class TerminalLines:
    """Entries to display lines for one mode: complete lines and the one
    still filling (stream views only)."""

    def __init__(self, mode: str, stamps: str) -> None:
        self.mode, self.stamps = mode, stamps
        self.stream = ByteStream(mode) if mode != "decoded" else None

    def add(self, e: Entry) -> list[Text]:
        if self.stream is None:
            line = render_entry(e, self.mode, self.stamps)
            return [line] if line is not None else []
        if e.kind in ("tx", "rx"):
            done = self.stream.feed(e.kind, e.t, e.wall, e.data)
            return [render_stream_line(x, self.mode, self.stamps) for x in done]
        if e.kind in ("state", "warning"):
            done = [render_stream_line(x, self.mode, self.stamps) for x in self.stream.interrupt()]
            return done + [render_entry(e, self.mode, self.stamps)]  # type: ignore[list-item]
        return []

    def pending(self) -> Text | None:
        if self.stream is None or self.stream.pending is None:
            return None
        return render_stream_line(self.stream.pending, self.mode, self.stamps)


class Terminal(Vertical):
    """Lines of one port. ``mode`` cycles decoded -> text -> hex; ``stamps``
    session -> wall."""

    mode: reactive[str] = reactive("decoded")
    stamps: reactive[str] = reactive("session")
    query_text: reactive[str] = reactive("")

    def __init__(self, title: str, port: str, *, id: str | None = None) -> None:
        super().__init__(id=id, classes="terminal")
        self.title_text = title
        self.port = port
        self.entries: list[Entry] = []
        self.bytes_in = self.bytes_out = 0
        self.last_ack = ""
        self.last_msg = ""
        self._view = TerminalLines("decoded", "session")

    def compose(self) -> ComposeResult:
        with Horizontal(classes="term-bar"):
            yield Label(self.title_text, classes="term-title")
            yield Label("", classes="term-info")
            yield Input(placeholder="search (/)", classes="term-search")
        yield RichLog(max_lines=MAX_LINES, wrap=False, markup=False, classes="term-log")
        yield Static("", classes="term-pending")

    def on_mount(self) -> None:
        self._update_info()

    # --- feeding -------------------------------------------------------------

    def add(self, entry: Entry) -> None:
        self.entries.append(entry)
        if len(self.entries) > MAX_LINES:
            del self.entries[: len(self.entries) - MAX_LINES]
        if entry.kind == "rx":
            self.bytes_in += len(entry.data)
        elif entry.kind == "tx":
            self.bytes_out += len(entry.data)
        elif entry.kind == "event":
            ev = entry.event
            if isinstance(ev, Ack):
                who = (ev.role or "") + ("" if ev.module is None else f"{ev.module:02d}")
                self.last_ack = f"{who} {code_name(ev.code)}".strip()
            elif isinstance(ev, ControlMessage):
                self.last_msg = f"{code_name(ev.code)} {' '.join(map(str, ev.args))}"
        self._update_info()
        lines = self._view.add(entry)
        # Traffic may still arrive while the app tears the widget down: the entry
        # is kept (above), there is just no log left to show it in.
        for log in self.query(RichLog).results(RichLog):
            for line in lines:
                if self._matches(line):
                    log.write(line)
        self._show_pending()

    def _matches(self, line: Text) -> bool:
        return not self.query_text or self.query_text.lower() in line.plain.lower()

    def _show_pending(self) -> None:
        line = self._view.pending()
        for pending in self.query(".term-pending").results(Static):
            shown = line is not None and self._matches(line)
            pending.display = shown
            pending.update(line if shown else "")

    def _update_info(self) -> None:
        parts = [f"{self.mode}", f"in {self.bytes_in} B", f"out {self.bytes_out} B"]
        if self.last_ack:
            parts.append(f"ACK {self.last_ack}")
        if self.last_msg:
            parts.append(f"MSG {self.last_msg}")
        # Traffic may still arrive while the app tears the widget down.
        for info in self.query(".term-info").results(Label):
            info.update(" | ".join(parts))

    # --- views ---------------------------------------------------------------

    def lines(self) -> list[Text]:
        """Every line of the current view (search applied), the one still
        filling last."""
        view = TerminalLines(self.mode, self.stamps)
        out = [line for e in self.entries for line in view.add(e)]
        pending = view.pending()
        out += [pending] if pending is not None else []
        return [line for line in out if self._matches(line)]

    def _redraw(self) -> None:
        if not self.is_mounted:
            return
        self._view = TerminalLines(self.mode, self.stamps)
        log = self.query_one(RichLog)
        log.clear()
        for e in self.entries:
            for line in self._view.add(e):
                if self._matches(line):
                    log.write(line)
        self._show_pending()
        self._update_info()

    def watch_mode(self) -> None:
        self._redraw()

    def watch_stamps(self) -> None:
        self._redraw()

    def watch_query_text(self) -> None:
        self._redraw()

    @on(Input.Changed, ".term-search")
    def _search(self, event: Input.Changed) -> None:
        event.stop()
        self.query_text = event.value.strip()

    def cycle_mode(self) -> str:
        self.mode = MODES[(MODES.index(self.mode) + 1) % len(MODES)]
        return self.mode

    def cycle_stamps(self) -> str:
        self.stamps = STAMPS[(STAMPS.index(self.stamps) + 1) % len(STAMPS)]
        return self.stamps

    def clear(self) -> None:
        self.entries.clear()
        self.bytes_in = self.bytes_out = 0
        self.last_ack = self.last_msg = ""
        self._redraw()

    def save(self, path: Path) -> Path:
        """Write the current view (mode, time stamps and search applied)."""
        path = Path(path)
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text("".join(line.plain + "\n" for line in self.lines()), encoding="utf-8")
        return path
