"""``hexbot console``: the Textual application.

Serial I/O never runs on the UI thread: the host's reader threads post
messages (``post_message`` is thread-safe), sends and multi-step workflows
run in thread workers, and a workflow checks a cancel event between and
during its steps.
"""

from __future__ import annotations

import threading
from collections.abc import Callable
from pathlib import Path

from textual import on, work
from textual.app import App, ComposeResult
from textual.binding import Binding
from textual.containers import Horizontal, ScrollableContainer, Vertical
from textual.widgets import Footer, Header, ProgressBar, Static, TabbedContent, TabPane

from hexbot.errors import HexBotError
from hexbot.host import commands
from hexbot.host.capture import Record
from hexbot.host.console.composer import Composer
from hexbot.host.console.connection import PortPanel
from hexbot.host.console.dialogs import HelpScreen, PromptScreen, RotateScreen
from hexbot.host.console.lattice import LatticeLegend, LatticeView
from hexbot.host.console.messages import Parsed, PortState, SimEvent, Traffic
from hexbot.host.console.modules_view import ModulesView
from hexbot.host.console.palette import ConsoleCommands
from hexbot.host.console.terminal import Entry, Terminal
from hexbot.host.endpoints import Endpoints, scenario_module_ids
from hexbot.host.host import DEBUG, IR, Host
from hexbot.host.link import LinkState, PortSettings
from hexbot.protocol import frames, wire
from hexbot.protocol.frames import Command

Opener = Callable[[], tuple[Host, Endpoints | None]]
Step = Callable[[threading.Event], str]


