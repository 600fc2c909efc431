"""``hexbot console``: the Textual application.

Serial I/O never runs on the UI thread: the host's reader threads post
messages (``post_message`` is thread-safe), sends and multi-step workflows
run in thread workers. Every exchange goes through one
:class:`~hexbot.host.session.Session` (typed outcomes, the protocol's reply
time-outs) and the thesis workflows are :mod:`hexbot.host.workflows`;
cancelling wakes the session's wait.
"""

from __future__ import annotations

import copy
import threading
import time
import traceback
from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING

from rich.markup import escape
from textual import on, work
from textual.app import App, ComposeResult
from textual.binding import Binding
from textual.containers import Horizontal, ScrollableContainer, Vertical
from textual.css.query import NoMatches
from textual.widgets import (
    Footer,
    Header,
    Input,
    ProgressBar,
    Static,
    TabbedContent,
    TabPane,
)

from hexbot.errors import CancelledError, HexBotError, LinkUnavailableError
from hexbot.host import workflows
from hexbot.host.capture import Record
from hexbot.host.console.boards_view import BoardsView
from hexbot.host.console.composer import Composer
from hexbot.host.console.connection import PortPanel
from hexbot.host.console.dialogs import HelpScreen, PlanScreen, PromptScreen, RotateScreen
from hexbot.host.console.lattice import LatticeLegend, LatticeView
from hexbot.host.console.messages import CaughtUp, HostNote, Parsed, PortState, SimEvent
from hexbot.host.console.messages import Traffic as TrafficMsg
from hexbot.host.console.modules_view import ModulesView
from hexbot.host.console.palette import ConsoleCommands
from hexbot.host.console.terminal import Entry, Terminal
from hexbot.host.endpoints import Endpoints
from hexbot.host.events import (
    HostEvent,
    HostWarning,
    Listener,
    Observed,
    PortChanged,
    SimVerdict,
    Traffic,
)
from hexbot.host.host import DEBUG, IR, Host
from hexbot.host.link import LinkState, PortSettings
from hexbot.host.replay_control import ReplayControl
from hexbot.host.session import Outcome, Session, select
from hexbot.protocol import frames, wire
from hexbot.protocol.codes import Role, lookup
from hexbot.protocol.frames import Command
from hexbot.protocol.simulation import PlantVerdict, Refused

if TYPE_CHECKING:  # the planner loads when a plan is asked for, not at start-up
    from hexbot.planning.plan import Plan

#: Opens the session's ports (in a worker thread); ``listeners`` see every
#: event from the first byte on.
Opener = Callable[[list[Listener]], tuple[Host, Endpoints | None]]
#: One step of an operation: runs in the worker, returns a one-line result,
#: raises HexBotError to end the operation as failed.
Step = Callable[[], str]
#: Plant verdicts listed under the lattice.
SIM_LOG_LINES = 3
#: Cluster views are redrawn at most this often (seconds).
REFRESH_S = 0.05
#: How often the status line shows a wait's progress (seconds).
WAIT_TICK_S = 0.25
BOARDS_TICK_S = 0.2  # the Boards tab's poll of the simulated pins


def _code(name: str) -> int:
    """A function's code, as the menus show it (Table 3-7)."""
    return lookup(name).code


