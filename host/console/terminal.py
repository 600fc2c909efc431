"""A port's terminal: time-stamped lines, decoded/text/hex views, search,
scroll-back, save. Replaces the VB GUI's IR and UART1 text boxes, with the
last ACK (and, for UART1, the last decoded MSG) shown in the title bar."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from rich.text import Text
from textual import on
from textual.app import ComposeResult
from textual.containers import Horizontal, Vertical
from textual.reactive import reactive
from textual.widgets import Input, Label, RichLog

from hexbot.host.describe import code_name, describe_event, describe_tx
from hexbot.protocol.parser import Ack, ControlMessage, ErrorReply, Event, Garbage
from hexbot.protocol.parser import Text as TextEv

MODES = ("decoded", "text", "hex")
MAX_LINES = 5000

_STYLE = {Ack: "bold green", ErrorReply: "bold red", Garbage: "dim red",
          ControlMessage: "bold cyan", TextEv: "yellow"}


@dataclass(frozen=True)
class Entry:
    t: float
    kind: str  # tx | rx | event | state
    data: bytes = b""
    event: Event | None = None
    text: str = ""


def _printable(data: bytes) -> str:
    out = []
    for b in data:
        if b == 10:
            out.append("\\n")
        elif b == 13:
            out.append("\\r")
        elif 32 <= b < 127:
            out.append(chr(b))
        else:
            out.append(f"\\x{b:02x}")
    return "".join(out)


def render_entry(e: Entry, mode: str) -> Text | None:
    """One display line for the mode, or None if the mode hides it."""
    stamp = Text(f"{e.t:9.3f} ", style="dim")
    if e.kind == "state":
        return stamp + Text(f"-- {e.text}", style="bold magenta")
    if e.kind == "tx":
        body = describe_tx(e.data) if mode == "decoded" else (
            e.data.hex(" ") if mode == "hex" else _printable(e.data))
        return stamp + Text(f"> {body}", style="bold blue")
    if e.kind == "event":
        if mode != "decoded":
            return None
        assert e.event is not None
        return stamp + Text(f"< {describe_event(e.event)}",
                            style=_STYLE.get(type(e.event), ""))
    if mode == "decoded":
        return None
    return stamp + Text("< " + (e.data.hex(" ") if mode == "hex" else _printable(e.data)))


class Terminal(Vertical):
    """Lines of one port. ``mode`` cycles decoded -> text -> hex."""

    mode: reactive[str] = reactive("decoded")
    query_text: reactive[str] = reactive("")

    def __init__(self, title: str, port: str, *, id: str | None = None) -> None:
        super().__init__(id=id, classes="terminal")
        self.title_text = title
        self.port = port
        self.entries: list[Entry] = []
        self.bytes_in = self.bytes_out = 0
        self.last_ack = ""
        self.last_msg = ""

    def compose(self) -> ComposeResult:
        with Horizontal(classes="term-bar"):
            yield Label(self.title_text, classes="term-title")
            yield Label("", classes="term-info")
            yield Input(placeholder="search", classes="term-search")
        yield RichLog(max_lines=MAX_LINES, wrap=False, markup=False, classes="term-log")

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
        line = render_entry(entry, self.mode)
        if line is not None and self._matches(line):
            self.query_one(RichLog).write(line)

    def _matches(self, line: Text) -> bool:
        return not self.query_text or self.query_text.lower() in line.plain.lower()

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
        out = []
        for e in self.entries:
            line = render_entry(e, self.mode)
            if line is not None and self._matches(line):
                out.append(line)
        return out

    def _redraw(self) -> None:
        if not self.is_mounted:
            return
        log = self.query_one(RichLog)
        log.clear()
        for line in self.lines():
            log.write(line)
        self._update_info()

    def watch_mode(self) -> None:
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

    def clear(self) -> None:
        self.entries.clear()
        self.bytes_in = self.bytes_out = 0
        self.last_ack = self.last_msg = ""
        self._redraw()

    def save(self, path: Path) -> Path:
        """Write the current view (mode and search applied) to a text file."""
        path = Path(path)
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text("".join(line.plain + "\n" for line in self.lines()), encoding="utf-8")
        return path
