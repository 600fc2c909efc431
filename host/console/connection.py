"""Port configuration for both ports (as the thesis' port window: port,
baud, parity, data bits, stop bits) with connect/disconnect and live state."""

from __future__ import annotations

from rich.markup import escape
from textual import on
from textual.app import ComposeResult
from textual.containers import Horizontal, Vertical
from textual.message import Message
from textual.widgets import Button, Input, Label, Select

from hexbot.errors import LinkUnavailableError
from hexbot.host.link import LinkState, PortSettings

STATE_STYLE = {LinkState.CONNECTED: "green", LinkState.LOST: "red",
               LinkState.CONNECTING: "yellow", LinkState.CLOSED: "dim"}


#: Beyond any UART this tool meets (FTDI adapters top out at 3-4 Mbaud).
MAX_BAUD = 4_000_000


class PortPanel(Vertical):
    """Settings and state of one port."""

    class Apply(Message):
        def __init__(self, port: str, settings: PortSettings | None) -> None:
            super().__init__()
            self.port, self.settings = port, settings  # None = disconnect

    def __init__(self, port: str, title: str, settings: PortSettings | None,
                 default_baud: int) -> None:
        super().__init__(id=f"port-{port}", classes="port-panel")
        self.port = port
        self.title_text = title
        self.settings = settings
        self.default_baud = default_baud

    def compose(self) -> ComposeResult:
        s = self.settings
        yield Label(self.title_text, classes="section")
        with Horizontal(classes="port-row"):
            yield Input(s.url if s else "", placeholder="device or URL (socket://, loop://)",
                        id=f"{self.port}-url", classes="port-url")
            yield Input(str(s.baud if s else self.default_baud), id=f"{self.port}-baud",
                        type="integer", classes="port-baud")
        with Horizontal(classes="port-row"):
            yield Select([(p, p) for p in "NEOMS"], value=s.parity if s else "N",
                         allow_blank=False, id=f"{self.port}-parity", classes="port-opt")
            yield Select([(str(b), b) for b in (8, 7, 6, 5)], value=s.data_bits if s else 8,
                         allow_blank=False, id=f"{self.port}-bits", classes="port-opt")
            yield Select([("1", 1.0), ("1.5", 1.5), ("2", 2.0)],
                         value=float(s.stop_bits) if s else 1.0, allow_blank=False,
                         id=f"{self.port}-stop", classes="port-opt")
        with Horizontal(classes="port-row"):
            yield Button("Connect", id=f"{self.port}-connect", variant="success")
            yield Button("Disconnect", id=f"{self.port}-disconnect", variant="error")
        yield Label("closed", id=f"{self.port}-state", classes="port-state")

    def read_settings(self) -> PortSettings:
        url = self.query_one(f"#{self.port}-url", Input).value.strip()
        baud = self.query_one(f"#{self.port}-baud", Input).value.strip()
        if not baud.isdigit() or not 0 < int(baud) <= MAX_BAUD:
            raise LinkUnavailableError(f"baud must be 1..{MAX_BAUD}, got {baud!r}")
        return PortSettings(url, int(baud),
                            str(self.query_one(f"#{self.port}-parity", Select).value),
                            int(self.query_one(f"#{self.port}-bits", Select).value),  # type: ignore[arg-type]
                            float(self.query_one(f"#{self.port}-stop", Select).value))  # type: ignore[arg-type]

    @on(Button.Pressed)
    def _button(self, event: Button.Pressed) -> None:
        event.stop()
        if event.button.id == f"{self.port}-disconnect":
            self.post_message(self.Apply(self.port, None))
            return
        try:
            settings = self.read_settings()
        except LinkUnavailableError as exc:  # the port stays as it is
            self.app.notify(escape(str(exc)), title="Not connected", severity="error")
            return
        self.post_message(self.Apply(self.port, settings))

    def show_state(self, state: LinkState, detail: str, counters: str = "") -> None:
        style = STATE_STYLE[state]
        text = f"[{style}]\u25cf {state.value}[/] {detail}"
        if counters:
            text += f"  [dim]{counters}[/]"
        # A port may change state while the app tears the panel down.
        for label in self.query(f"#{self.port}-state").results(Label):
            label.update(text)