class HexBotConsole(App[None]):
    CSS_PATH = "console.tcss"
    TITLE = "HexBot console"
    COMMANDS = App.COMMANDS | {ConsoleCommands}

    #: every tab, in the order of their keys 1..6 (the palette lists them all)
    TABS = (("terminals", "Terminals"), ("compose", "Composer"), ("modules", "Modules"),
            ("lattice", "Lattice"), ("ports", "Ports"), ("boards", "Boards"))
    #: (action, palette title, help) of the thesis workflows
    WORKFLOWS = (
        ("select", f"Select modules ({_code('Select')})",
         "address the following commands to module ids"),
        ("ref", f"Make reference ({_code('Ref')})",
         "the selected module becomes (0,0), Yref 0, role S"),
        ("localize", f"Localize cluster ({_code('Localize')})",
         "Ref, then localization and status of all"),
        ("status", f"Status ({_code('Status')})", "status of the selected modules (or all)"),
        ("rotate", f"Rotate CW/CCW ({_code('CW')}/{_code('CCW')})",
         "rotate a mobile module about a lattice joint"),
        ("plan", "Plan and execute (goal file)",
         "localize, plan to a goal configuration, check the plan, execute and verify it"),
        ("all_off", f"All actuators off ({_code('TurnOffAll')})", "TurnOffAll to every module"),
        ("set_role", f"Set role ({_code('SetRole')})",
         f"mobile ({Role.MOBILE.value}) or substrate ({Role.SUBSTRATE.value}) for the selected "
         "modules"),
        ("clear_error", f"Clear error ({_code('ClearError')})",
         "clear the last error of the selected modules"),
        ("cancel", "Cancel operation", "stop the running workflow"),
        ("cycle_mode", "Terminal view: decoded/text/hex", "cycle how terminals show bytes"),
        ("cycle_stamps", "Time stamps: session/wall clock", "seconds since start or time of day"),
        ("search", "Search the terminals", "type to keep only matching lines"),
        ("save_terminals", "Save terminals", "write both terminals to the session folder"),
        ("clear_terminals", "Clear terminals", "clear both terminals and their counters"),
        ("restart_session", "Restart the simulator", "open the session's ports anew"),
        ("help", "Help", "keys and workflows"),
    )

    # The footer shows them in this order and cuts at the terminal's edge:
    # help, the emergency stop and quit come first (80 columns show them).
    BINDINGS = [
        Binding("f1,question_mark", "help", "Help"),
        Binding("o", "all_off", "All off"),
        Binding("q", "quit", "Quit"),
        Binding("l", "localize", "Localize"),
        Binding("w", "rotate", "Rotate"),
        Binding("g", "plan", "Plan"),
        Binding("s", "select", "Select"),
        Binding("r", "ref", "Ref"),
        Binding("t", "status", "Status"),
        Binding("escape", "cancel", "Cancel", show=False),
        Binding("m", "cycle_mode", "View", show=False),
        Binding("c", "cycle_stamps", "Time stamps", show=False),
        Binding("slash", "search", "Search", show=False),
        Binding("ctrl+s", "save_terminals", "Save", show=False),
        Binding("ctrl+l", "clear_terminals", "Clear", show=False),
        Binding("ctrl+r", "restart_session", "Restart simulator", show=False),
        Binding("p", "replay_pause", "Replay: pause / resume", show=False),
        Binding("left_square_bracket", "replay_speed(False)", "Replay: half speed", show=False),
        Binding("right_square_bracket", "replay_speed(True)", "Replay: double speed",
                show=False),
        Binding("full_stop", "replay_skip", "Replay: skip 10 s ahead", show=False),
        Binding("1", "show_tab('terminals')", "Terminals", show=False),
        Binding("2", "show_tab('compose')", "Composer", show=False),
        Binding("3", "show_tab('modules')", "Modules", show=False),
        Binding("4", "show_tab('lattice')", "Lattice", show=False),
        Binding("5", "show_tab('ports')", "Ports", show=False),
        Binding("6", "show_tab('boards')", "Boards", show=False),
    ]

    def __init__(self, host: Host | None = None, *, opener: Opener | None = None,
                 reply_timeout: float | None = None, start_ports: bool = True,
                 replay: list[Record] | None = None) -> None:
        """``host``: a host whose ports are configured (started here unless
        ``start_ports`` is False); or ``opener``: opens one (a worker thread).
        ``reply_timeout`` overrides the protocol's bound on replies for the
        console's single commands (None: the protocol decides)."""
        super().__init__()
        self.host = host
        self.session: Session | None = None
        self._opener = opener
        self.endpoints: Endpoints | None = None
        self.reply_timeout = reply_timeout
        self.start_ports = start_ports
        self.replay_records = replay
        self.replay_control: ReplayControl | None = None  # while a replay plays
        self.cancel_event = threading.Event()
        self.busy = ""
        self.all_off_next = False  # All off asked while an operation ran
        self.last_result = ""
        self.port_states: dict[str, tuple[LinkState, str]] = {}
        self.sim_log: list[PlantVerdict] = []  # the plant's verdicts, newest last
        self._refresh_pending = False
        self.step_progress = (0, 1)  # (steps done, steps) of the running operation
        self.after_operation: Callable[[], None] | None = None  # see start_operation
        self.goal_file = ""  # the last goal configuration planned to
        #: the goal of the plan shown or running (outlined in the lattice)
        self.goal_cells: frozenset[tuple[int, int]] = frozenset()
        #: exit status for `hexbot console` when the session could not go on
        self.failure_status: int | None = None

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
            with TabPane("Ports", id="ports"):  # keys 5 and 6: the tabs in this order
                with Vertical(id="ports-box"):
                    yield PortPanel(IR, "IR transceiver (all modules)", None, wire.BAUD_IR)
                    yield PortPanel(DEBUG, "UART1 debug port (one control board)", None,
                                    wire.BAUD_DEBUG)
                    yield Static("", id="session-info")
            with TabPane("Boards", id="boards"):
                yield BoardsView(id="boards-view")
        yield Static("", id="alert")
        with Horizontal(id="status-bar"):
            yield Static("", id="status")
            yield ProgressBar(id="progress", show_eta=False)
        yield Footer(compact=True)

    def on_mount(self) -> None:
        self.main_query("#progress", ProgressBar).display = False
        self.set_interval(WAIT_TICK_S, self._show_wait)
        self.set_interval(BOARDS_TICK_S, self.refresh_boards)
        self.on_resize()
        if self.host is not None:
            self.attach(self.host, None, start=self.start_ports)
        elif self._opener is not None:
            self.busy = "starting"
            self._update_status()
            self._open_session()

    def _shown(self) -> bool:
        """The main screen's widgets are up. Port readers post messages from their
        own threads, so traffic can arrive after the screens are gone, or while
        the app tears the main screen's widgets down at exit (seen in tests as
        NoMatches for '#status' on an emptied screen)."""
        return bool(self.screen_stack) and bool(self.screen_stack[0].query("#status"))

    def main_query(self, selector, expect_type=None):
        """A widget of the main screen, also while a dialog is on top (the
        app's own ``query_one`` looks at the active screen only)."""
        screen = self.screen_stack[0] if self.screen_stack else self.screen
        return screen.query_one(selector, expect_type)

    def on_resize(self, event: object = None) -> None:
        # Terminals side by side when there is room, stacked in 80 columns.
        self.screen.set_class(self.size.width >= 120, "wide")

    @work(thread=True, exclusive=True, group="open")
    def _open_session(self) -> None:
        assert self._opener is not None
        try:
            # the listener from the first byte: the terminals show the boot texts
            host, endpoints = self._opener([self._from_reader])
        except HexBotError as exc:
            self.call_from_thread(self._open_failed, str(exc), exc.exit_status)
            return
        self.call_from_thread(self.attach, host, endpoints, start=False, listening=True)

    def _open_failed(self, why: str, status: int) -> None:
        self.busy = ""
        self.last_result = "[red]cannot open session[/]"
        self.show_alert(f"cannot open session: {why}", status)
        self._update_status()

    def show_alert(self, text: str, status: int | None) -> None:
        """Keep ``text`` in full above the status line (None: clear it);
        quitting then exits with ``status``."""
        alert = self.main_query("#alert", Static)
        alert.update(escape(text))
        alert.display = bool(text)
        self.failure_status = status if text else None

    def attach(self, host: Host, endpoints: Endpoints | None, *, start: bool = True,
               listening: bool = False) -> None:
        """Show this host's ports, follow its traffic (unless ``listening``
        already), start its ports (with ``start``) and open the session."""
        self.host, self.endpoints, self.busy = host, endpoints, ""
        if not listening:
            host.add_listener(self._from_reader)
        for name in (IR, DEBUG):
            panel = self.main_query(f"#port-{name}", PortPanel)
            ch = host.channels.get(name)
            if ch is not None:
                self._fill_panel(panel, ch.settings)
                self.port_states[name] = (ch.link.state, ch.link.detail)
                panel.show_state(ch.link.state, ch.link.detail)
        if start:
            host.start()
        sim = host.simulator  # the embedded simulator's typed interface, or None
        self.session = Session(host, sim.module_ids() if sim is not None else ())
        info = []
        if sim is not None:
            scenario = endpoints.scenario if endpoints is not None else None
            info.append(f"simulator: scenario {scenario or sim.scenario}, "
                        f"{sim.speed:g}x real time")
        if host.log is not None:
            info.append(f"session log: {host.log.folder}")
        self.main_query("#session-info", Static).update("\n".join(info))
        self._update_status()
        self.refresh_cluster()
        if sim is not None:
            session, ids = self.session, sim.module_ids()

            # Frames sent while the simulated modules boot are lost.
            def boot() -> str:
                heard, answered = session.boot(ids)
                heard |= answered
                if session.cancel.is_set():
                    return "boot wait cancelled"
                if not heard >= set(ids):
                    raise HexBotError("no boot text and no answer to a Status from module(s) "
                                      + ", ".join(map(str, sorted(set(ids) - heard))))
                return f"{len(heard)} modules booted"
            boot.__name__ = "modules booting"
            self.start_operation("Simulator", [boot])
        if self.replay_records is not None:
            records = self.replay_records
            control = self.replay_control = ReplayControl(end=records[-1].t if records else 0.0)
            cancel = self.session.cancel

            def replay() -> str:
                played = host.replay(records, control=control, cancel=cancel,
                                     after_record=lambda: self._caught_up(cancel))
                return f"{played} records"
            replay.__name__ = f"{len(records)} records"
            self.start_operation("Replay", [replay])

    def _caught_up(self, cancel: threading.Event) -> None:
        """The replay waits here after each record until the terminals have
        shown it: it never runs ahead of the screen, so pause and Escape act
        on what is shown (on a loaded machine the replay had ended while the
        screen still lagged, and the keys found nothing to pause)."""
        done = threading.Event()
        self.post_message(CaughtUp(done))
        while not done.wait(0.1):
            if cancel.is_set() or not self.is_running:
                return

    def on_caught_up(self, msg: CaughtUp) -> None:
        msg.done.set()

    def _fill_panel(self, panel: PortPanel, s: PortSettings) -> None:
        from textual.widgets import Input, Select

        panel.query_one(f"#{panel.port}-url", Input).value = s.url
        panel.query_one(f"#{panel.port}-baud", Input).value = str(s.baud)
        panel.query_one(f"#{panel.port}-parity", Select).value = s.parity
        panel.query_one(f"#{panel.port}-bits", Select).value = s.data_bits
        panel.query_one(f"#{panel.port}-stop", Select).value = float(s.stop_bits)

    # --- traffic from the reader threads ------------------------------------

    def _from_reader(self, event: HostEvent) -> None:
        """The host's listener (reader or simulating thread): one typed
        event becomes one message for the UI thread."""
        if isinstance(event, Observed):
            self.post_message(Parsed(event.port, event))
        elif isinstance(event, Traffic):
            self.post_message(TrafficMsg(event.port, event.direction.value, event.t,
                                         event.data, time.time()))
        elif isinstance(event, PortChanged):
            self.post_message(PortState(event.port, event.state,  # type: ignore[arg-type]
                                        event.detail, event.t, time.time()))
        elif isinstance(event, SimVerdict):
            self.post_message(SimEvent(event.verdict))
        elif isinstance(event, HostWarning):
            self.post_message(HostNote(event.text, event.t, time.time()))

    def terminal(self, port: str) -> Terminal:
        return self.main_query("#ir-term" if port == IR else "#debug-term", Terminal)

    def on_traffic(self, msg: TrafficMsg) -> None:
        if not self._shown():
            return
        self.terminal(msg.port).add(Entry(msg.t, msg.direction, data=msg.data, wall=msg.wall))

    def on_parsed(self, msg: Parsed) -> None:
        if not self._shown():
            return
        obs = msg.observed
        self.terminal(msg.port).add(Entry(obs.t, "event", event=obs.event))
        self.refresh_soon()

    def on_sim_event(self, msg: SimEvent) -> None:
        if not self._shown():
            return
        verdict = msg.verdict
        self.sim_log = [*self.sim_log, verdict][-SIM_LOG_LINES:]
        if isinstance(verdict, Refused):
            who = f"module {verdict.module}" if verdict.module is not None else "no module"
            self.notify(escape(f"{who}: {verdict.reason.value} ({verdict.detail})"),
                        title="Simulator: rotation refused", severity="warning")
        self.refresh_soon()

    def on_host_note(self, msg: HostNote) -> None:
        """The host's warnings (what `hexbot send` prints as `warning: ...`):
        in the IR terminal, where the traffic that caused them is, and once
        as a notification."""
        if not self._shown():
            return
        self.terminal(IR).add(Entry(msg.t, "warning", text=msg.text, wall=msg.wall))
        self.notify(escape(msg.text), title="Warning", severity="warning", timeout=10)

    def on_port_state(self, msg: PortState) -> None:
        if not self._shown():
            return
        self.port_states[msg.port] = (msg.state, msg.detail)
        self.terminal(msg.port).add(Entry(msg.t, "state", wall=msg.wall,
                                          text=f"{msg.state.value} {msg.detail}"))
        self.main_query(f"#port-{msg.port}", PortPanel).show_state(msg.state, msg.detail)
        ch = self.host.channels.get(msg.port) if self.host is not None else None
        if msg.state is LinkState.LOST and ch is not None and not ch.link.retries:
            restart = "; ctrl+r restarts it" if self._opener is not None else ""
            self.show_alert(f"{msg.port}: {msg.detail}{restart}", LinkUnavailableError.exit_status)
        elif msg.state is LinkState.LOST:
            self.notify(escape(f"{msg.port}: {msg.detail}; retrying"), title="Port lost",
                        severity="warning")
        self._update_status()

    def refresh_soon(self) -> None:
        """Redraw the cluster views once for a burst of events (a localization
        brings dozens): the UI thread's work competes with the readers."""
        if not self._refresh_pending:
            self._refresh_pending = True
            self.set_timer(REFRESH_S, self.refresh_cluster)

    def refresh_cluster(self) -> None:
        self._refresh_pending = False
        if self.host is None or not self.screen_stack:
            return
        # the plant's truth in the localization's frame (none on hardware)
        truth = workflows.plant_placements(self.session) if self.session is not None else {}
        with self.host.lock:  # a copy: readers must not wait for the drawing
            model = copy.deepcopy(self.host.model)
        self.main_query(ModulesView).refresh_from(model)
        self.main_query(LatticeView).refresh_from(model, truth, self.goal_cells)
        self.main_query(LatticeLegend).refresh_from(model, truth, self.sim_log, self.goal_cells)
        self._update_status()

    def refresh_boards(self) -> None:
        """Pins change without a message (a rotation's sequence, an LED test):
        poll the simulator, only while the Boards tab is shown."""
        if self.host is None or not self.screen_stack:
            return
        try:
            if self.main_query(TabbedContent).active != "boards":
                return
            view = self.main_query(BoardsView)
        except NoMatches:  # the screen is being torn down
            return
        with self.host.lock:
            model = copy.deepcopy(self.host.model)
        try:
            view.refresh_from(self.host.simulator, model,
                              workflows.plant_placements(self.session) if self.session else None)
        except NoMatches:  # its table is gone already: the app is being torn down
            return

    def _update_status(self) -> None:
        # What runs, or how the last operation ended, comes first: on a
        # narrow terminal (80 columns) the line is cut at its end.
        parts = []
        if self.busy.startswith("Replay") and self.replay_control is not None:
            parts.append(f"[b]Replay[/] {self.replay_control.describe()} "
                         "(p pause, [ ] speed, . skip)")
        elif self.busy:
            parts.append(f"[b]{escape(self.busy)}[/]{self.wait_text()} (esc cancels)")
        elif self.last_result:
            parts.append(self.last_result)
        parts.append(f"sel {self.selection_text()}")  # before the ports: 80 columns keep it
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
        self.main_query("#status", Static).update(" | ".join(parts))

    # --- ports ---------------------------------------------------------------

    @on(PortPanel.Apply)
    def _apply_port(self, msg: PortPanel.Apply) -> None:
        if self.host is None:
            return
        if self.host.simulator is not None:
            # its ports belong to the cluster it runs: closing one closes the
            # whole cluster, opening one again boots a new cluster behind the
            # session's back
            self.notify("the embedded simulator's ports open and close with it: ctrl+r "
                        "restarts it", title="Not changed", severity="warning")
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

    def send_command(self, command: Command | bytes) -> None:
        if self.busy:  # its frame would land in the middle of the workflow's
            self.notify(f"busy: {self.busy} (escape cancels it)", title="Not sent",
                        severity="warning")
            return
        self._send_worker(command)

    @work(thread=True, group="send")
    def _send_worker(self, command: Command | bytes) -> None:
        # Writing at 300 baud takes ~0.4 s per frame: never on the UI thread.
        try:
            if self.session is None:
                raise HexBotError("no session yet")
            self.session.send(command)
        except HexBotError as exc:
            self.call_from_thread(self.notify, str(exc), title="Not sent", severity="error")
            return
        self.call_from_thread(self.main_query(Composer).remember, command)

    # --- workflows -------------------------------------------------------------

    def do_workflow(self, action: str) -> None:
        """Run ``action_<name>`` (for the command palette)."""
        getattr(self, f"action_{action}")()

    def selection_text(self) -> str:
        """Who the next command addresses, as the session knows it."""
        s = self.session
        if s is not None and s.selection is None:
            return "none"  # no Select yet: every module runs and answers (legacy)
        if s is None or s.all_selected:
            return "all"
        return ",".join(map(str, s.selection))

    def _exchange(self, command: Command) -> Step:
        """A step: ``command`` through the session, which waits for the
        replies its addressing implies; anything but acknowledged fails."""
        def step() -> str:
            assert self.session is not None
            out: Outcome = self.session.request(command, timeout=self.reply_timeout)
            return out.reason
        step.__name__ = str(command)
        return step

    def start_operation(self, title: str, steps: list[Step],
                        then: Callable[[], None] | None = None) -> None:
        """Run ``steps`` in a worker; ``then`` runs on the UI thread after
        they all succeeded (not after a failure or a cancel)."""
        if self.replay_records is not None and title != "Replay":
            self.notify("this console plays a capture: nothing is sent", severity="warning")
            return
        if self.busy:
            self.notify(f"busy: {self.busy}", severity="warning")
            return
        if self.session is None:
            self.notify("no session yet", severity="error")
            return
        self.cancel_event = threading.Event()
        self.session.cancel.clear()
        self.busy = title
        bar = self.main_query("#progress", ProgressBar)
        self.step_progress = (0, len(steps))
        bar.update(total=len(steps), progress=0)
        bar.display = True
        self._update_status()
        self.after_operation = then
        self._operation(title, steps, self.cancel_event)

    @work(thread=True, exclusive=True, group="operation")
    def _operation(self, title: str, steps: list[Step], cancel: threading.Event) -> None:
        detail, ok, cancelled = "", True, False
        for n, step in enumerate(steps):
            if cancel.is_set():
                break
            self.call_from_thread(self._progress, n, f"{title}: {step.__name__}")
            try:
                detail = step()
            except CancelledError:  # Escape, or ctrl+r restarting the session
                cancelled = True
                break
            except HexBotError as exc:  # refused, timed out, port lost, not verified
                detail, ok = str(exc), False
                break
            except Exception as exc:  # a bug must fail the operation, not kill the console
                self.log.error(traceback.format_exc())
                detail, ok = f"internal error: {type(exc).__name__}: {exc}", False
                break
        if cancel.is_set() or cancelled:
            result, ok = f"{title}: cancelled", False
        elif ok:
            result = f"{title}: done" + (f": {detail}" if detail else "")
        else:
            result = f"{title}: {detail}"
        self.call_from_thread(self._finished, result, ok, len(steps))

    def wait_text(self) -> str:
        """``: 3 of 7 replied, 12.4 s of 61 s`` while the session waits."""
        w = self.session.waiting if self.session is not None else None
        if w is None:
            return ""
        elapsed = max(0.0, self.session.now() - w.started)  # type: ignore[union-attr]
        return f": {w.replied} of {w.need} replied, {elapsed:.1f} s of {w.timeout:.0f} s"

    def _show_wait(self) -> None:
        """Tick: a long wait (a localization, ~50 s) moves the bar by replies
        and shows the time it has been waiting and its time-out."""
        if not self.busy or self.session is None or not self._shown():
            return  # the timer ticks on while the app tears its widgets down
        w = self.session.waiting
        done, total = (w.replied, w.need) if w is not None else self.step_progress
        self.main_query("#progress", ProgressBar).update(total=total, progress=done)
        self._update_status()

    def _progress(self, n: int, label: str) -> None:
        if not self._shown():  # a worker's step that ends while the app exits
            return
        self.step_progress = (n, self.step_progress[1])
        self.main_query("#progress", ProgressBar).update(total=self.step_progress[1],
                                                         progress=n)
        self.busy = label
        self._update_status()

    def _finished(self, result: str, ok: bool, total: int) -> None:
        then, self.after_operation = self.after_operation, None
        self.busy = ""
        if not self._shown():  # the app exits: nothing left to show it in
            return
        self.last_result = escape(result) if ok else f"[red]{escape(result)}[/]"
        bar = self.main_query("#progress", ProgressBar)
        bar.update(progress=total)
        bar.display = False
        self.notify(escape(result), title="Done" if ok else "Failed",
                    severity="information" if ok else "error")
        self._update_status()
        if ok and then is not None:
            then()
        if self.all_off_next:  # All off was asked while this ran
            self.all_off_next = False
            self.action_all_off()

    def action_cancel(self) -> None:
        """Escape: leave a text input first (so letter keys act again),
        otherwise cancel the running operation."""
        if isinstance(self.focused, Input) and self.screen is self.screen_stack[0]:
            self.set_focus(None)
            return
        if self.busy:
            self.cancel_event.set()
            if self.session is not None:
                self.session.wake()  # ends the session's current wait at once

    def _ask(self, question: str, default: str, then: Callable[[list[int]], None]) -> None:
        def done(text: str | None) -> None:
            if text is None:
                return
            try:
                ids = [int(w) for w in text.replace(",", " ").split()]
            except ValueError:
                self.notify(escape(f"not module ids: {text!r}"), severity="error")
                return
            if not ids:
                return
            then(ids)
        self.push_screen(PromptScreen(question, default), done)

    def action_select(self) -> None:
        sel = self.selection_text()
        self._ask("Select module ids (0 = all; answers come in this order)",
                  "0" if sel in ("all", "none") else sel.replace(",", " "), self.select_modules)

    def select_modules(self, ids: list[int]) -> None:
        try:
            cmd = select(*ids)
        except HexBotError as exc:
            self.notify(escape(str(exc)), severity="error")
            return
        self.start_operation(f"Select {' '.join(map(str, ids))}", [self._exchange(cmd)])

    def action_ref(self) -> None:
        s = self.session
        if s is not None and (s.selection is None or s.all_selected or len(s.selection) != 1):
            # every module that runs Ref becomes (0, 0): two origins
            self.notify("Ref makes the selected modules the origin: select exactly one "
                        "module first (s)", severity="warning")
            return
        self.start_operation("Ref", [self._exchange(frames.make("Ref"))])

    def action_status(self) -> None:
        s = self.session
        if s is not None and s.selection is None and len(s.cluster) > 1:
            # without a Select every module of a known cluster answers at once:
            # the replies collide (one module alone, or an unknown cluster: fine)
            self.notify("Status asks the selected modules: select first (s; 0 = all)",
                        severity="warning")
            return
        self.start_operation("Status", [self._exchange(frames.make("Status"))])

    def action_all_off(self) -> None:
        """Everything off, at any time: a running operation is cancelled
        first, and All off runs as soon as it has stopped."""
        if self.replay_records is not None:
            self.notify("this console plays a capture: nothing is sent", severity="warning")
            return
        if self.busy:
            self.all_off_next = True
            self.cancel_event.set()
            if self.session is not None:
                self.session.wake()
            return

        def step() -> str:
            assert self.session is not None
            workflows.all_off(self.session)
            return ""
        step.__name__ = "TurnOffAll, Select(0), TurnOffAll"
        self.start_operation("All off", [step])

    def action_set_role(self) -> None:
        def chosen(ids: list[int]) -> None:
            try:
                cmd = frames.make("SetRole", ids[0])
            except HexBotError as exc:
                self.notify(escape(str(exc)), severity="error")
                return
            self.start_operation("SetRole", [self._exchange(cmd)])
        self._ask("Role for the selected modules: 1 mobile (M), 2 substrate (S)", "1", chosen)

    def action_clear_error(self) -> None:
        self.start_operation("ClearError", [self._exchange(frames.make("ClearError"))])

    def action_localize(self) -> None:
        sel = self.selection_text()
        default = sel.split(",")[0] if sel not in ("all", "none") else "1"
        def chosen(ids: list[int]) -> None:
            if len(ids) != 1:  # it used to take the first and drop the rest
                self.notify("one reference module: it becomes (0,0)", severity="warning")
                return
            self.localize(ids[0])
        self._ask("Reference module id (becomes (0,0))", default, chosen)

    def localize(self, ref_id: int) -> None:
        """The localization workflow: ``ref_id`` becomes (0,0), one code 66
        for everyone, then everyone's status."""
        def step() -> str:
            assert self.session is not None
            found = workflows.localize(self.session, ref_id)
            return f"{len(found)} modules localized"
        step.__name__ = f"Select({ref_id}), Ref, Select(0), Localize, Status"
        self.start_operation("Localize", [step])

    def known_ids(self) -> list[int]:
        """Every module id the replies, the boot texts or the scenario named."""
        ids: set[int] = set()
        if self.host is not None:
            ids |= {m.module_id for m in self.host.model.modules.values()
                    if m.module_id is not None}
        if self.session is not None:
            ids |= self.session.known | self.session.cluster
        return sorted(ids)

    def action_rotate(self) -> None:
        if self.host is None:
            return
        ids = self.known_ids()
        if len(ids) < 2:
            self.notify("need two known modules: localize first (l)", severity="warning")
            return
        self.push_screen(RotateScreen(ids), self._rotate_chosen)

    def _rotate_chosen(self, choice: tuple[str, int, int, int] | None) -> None:
        if choice is not None:
            self.rotate(*choice)

    def rotate(self, direction: str, joint: int, mobile: int, substrate: int) -> None:
        """The rotation workflow: roles, selection, 67/68, and the check that
        the module is where it should be (the plant's verdict on the
        simulator, a new localization elsewhere). Refused before sending when
        an orientation is unknown or stale; a refused or unverified move
        fails."""
        def step() -> str:
            assert self.session is not None
            return workflows.rotate(self.session, direction, joint, mobile,
                                    substrate).describe()
        step.__name__ = f"module {mobile} on {substrate}, then verify"
        self.start_operation(f"Rotate {direction} {joint}", [step])

    def action_plan(self) -> None:
        from hexbot.planning.execute import PLAN_USAGE

        self.push_screen(PromptScreen(
            f"Plan to a goal: {PLAN_USAGE} (GOAL: a 0/1 grid or .toml cells file; the "
            "reference, by default the cluster's origin if a Ref made one, else the "
            "simulator's base module, stays where it is)",
            self.goal_file), lambda text: self.plan_to(text) if text else None)

    def plan_to(self, text: str) -> None:
        """The plan workflow for ``GOAL [reference ID] [verify ...]``: localize
        from the reference, plan from the cluster as it stands to the goal
        (robust mode, the reference fixed), show the plan; :meth:`execute_plan`
        runs it when confirmed."""
        from hexbot.planning.execute import plan_from_cluster, plan_request

        if self.session is None:
            self.notify("no session yet", severity="error")
            return
        try:
            request = plan_request(text.split())
        except HexBotError as exc:  # file:line: problem, or a bad option
            self.notify(escape(str(exc)), title="Goal not loaded", severity="error")
            return
        self.goal_file, goal = text, request.goal
        session, made = self.session, {}
        reference = request.reference_in(session)
        path = text.split()[0]

        def step() -> str:
            plan, poses = plan_from_cluster(session, goal, reference)
            made.update(plan=plan, poses=poses)
            # planned, not done: nothing has moved yet (e executes it)
            return (f"{plan.move_count} move(s) in {plan.time_steps} time step(s) planned, "
                    f"not executed ({plan.method or plan.mode})")
        step.__name__ = f"localize from module {reference}, then plan to {Path(path).name}"

        def discard() -> None:
            self.show_goal(frozenset())
            self.last_result = "Plan: discarded, nothing executed"
            self._update_status()

        def show() -> None:
            self.show_goal(made["plan"].goal)
            self.push_screen(PlanScreen(made["plan"]), lambda go: self.execute_plan(
                made["plan"], reference, made["poses"], request.verify)
                if go else discard())
        self.start_operation("Plan", [step], then=show)

    def show_goal(self, goal: frozenset[tuple[int, int]]) -> None:
        """Outline ``goal`` in the lattice (empty: none)."""
        self.goal_cells = frozenset(goal)
        self.refresh_cluster()

    def execute_plan(self, plan: Plan, reference: int, poses: dict[int, workflows.Pose],
                     verify: workflows.Verify = workflows.Verify.AUTO) -> None:
        """Run a confirmed plan move by move (:func:`hexbot.planning.execute.execute`:
        each move verified, the first refused or unverified one ends it, and
        the goal is claimed only after a final localization)."""
        from hexbot.planning.execute import execute

        session, total = self.session, plan.move_count

        def moved(line: str) -> None:  # one line per verified move, from the worker
            self.call_from_thread(self._move_done, line, total)

        def step() -> str:
            assert session is not None
            report = execute(plan, session, reference, poses=poses, log=moved, verify=verify)
            return report.outcome(total)
        step.__name__ = f"{total} moves in {plan.time_steps} time steps"
        self.start_operation("Execute plan", [step])
        self.step_progress = (0, total)

    def _move_done(self, line: str, total: int) -> None:
        """The bar and the status line follow the moves (the lattice legend
        shows each verdict)."""
        done = self.step_progress[0] + 1
        self.step_progress = (done, total)
        last = line.split(": ", 1)[-1]
        self._progress(done, f"Execute plan: {done} of {total} moves, last: {last}")

    # --- views ---------------------------------------------------------------

    def action_show_tab(self, tab: str) -> None:
        self.show_tab(tab)

    def show_tab(self, tab: str) -> None:
        self.main_query(TabbedContent).active = tab

    def compose_function(self, code: int) -> None:
        self.show_tab("compose")
        self.main_query(Composer).choose(code, focus=True)

    def action_cycle_mode(self) -> None:
        for port in (IR, DEBUG):
            mode = self.terminal(port).cycle_mode()
        self.notify(f"terminals show {mode}")

    def action_cycle_stamps(self) -> None:
        for port in (IR, DEBUG):
            stamps = self.terminal(port).cycle_stamps()
        self.notify(f"time stamps: {'wall clock' if stamps == 'wall' else 'since start'}")

    def _replaying(self) -> ReplayControl | None:
        if self.replay_control is None or not self.busy.startswith("Replay"):
            self.notify("no replay is playing", severity="warning")
            return None
        return self.replay_control

    def action_replay_pause(self) -> None:
        if control := self._replaying():
            control.toggle_pause()
            self._update_status()

    def action_replay_speed(self, faster: bool) -> None:
        """``[`` halves the speed, ``]`` doubles it (x1/8..x64)."""
        if control := self._replaying():
            control.faster() if faster else control.slower()
            self._update_status()

    def action_replay_skip(self) -> None:
        if control := self._replaying():
            control.seek(control.position() + 10.0)
            self._update_status()

    def action_search(self) -> None:
        """``/``: the terminals' search box (escape leaves it)."""
        self.show_tab("terminals")
        self.terminal(IR).query_one(".term-search", Input).focus()

    def action_restart_session(self) -> None:
        """ctrl+r: close the session's ports and open them again (a fresh
        embedded simulator); terminals keep their lines."""
        if self._opener is None:
            self.notify("this console was given its ports: nothing to restart",
                        severity="warning")
            return
        if self.session is not None:
            self.session.wake()
        if self.host is not None:
            self.host.close()
        self.host = self.session = None
        self.show_alert("", None)
        self.busy = "starting"
        self._update_status()
        self._open_session()

    def action_clear_terminals(self) -> None:
        for port in (IR, DEBUG):
            self.terminal(port).clear()

    def action_save_terminals(self) -> None:
        """Both terminals to the session folder (without a session log: the
        current folder), stamped so that a second save keeps the first."""
        folder = self.host.log.folder if self.host and self.host.log else Path.cwd()
        stamp = base = time.strftime("%Y%m%d-%H%M%S")
        n = 1
        while any((folder / f"terminal-{p}-{stamp}.txt").exists() for p in (IR, DEBUG)):
            n += 1  # a second save within the same second must not overwrite the first
            stamp = f"{base}-{n}"
        try:
            paths = [self.terminal(p).save(folder / f"terminal-{p}-{stamp}.txt")
                     for p in (IR, DEBUG)]
        except OSError as exc:
            self.notify(escape(f"{folder}: {exc.strerror or exc}"), title="Not saved",
                        severity="error")
            return
        self.notify(escape("saved " + ", ".join(str(p) for p in paths)))

    def action_help(self) -> None:
        keys = [(key_names(self, b), b.description) for b in self.BINDINGS
                if isinstance(b, Binding)]
        keys.append(("ctrl+p", "command palette: workflows, tabs, every function"))
        self.push_screen(HelpScreen(keys))

    def on_unmount(self) -> None:
        if self.session is not None:
            self.session.wake()  # a workflow still waiting gives up
        if self.host is not None:
            self.host.close()
        if self.endpoints is not None:
            self.endpoints.close()


def key_names(app: App, binding: Binding) -> str:
    """A binding's keys as people write them: ``f1, ?`` (not ``f1,question_mark``)."""
    return ", ".join(app.get_key_display(Binding(key.strip(), binding.action))
                     for key in binding.key.split(","))
