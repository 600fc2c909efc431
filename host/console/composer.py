"""The message composer: a searchable function table generated from
``protocol/``, one validated input per argument with its range and meaning,
the exact frame previewed in hex, and a history to re-send from."""

from __future__ import annotations

from collections.abc import Callable

from rich.markup import escape
from textual import events, on
from textual.app import ComposeResult
from textual.containers import Horizontal, Vertical, VerticalScroll
from textual.message import Message
from textual.widgets import Button, DataTable, Input, Label, Static

from hexbot.errors import FrameError
from hexbot.host.commands import parse_raw
from hexbot.host.describe import describe_tx
from hexbot.protocol import frames
from hexbot.protocol.codes import CODES, FunctionCode, executable_codes
from hexbot.protocol.frames import Command


def function_rows(query: str) -> list[FunctionCode]:
    """Executable functions whose code, name, board or comment contain
    every word of the query, best name matches first."""
    words = query.lower().split()
    out = []
    for fn in executable_codes():
        hay = f"{fn.code} {fn.name} {fn.board.value} {fn.comment} {fn.signature()}".lower()
        if all(w in hay for w in words):
            out.append(fn)
    if words:
        # Exact code or name first, then names starting with / containing the query.
        first = words[0]
        name_rank = [(lambda n: 0 if n == first or str(fn.code) == first else
                      1 if n.startswith(first) else 2 if first in n else 3)(fn.name.lower())
                     for fn in out]
        out = [fn for _, fn in sorted(zip(name_rank, out, strict=True), key=lambda p: p[0])]
    return out


#: Seconds the filter holds keys typed after Enter for the form Enter opens,
#: at most (it hands them over as soon as the form has the focus).
TYPEAHEAD_HOLD_S = 1.0


class FunctionFilter(Input):
    """The function table's filter. Enter opens the highlighted function's
    form, whose first field takes the focus only after a refresh; keys
    typed in between (a fast typist, a paste) belong to that form, not to
    the filter, so they wait here until the composer plays them again."""

    def __init__(self, **kwargs) -> None:
        super().__init__(**kwargs)
        self.held: list[events.Key] | None = None  # None: not holding

    async def _on_key(self, event: events.Key) -> None:
        if self.held is not None:
            event.stop()
            event.prevent_default()
            self.held.append(event)
            return
        if event.key == "enter":  # the submit that follows says where they go
            held = self.held = []
            self.set_timer(TYPEAHEAD_HOLD_S, lambda: self.play_held(held))
        await super()._on_key(event)

    def play_held(self, only: list[events.Key] | None = None) -> None:
        """Send the held keys again, to whatever has the focus now (with
        ``only``: if the filter still holds that list, a time-out's)."""
        if only is not None and self.held is not only:
            return
        held, self.held = self.held or [], None
        for key in held:
            self.app.post_message(events.Key(key.key, key.character))