class HexBotConsole(App[None]):
    CSS_PATH = "console.tcss"
    TITLE = "HexBot console"
    COMMANDS = App.COMMANDS | {ConsoleCommands}

    TABS = (("terminals", "Terminals"), ("compose", "Composer"), ("modules", "Modules"),
            ("lattice", "Lattice"), ("ports", "Ports"))
    #: (action, palette title, help) of the thesis workflows
    WORKFLOWS = (
        ("select", "Select modules (69)", "address the following commands to module ids"),
        ("ref", "Make reference (65)", "the selected module becomes (0,0), Yref 0, role S"),
        ("localize", "Localize cluster (66)", "Ref, then localization and status of all"),
        ("status", "Status (70)", "status of the selected modules (or all)"),
        ("rotate", "Rotate CW/CCW (67/68)", "rotate a mobile module about a lattice joint"),
        ("all_off", "All actuators off (20)", "TurnOffAll to every module"),
        ("set_role", "Set role (71)", "mobile (1) or substrate (2) for the selected modules"),
        ("clear_error", "Clear error (72)", "clear the last error of the selected modules"),
        ("cancel", "Cancel operation", "stop the running workflow"),
        ("cycle_mode", "Terminal view: decoded/text/hex", "cycle how terminals show bytes"),
        ("save_terminals", "Save terminals", "write both terminals to the session folder"),
        ("clear_terminals", "Clear terminals", "clear both terminals and their counters"),
        ("help", "Help", "keys and workflows"),
    )

    BINDINGS = [
        Binding("f1,question_mark", "help", "Help"),
        Binding("s", "select", "Select"),
        Binding("r", "ref", "Ref"),
        Binding("l", "localize", "Localize"),
        Binding("t", "status", "Status"),
        Binding("w", "rotate", "Rotate"),
        Binding("o", "all_off", "All off"),
        Binding("escape", "cancel", "Cancel", show=False),
        Binding("m", "cycle_mode", "View", show=False),
        Binding("ctrl+s", "save_terminals", "Save", show=False),
        Binding("ctrl+l", "clear_terminals", "Clear", show=False),
        Binding("1", "show_tab('terminals')", "Terminals", show=False),
        Binding("2", "show_tab('compose')", "Composer", show=False),
        Binding("3", "show_tab('modules')", "Modules", show=False),
        Binding("4", "show_tab('lattice')", "Lattice", show=False),
        Binding("5", "show_tab('ports')", "Ports", show=False),
        Binding("q", "quit", "Quit"),
    ]

    def __init__(self, host: Host | None = None, *, opener: Opener | None = None,
                 reply_timeout: float = 5.0, quiet_s: float = 1.5,
                 localize_timeout: float = 120.0, boot_quiet: float = 2.0,
                 start_ports: bool = True, replay: list[Record] | None = None) -> None:
        super().__init__()
        self.host = host
        self._opener = opener
        self.endpoints: Endpoints | None = None
        self.reply_timeout = reply_timeout
        self.quiet_s = quiet_s
        self.localize_timeout = localize_timeout
        self.start_ports = start_ports
        self.boot_quiet = boot_quiet
        self.replay_records = replay
        self.selection: list[int] | None = None
        self.cancel_event = threading.Event()
        self.busy = ""
        self.last_result = ""
        self.port_states: dict[str, tuple[LinkState, str]] = {}

    # --- layout ---------------------------------------------------------------

    def compose(self) -> ComposeResult:
        yield Header()
        with TabbedContent(initial="terminals", id="tabs"):
            with TabPane("Terminals", id="terminals"):
                with Horizontal(id="terminals-box"):
                    yield Terminal("IR", IR, id="ir-term")
                    yield Terminal("UART1", DEBUG, id="debug-term")
            with TabPane("Composer", id="compose"):
                yield Composer(id="composer")
            with TabPane("Modules", id="modules"):
                yield ModulesView(id="modules-view")
            with TabPane("Lattice", id="lattice"):
                with ScrollableContainer(id="lattice-box"):  # big clusters scroll
                    yield LatticeView(id="lattice-view")
                yield LatticeLegend(id="lattice-legend")
            with TabPane("Ports", id="ports"):
                with Vertical(id="ports-box"):
                    yield PortPanel(IR, "IR transceiver (all modules)", None, wire.BAUD_IR)
                    yield PortPanel(DEBUG, "UART1 debug port (one control board)", None,
                                    wire.BAUD_DEBUG)
                    yield Static("", id="session-info")
        with Horizontal(id="status-bar"):
            yield Static("", id="status")
            yield ProgressBar(id="progress", show_eta=False)
        yield Footer()

    def on_mount(self) -> None:
        self.query_one("#progress", ProgressBar).display = False
        self.on_resize()
        if self.host is not None:
            self.attach(self.host, None)
        elif self._opener is not None:
            self.busy = "starting"
            self._update_status()
            self._open_session()

    def on_resize(self, event: object = None) -> None:
        # Terminals side by side when there is room, stacked in 80 columns.
        self.screen.set_class(self.size.width >= 120, "wide")

    @work(thread=True, exclusive=True, group="open")
    def _open_session(self) -> None:
        assert self._opener is not None
        try:
            host, endpoints = self._opener()
        except HexBotError as exc:
            self.call_from_thread(self._open_failed, str(exc))
            return
        self.call_from_thread(self.attach, host, endpoints)

    def _open_failed(self, why: str) -> None:
        self.busy = ""
        self.last_result = f"[red]cannot open session: {why}[/]"
        self._update_status()
        self.notify(why, title="Session", severity="error", timeout=10)

    def attach(self, host: Host, endpoints: Endpoints | None) -> None:
        """Show this host's ports and follow its traffic."""
        self.host, self.endpoints, self.busy = host, endpoints, ""
        host.add_listener(self._from_reader)
        for name in (IR, DEBUG):
            panel = self.query_one(f"#port-{name}", PortPanel)
            ch = host.channels.get(name)
            if ch is not None:
                self._fill_panel(panel, ch.settings)
                self.port_states[name] = (ch.link.state, ch.link.detail)
                panel.show_state(ch.link.state, ch.link.detail)
        info = []
        if endpoints is not None and endpoints.sim is not None:
            info.append(f"simulator: scenario {endpoints.sim.scenario}")
        if host.log is not None:
            info.append(f"session log: {host.log.folder}")
        self.query_one("#session-info", Static).update("\n".join(info))
        if self.start_ports:
            host.start()
        self._update_status()
        self.refresh_cluster()
        if endpoints is not None and endpoints.sim is not None:
            # Frames sent while the simulated modules boot are lost.
            def boot(cancel: threading.Event) -> str:
                n = commands.wait_until_booted(
                    host, self.boot_quiet, 60.0, cancel,
                    expected=scenario_module_ids(endpoints.sim.scenario))
                return f"{n} boot events"
            boot.__name__ = "modules booting"
            self.start_operation("Simulator", [boot])
        if self.replay_records is not None:
            records = self.replay_records

            def replay(cancel: threading.Event) -> str:
                return f"{host.replay(records, realtime=True, cancel=cancel)} records"
            replay.__name__ = f"{len(records)} records"
            self.start_operation("Replay", [replay])

    def _fill_panel(self, panel: PortPanel, s: PortSettings) -> None:
        from textual.widgets import Input, Select

        panel.query_one(f"#{panel.port}-url", Input).value = s.url
        panel.query_one(f"#{panel.port}-baud", Input).value = str(s.baud)
        panel.query_one(f"#{panel.port}-parity", Select).value = s.parity
        panel.query_one(f"#{panel.port}-bits", Select).value = s.data_bits
        panel.query_one(f"#{panel.port}-stop", Select).value = float(s.stop_bits)

    # --- traffic from the reader threads ------------------------------------

    def _from_reader(self, kind: str, port: str, payload: object) -> None:
        if kind == "event":
            self.post_message(Parsed(port, payload))  # type: ignore[arg-type]
        elif kind in ("tx", "rx"):
            t, data = payload  # type: ignore[misc]
            self.post_message(Traffic(port, kind, t, data))
        elif kind == "state":
            state, detail, t = payload  # type: ignore[misc]
            self.post_message(PortState(port, state, detail, t))
        elif kind == "sim":
            self.post_message(SimEvent(payload))  # type: ignore[arg-type]

    def terminal(self, port: str) -> Terminal:
        return self.query_one("#ir-term" if port == IR else "#debug-term", Terminal)

    def on_traffic(self, msg: Traffic) -> None:
        self.terminal(msg.port).add(Entry(msg.t, msg.direction, data=msg.data))

    def on_parsed(self, msg: Parsed) -> None:
        obs = msg.observed
        self.terminal(msg.port).add(Entry(obs.t, "event", event=obs.event))
        self.refresh_cluster()

    def on_sim_event(self, msg: SimEvent) -> None:
        if msg.event.get("event") == "refused":
            self.notify(f"module {msg.event.get('module')}: {msg.event.get('reason', '')}",
                        title="Simulator: rotation refused", severity="warning")
        self.refresh_cluster()

    def on_port_state(self, msg: PortState) -> None:
        self.port_states[msg.port] = (msg.state, msg.detail)
        self.terminal(msg.port).add(Entry(msg.t, "state",
                                          text=f"{msg.state.value} {msg.detail}"))
        self.query_one(f"#port-{msg.port}", PortPanel).show_state(msg.state, msg.detail)
        if msg.state is LinkState.LOST:
            self.notify(f"{msg.port}: {msg.detail}; retrying", title="Port lost",
                        severity="warning")
        self._update_status()

    def refresh_cluster(self) -> None:
        if self.host is None:
            return
        with self.host.lock:
            self.query_one(ModulesView).refresh_from(self.host.model)
            self.query_one(LatticeView).refresh_from(self.host.model)
            self.query_one(LatticeLegend).refresh_from(self.host.model)
        self._update_status()

    def _update_status(self) -> None:
        parts = []
        for name, label in ((IR, "IR"), (DEBUG, "UART1")):
            state = self.port_states.get(name)
            if state is None:
                parts.append(f"{label} [dim]-[/]")
                continue
            colour = {LinkState.CONNECTED: "green", LinkState.LOST: "red"}.get(state[0],
                                                                             "yellow")
            parts.append(f"{label} [{colour}]{state[0].value}[/]")
        if self.host is not None:
            parts.append(f"{len(self.host.model.modules)} modules, "
                         f"{len(self.host.model.placements)} placed")
        sel = "all" if self.selection is None else ",".join(map(str, self.selection))
        parts.append(f"sel {sel}")
        if self.busy:
            parts.append(f"[b]{self.busy}[/] (esc cancels)")
        elif self.last_result:
            parts.append(self.last_result)
        self.query_one("#status", Static).update(" | ".join(parts))

    # --- ports ---------------------------------------------------------------

    @on(PortPanel.Apply)
    def _apply_port(self, msg: PortPanel.Apply) -> None:
        if self.host is None:
            return
        if msg.settings is None:
            ch = self.host.channels.get(msg.port)
            if ch is not None:
                ch.link.close()
            return
        ch = self.host.add_port(msg.port, msg.settings)
        ch.link.start()

    # --- sending -------------------------------------------------------------

    @on(Composer.Send)
    def _composer_send(self, msg: Composer.Send) -> None:
        self.send_command(msg.command)

    def send_command(self, command: Command) -> None:
        self.query_one(Composer).remember(command)
        self._send_worker(command)

    @work(thread=True, group="send")
    def _send_worker(self, command: Command) -> None:
        # Writing at 300 baud takes ~0.4 s per frame: never on the UI thread.
        try:
            if self.host is None:
                raise HexBotError("no session yet")
            self.host.send(command)
        except HexBotError as exc:
            self.call_from_thread(self.notify, str(exc), title="Not sent", severity="error")

    # --- workflows -------------------------------------------------------------

    def do_workflow(self, action: str) -> None:
        """Run ``action_<name>`` (for the command palette)."""
        getattr(self, f"action_{action}")()

    def _exchange(self, command: Command, modules: list[int] | None,
                  collect: bool = False, quiet: float | None = None,
                  timeout: float | None = None) -> Step:
        def step(cancel: threading.Event) -> str:
            assert self.host is not None
            mark = self.host.mark()
            out = commands.exchange(self.host, command, modules=modules,
                                    timeout=timeout or self.reply_timeout, cancel=cancel)
            if not out.ok:
                raise HexBotError(out.message)
            if collect:
                commands.collect_until_quiet(self.host, mark, quiet or self.quiet_s,
                                             timeout or self.reply_timeout, cancel)
            return out.message
        step.__name__ = str(command)
        return step

    def start_operation(self, title: str, steps: list[Step]) -> None:
        if self.busy:
            self.notify(f"busy: {self.busy}", severity="warning")
            return
        if self.host is None:
            self.notify("no session yet", severity="error")
            return
        self.cancel_event = threading.Event()
        self.busy = title
        bar = self.query_one("#progress", ProgressBar)
        bar.update(total=len(steps), progress=0)
        bar.display = True
        self._update_status()
        self._operation(title, steps, self.cancel_event)

    @work(thread=True, exclusive=True, group="operation")
    def _operation(self, title: str, steps: list[Step], cancel: threading.Event) -> None:
        result, ok = f"{title}: done", True
        for n, step in enumerate(steps):
            if cancel.is_set():
                result, ok = f"{title}: cancelled", False
                break
            self.call_from_thread(self._progress, n, f"{title}: {step.__name__}")
            try:
                step(cancel)
            except HexBotError as exc:
                result, ok = f"{title}: {exc}", False
                break
            if cancel.is_set():
                result, ok = f"{title}: cancelled", False
                break
        self.call_from_thread(self._finished, result, ok, len(steps))

    def _progress(self, n: int, label: str) -> None:
        self.query_one("#progress", ProgressBar).update(progress=n)
        self.busy = label
        self._update_status()

    def _finished(self, result: str, ok: bool, total: int) -> None:
        self.busy = ""
        self.last_result = result if ok else f"[red]{result}[/]"
        bar = self.query_one("#progress", ProgressBar)
        bar.update(progress=total)
        bar.display = False
        self.notify(result, title="Done" if ok else "Failed",
                    severity="information" if ok else "error")
        self._update_status()

    def action_cancel(self) -> None:
        if self.busy:
            self.cancel_event.set()

    def _ask(self, question: str, default: str, then: Callable[[list[int]], None]) -> None:
        def done(text: str | None) -> None:
            if text is None:
                return
            try:
                ids = [int(w) for w in text.replace(",", " ").split()]
            except ValueError:
                self.notify(f"not module ids: {text!r}", severity="error")
                return
            if not ids:
                return
            then(ids)
        self.push_screen(PromptScreen(question, default), done)

    def action_select(self) -> None:
        default = "0" if self.selection is None else " ".join(map(str, self.selection))
        self._ask("Select module ids (0 = all; answers come in this order)", default,
                  self.select_modules)

    def select_modules(self, ids: list[int]) -> None:
        try:
            cmd = commands.select(*ids)
        except HexBotError as exc:
            self.notify(str(exc), severity="error")
            return
        modules = None if ids == [0] else ids
        self.selection = modules
        self.start_operation(f"Select {' '.join(map(str, ids))}",
                             [self._exchange(cmd, modules, collect=modules is None)])

    def action_ref(self) -> None:
        self.start_operation("Ref", [self._exchange(commands.ref(), self.selection)])

    def action_status(self) -> None:
        self.start_operation("Status", [self._exchange(commands.status(), self.selection,
                                                       collect=self.selection is None)])

    def action_all_off(self) -> None:
        self.selection = None
        self.start_operation("All off", [
            self._exchange(commands.select(0), None, collect=True),
            self._exchange(commands.all_off(), None, collect=True)])

    def action_set_role(self) -> None:
        def chosen(ids: list[int]) -> None:
            try:
                cmd = frames.make("SetRole", ids[0])
            except HexBotError as exc:
                self.notify(str(exc), severity="error")
                return
            self.start_operation("SetRole", [self._exchange(cmd, self.selection,
                                                            collect=self.selection is None)])
        self._ask("Role for the selected modules: 1 mobile (M), 2 substrate (S)", "1", chosen)

    def action_clear_error(self) -> None:
        self.start_operation("ClearError", [self._exchange(
            frames.make("ClearError"), self.selection, collect=self.selection is None)])

    def action_localize(self) -> None:
        default = str(self.selection[0]) if self.selection else "1"
        self._ask("Reference module id (becomes (0,0))", default,
                  lambda ids: self.localize(ids[0]))

    def localize(self, ref_id: int) -> None:
        self.selection = None
        long = self.localize_timeout
        self.start_operation("Localize", [
            self._exchange(commands.select(ref_id), [ref_id]),
            self._exchange(commands.ref(), [ref_id]),
            self._exchange(commands.select(0), None, collect=True),
            # reports come one slot apart (2.4 s at 300 baud): allow twice the usual quiet
            self._exchange(commands.localize(), None, collect=True, quiet=2 * self.quiet_s,
                           timeout=long),
            self._exchange(commands.status(), None, collect=True),
        ])

    def action_rotate(self) -> None:
        if self.host is None:
            return
        ids = sorted(m.module_id for m in self.host.model.modules.values()
                     if m.module_id is not None)
        if len(ids) < 2:
            self.notify("need two known modules: localize first (l)", severity="warning")
            return
        self.push_screen(RotateScreen(ids), self._rotate_chosen)

    def _rotate_chosen(self, choice: tuple[str, int, int, int] | None) -> None:
        if choice is None or self.host is None:
            return
        direction, joint, mobile, substrate = choice
        rows = {i: self.host.model.module(i) for i in (mobile, substrate)}
        missing = [i for i, r in rows.items() if r is None or r.orientation is None]
        if missing:
            self.notify(f"orientation of {missing} unknown: run status (t) after localizing",
                        severity="error")
            return
        cmd = commands.rotate(direction, joint, rows[mobile].orientation,  # type: ignore
                              rows[substrate].orientation)  # type: ignore[union-attr]
        self.selection = [substrate, mobile]
        self.start_operation(f"Rotate {direction} {joint}", [
            self._exchange(commands.select(substrate, mobile), [substrate, mobile]),
            self._exchange(cmd, [substrate, mobile], timeout=max(self.reply_timeout, 8.0)),
        ])

    # --- views ---------------------------------------------------------------

    def action_show_tab(self, tab: str) -> None:
        self.show_tab(tab)

    def show_tab(self, tab: str) -> None:
        self.query_one(TabbedContent).active = tab

    def compose_function(self, code: int) -> None:
        self.show_tab("compose")
        self.query_one(Composer).choose(code, focus=True)

    def action_cycle_mode(self) -> None:
        for port in (IR, DEBUG):
            mode = self.terminal(port).cycle_mode()
        self.notify(f"terminals show {mode}")

    def action_clear_terminals(self) -> None:
        for port in (IR, DEBUG):
            self.terminal(port).clear()

    def action_save_terminals(self) -> None:
        folder = self.host.log.folder if self.host and self.host.log else Path.cwd()
        paths = [self.terminal(p).save(folder / f"terminal-{p}.txt") for p in (IR, DEBUG)]
        self.notify("saved " + ", ".join(str(p) for p in paths))

    def action_help(self) -> None:
        keys = [(b.key, b.description) for b in self.BINDINGS if isinstance(b, Binding)]
        keys.append(("ctrl+p", "command palette: workflows, tabs, every function"))
        keys.append(("/", "terminals: type in the search box to filter lines"))
        self.push_screen(HelpScreen(keys))

    def on_unmount(self) -> None:
        if self.host is not None:
            self.host.close()
        if self.endpoints is not None:
            self.endpoints.close()