class Composer(Vertical):
    class Send(Message):
        """The user asked to send this command (or these raw bytes)."""

        def __init__(self, command: Command | bytes) -> None:
            super().__init__()
            self.command = command

    def __init__(self, *, id: str | None = None) -> None:
        super().__init__(id=id)
        self.function: FunctionCode | None = None
        self.command: Command | None = None
        self.history: list[Command | bytes] = []

    def compose(self) -> ComposeResult:
        with Vertical(id="fn-pick"):
            yield FunctionFilter(placeholder="filter: name, code or words (e.g. 'magnet')",
                                 id="fn-filter")
            yield DataTable(id="fn-table", cursor_type="row", zebra_stripes=True)
        with VerticalScroll(id="fn-form"):
            yield Label("pick a function", id="fn-title")
            with Horizontal(id="fn-buttons"):
                yield Button("Send", id="fn-send", variant="primary", disabled=True)
                yield Static("", id="fn-preview")
            yield Vertical(id="fn-args")
            yield Input(placeholder='raw bytes: hex 2A 46 4E.. or "*FNNNNNNNN#" (enter sends)',
                        id="raw-input")
            yield Label("history (enter re-sends)", classes="section")
            yield DataTable(id="fn-history", cursor_type="row")

    def on_mount(self) -> None:
        table = self.query_one("#fn-table", DataTable)
        table.add_columns("code", "function", "board", "comment")
        history = self.query_one("#fn-history", DataTable)
        history.add_columns("#", "command", "frame")
        self._fill("")

    def _fill(self, query: str) -> None:
        table = self.query_one("#fn-table", DataTable)
        table.clear()
        for fn in function_rows(query):
            table.add_row(str(fn.code), fn.signature(), fn.board.value, fn.comment,
                          key=str(fn.code))

    @on(Input.Changed, "#fn-filter")
    def _filter(self, event: Input.Changed) -> None:
        event.stop()
        self._fill(event.value)

    @on(Input.Submitted, "#fn-filter")
    def _filter_enter(self, event: Input.Submitted) -> None:
        event.stop()
        table = self.query_one("#fn-table", DataTable)
        typed = self.query_one("#fn-filter", FunctionFilter)
        if table.row_count:
            key = table.coordinate_to_cell_key((table.cursor_row, 0)).row_key.value
            self.choose(int(key), focus=True, then=typed.play_held)
        else:
            typed.play_held()  # no form: they were the filter's after all

    @on(DataTable.RowHighlighted, "#fn-table")
    @on(DataTable.RowSelected, "#fn-table")
    def _row(self, event: DataTable.RowHighlighted | DataTable.RowSelected) -> None:
        event.stop()
        if event.row_key is not None and event.row_key.value is not None:
            self.choose(int(event.row_key.value), focus=isinstance(event, DataTable.RowSelected))

    def choose(self, code: int, *, focus: bool = False,
               then: Callable[[], None] | None = None) -> None:
        """Show the form of one function (also used by the command palette);
        with ``focus``, focus its first field and then call ``then``."""
        fn = CODES[code]
        if self.function is fn:
            if focus:
                self._focus_first(then)
            return
        self.function = fn
        self.query_one("#fn-title", Label).update(
            f"{fn.code} {fn.signature()} - {fn.comment} [{fn.board.value} board]")
        box = self.query_one("#fn-args", Vertical)
        box.remove_children()
        rows = []
        for i, arg in enumerate(fn.args):
            unit = " x 10 ms" if arg.unit == "tick" else ""
            rows.append(Horizontal(
                Label(f"{arg.name:>4}", classes="arg-name"),
                Input(placeholder=f"{arg.lo}..{arg.hi}", id=f"arg-{i}", classes="arg-input",
                      type="integer"),
                Label(f"{arg.meaning} ({arg.lo}..{arg.hi}{unit})", classes="arg-meaning"),
                classes="arg-row"))
        box.mount_all(rows)
        self._validate()
        if focus:
            self.call_after_refresh(self._focus_first, then)

    def _focus_first(self, then: Callable[[], None] | None = None) -> None:
        inputs = self.query(".arg-input")
        (inputs.first() if inputs else self.query_one("#fn-send")).focus()
        if then is not None:  # after the app has moved the focus (focus() queues that)
            self.app.call_later(then)

    def arg_values(self) -> list[str]:
        return [inp.value.strip() for inp in self.query(".arg-input").results(Input)]

    @on(Input.Changed, ".arg-input")
    def _arg_changed(self, event: Input.Changed) -> None:
        event.stop()
        self._validate()

    @on(Input.Submitted, ".arg-input")
    def _arg_submitted(self, event: Input.Submitted) -> None:
        event.stop()
        # Enter sends as soon as the command is complete, else moves on.
        if self.command is not None:
            self.send()
            return
        inputs = list(self.query(".arg-input").results(Input))
        idx = inputs.index(event.input)
        if idx + 1 < len(inputs):
            inputs[idx + 1].focus()
        else:
            self.app.bell()

    def _validate(self) -> None:
        preview = self.query_one("#fn-preview", Static)
        button = self.query_one("#fn-send", Button)
        self.command = None
        if self.function is None:
            return
        values = self.arg_values()
        # Optional trailing arguments (Select's further ids) may stay empty.
        while values and not values[-1]:
            values.pop()
        try:
            if any(not v for v in values):
                raise FrameError("fill in every argument up to the last one used")
            args = [int(v) for v in values]
            cmd = frames.make(self.function.code, *args)
            data = frames.encode_pc(cmd)
        except (FrameError, ValueError) as exc:
            preview.update(f"[red]{exc}[/]")
            button.disabled = True
            return
        self.command = cmd
        preview.update(f"frame  [b]{data.hex(' ')}[/b]   ({cmd})")
        button.disabled = False

    @on(Button.Pressed, "#fn-send")
    def _pressed(self, event: Button.Pressed) -> None:
        event.stop()
        self.send()

    def send(self) -> bool:
        if self.command is None:
            self.app.bell()
            return False
        self.post_message(self.Send(self.command))
        return True

    @on(Input.Submitted, "#raw-input")
    def _send_raw(self, event: Input.Submitted) -> None:
        """Raw bytes as ``hexbot send --raw`` reads them; a bad entry stays
        in the input with the reason."""
        event.stop()
        try:
            data = parse_raw(event.value, "raw bytes")
        except FrameError as exc:
            self.app.notify(escape(str(exc)), title="Not sent", severity="error")
            return
        event.input.value = ""
        self.post_message(self.Send(data))

    def remember(self, command: Command | bytes) -> None:
        """Add a sent command to the history (newest first)."""
        self.history.insert(0, command)
        table = self.query_one("#fn-history", DataTable)
        table.clear()
        for n, cmd in enumerate(self.history[:50]):
            if isinstance(cmd, bytes):
                shown, data = f"raw: {describe_tx(cmd)}", cmd
            else:
                shown, data = str(cmd), frames.encode_pc(cmd, strict=False)
            table.add_row(str(len(self.history) - n), shown, data.hex(" "), key=str(n))

    @on(DataTable.RowSelected, "#fn-history")
    def _resend(self, event: DataTable.RowSelected) -> None:
        event.stop()
        if event.row_key.value is not None:
            self.post_message(self.Send(self.history[int(event.row_key.value)]))
