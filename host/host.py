"""The host side of a session: ports, parser, logs, cluster model, clock.

One :class:`Channel` per port joins a :class:`~hexbot.host.link.Link`
(bytes), a :class:`~hexbot.protocol.parser.ReplyParser` (events) and the
session log. :class:`Host` holds the channels, keeps a journal of every
event for code that waits for replies (through
:class:`~hexbot.host.session.Session`, the one send-and-wait layer), feeds
the :class:`~hexbot.host.cluster.ClusterModel` and tells listeners
(:mod:`hexbot.host.events`). Listeners are called from reader threads and
must hand work over to their own thread.

The clock is chosen when the ports start: a stepped simulated port makes
time virtual (:class:`~hexbot.host.clock.SteppedClock`), anything else is
the wall clock.
"""

from __future__ import annotations

import threading
from collections.abc import Callable, Iterable

from hexbot.errors import LinkUnavailableError
from hexbot.host.capture import Record
from hexbot.host.clock import Clock, PacedClock, SteppedClock, WallClock
from hexbot.host.cluster import ClusterModel
from hexbot.host.events import (
    HostEvent,
    HostWarning,
    Listener,
    Observed,
    PortChanged,
    SimVerdict,
    Traffic,
    TrafficDirection,
)
from hexbot.host.link import Link, LinkState, PortSettings
from hexbot.host.replay_control import ReplayControl
from hexbot.host.session_log import SessionLog
from hexbot.protocol import frames
from hexbot.protocol.codes import ErrorCode
from hexbot.protocol.frames import Command
from hexbot.protocol.header import schema_mismatch
from hexbot.protocol.mavlink_codec import FramedParser, Framing, MavlinkEncoder
from hexbot.protocol.parser import Event, StatusReport
from hexbot.protocol.simulation import Moved, PlantVerdict, SimulatorAccess

#: Port names: the central IR transceiver and one control board's UART1.
IR, DEBUG = "ir", "debug"
QUIET_FLUSH_S = 1.0  # a half reply older than this becomes garbage
#: Last errors that say a board restarted on its own, and what that means.
_RESTARTS = {
    ErrorCode.WATCHDOG_RESET: "its comm board restarted (watchdog): role, place and "
                              "selection are lost",
    ErrorCode.BROWN_OUT: "its comm board restarted (brown-out): role, place and "
                         "selection are lost",
    ErrorCode.CONTROL_RESTARTED: "its control board restarted: every joint and magnet "
                                 "was released",
}

__all__ = ["DEBUG", "IR", "Host", "Listener", "Observed"]


class PortDecoder:
    """One port's received bytes to events, live and in a replay alike. The
    parser holds a half reply (and garbage, until the next reply) back:
    after ``QUIET_FLUSH_S`` of quiet nothing more is coming to complete it,
    and what it held comes out stamped at the end of that quiet second (so
    a replay, which knows when the next bytes came, shows what the live
    session showed, at the same time).

    ``live``: the times are when a reader thread got the bytes, not when
    they came. A reader that ran late (a loaded machine, a simulator paced
    faster than the reader) reads the second half of a reply long after
    the first, though the line had no gap; so live, the quiet is the time
    between two reads that found nothing (:meth:`quiet` is called for
    each), never the time between two reads that found bytes. (A replay
    has only the capture's read times, so the live session records where
    it cut (:meth:`Host.cut`) and a replay of such a capture cuts there and
    nowhere else: ``cuts_recorded``, :class:`ReplayDecoders`.)"""

    def __init__(self, *, live: bool = False, cuts_recorded: bool = False) -> None:
        self.parser = FramedParser()  # legacy replies and MAVLink frames alike
        self.live = live
        self.cuts_recorded = cuts_recorded
        self._last_rx = 0.0
        self._idle_since: float | None = None  # live: the first empty read since bytes
        self._unflushed = False

    def feed(self, t: float, data: bytes) -> list[tuple[float, Event]]:
        """Bytes received at ``t``: what was held back and went quiet before
        them (a replay), then the events they complete."""
        held = [] if self.live or self.cuts_recorded else self.quiet(t)
        self._last_rx = t
        self._idle_since = None
        self._unflushed = True
        return held + [(t, ev) for ev in self.parser.feed(data)]

    def quiet(self, now: float) -> list[tuple[float, Event]]:
        """What the parser held, when nothing came for ``QUIET_FLUSH_S`` before
        ``now`` (live: since the first read that found nothing)."""
        if not self._unflushed:
            return []
        since = self._last_rx
        if self.live:
            if self._idle_since is None:
                self._idle_since = now
                return []
            since = self._idle_since
        if now - since <= QUIET_FLUSH_S:
            return []
        self._unflushed = False
        stamp = since + QUIET_FLUSH_S
        return [(stamp, ev) for ev in self.parser.flush()]

    @property
    def holding(self) -> bool:
        """Whether the parser holds the start of a reply it has not decoded."""
        return bool(self.parser.pending)

    def flush(self) -> list[tuple[float, Event]]:
        """Everything held, now (the end of a replay), stamped with the last bytes' time."""
        return self.cut(self._last_rx)

    def cut(self, stamp: float) -> list[tuple[float, Event]]:
        """Everything held, stamped ``stamp`` (a replay, where the live session cut)."""
        self._unflushed = False
        return [(stamp, ev) for ev in self.parser.flush()]


class ReplayDecoders:
    """A replay's decoders, one per port, fed with capture records. A format
    2 capture records where the live session cut a half reply (``cut``), so
    the replay cuts there and only there; a format 1 capture has only its
    read times, which judge the quiet second."""

    def __init__(self) -> None:
        self.ports: dict[str, PortDecoder] = {}

    def play(self, rec: Record) -> list[tuple[float, Event]]:
        """The events ``rec`` completes (none for records other than rx and cut)."""
        if rec.kind not in ("rx", "cut"):
            return []
        decoder = self.ports.get(rec.port)
        if decoder is None:
            decoder = self.ports[rec.port] = PortDecoder(cuts_recorded=rec.format >= 2)
        if rec.kind == "rx":
            return decoder.feed(rec.t, rec.data)
        return decoder.cut(float(rec.text))

    def flush(self) -> list[tuple[str, float, Event]]:
        """What each port still holds at the end of the capture (as garbage)."""
        return [(port, t, ev) for port, decoder in self.ports.items()
                for t, ev in decoder.flush()]


class Channel:
    def __init__(self, host: Host, name: str, settings: PortSettings, retry_s: float) -> None:
        self.host = host
        self.name = name
        self.decoder = PortDecoder(live=True)
        self.link = Link(settings, self._on_data, self._on_state, self._on_idle, retry_s=retry_s)

    @property
    def settings(self) -> PortSettings:
        return self.link.settings

    def _on_data(self, data: bytes) -> None:
        for t, ev in self.decoder.feed(self.host.received(self.name, data), data):
            self.host.observe(t, self.name, ev)

    def behind(self) -> bool:
        """Whether this port has bytes its reader has not turned into events
        yet: unread at the port, or the start of a reply in the parser."""
        return self.link.unread() > 0 or self.decoder.holding

    def _on_idle(self) -> None:
        held = self.decoder.quiet(self.host.elapsed())
        if held:  # the capture says so: its read times alone cannot (late reader)
            self.host.cut(self.name, held[0][0])
        for t, ev in held:
            self.host.observe(t, self.name, ev)

    def _on_state(self, state: LinkState, detail: str) -> None:
        self.host.link_state(self.name, state, detail)

    def write(self, data: bytes) -> float:
        self.link.write(data)
        return self.host.sent(self.name, data)


class Host:
    def __init__(self, log: SessionLog | None = None) -> None:
        self.log = log
        self.channels: dict[str, Channel] = {}
        self.model = ClusterModel()
        self.lock = threading.RLock()  # guards model and journal
        self.changed = threading.Condition(self.lock)
        self._journal: list[Observed] = []
        self._listeners: list[Listener] = []
        self.warnings: list[str] = []
        self._schema_checked: set[int] = set()
        self.replaying = False  # events come from a capture (replay), not from a port
        self._restarts_told: dict[int, int] = {}  # module -> restart error warned
        self.clock: Clock = WallClock(self.changed, behind=self._behind)
        #: how commands go out on the IR port (AUTO: the session probes first)
        self.framing = Framing.LEGACY
        self._mavlink: MavlinkEncoder | None = None
        if log is not None:
            log.capture.use_clock(self.elapsed)

    # --- set-up -----------------------------------------------------------

    def add_port(self, name: str, settings: PortSettings, retry_s: float = 1.0) -> Channel:
        if name in self.channels:
            self.channels[name].link.close()
        ch = Channel(self, name, settings, retry_s)
        self.channels[name] = ch
        if self.log:
            self.log.port(name, settings.describe())
        return ch

    def set_framing(self, framing: Framing) -> None:
        """Legacy frames, MAVLink 2 frames, or AUTO (decided by the session's
        probe); replies of both framings are always understood."""
        self.framing = framing
        if framing is Framing.MAVLINK and self._mavlink is None:
            self._mavlink = MavlinkEncoder()
        if self.log:
            self.log.note("host", f"framing {framing.value}")

    def start(self, wait_s: float = 0.0) -> Host:
        """Start every port and choose the clock; with ``wait_s`` raise
        LinkUnavailableError if a port is not connected by then."""
        for ch in self.channels.values():
            ch.link.start()
        if wait_s:
            for ch in self.channels.values():
                ch.link.start(wait_s)
        self._choose_clock()
        return self

    def _choose_clock(self) -> None:
        sim = self.simulator
        if sim is None or not isinstance(self.clock, WallClock):
            return  # hardware, or chosen already
        if sim.stepped:
            self.clock = SteppedClock(sim, self.pump, self._simulator_stopped)
        else:
            self.clock = PacedClock(self.changed, sim, self._simulator_stopped,
                                    behind=self._behind)
        sim.subscribe(self._verdict)
        for note in sim.image_notes:  # what a module's Status would tell, before it runs
            self.warn(self.elapsed(), note)

    def _behind(self) -> bool:
        """Whether a port's reader has bytes it has not turned into events yet."""
        return any(ch.behind() for ch in list(self.channels.values()))

    @property
    def simulator(self) -> SimulatorAccess | None:
        """The simulator behind the IR port, when it is one (``hexbot-sim://``)."""
        ch = self.channels.get(IR)
        return ch.link.simulator if ch is not None else None

    def _simulator_stopped(self) -> str | None:
        """Why the simulator behind the IR port stopped, or None while it runs:
        its port lost is lost for good (an in-process cluster is not opened
        again), and the simulator's clock with it."""
        ch = self.channels.get(IR)
        if ch is None or ch.link.state is not LinkState.LOST:
            return None
        return f"{IR} port lost: {ch.link.detail}" if ch.link.detail else f"{IR} port lost"

    def pump(self) -> None:
        """Stepped ports: move what they received into the session."""
        for ch in self.channels.values():
            ch.link.pump()

    def add_listener(self, listener: Listener) -> None:
        self._listeners.append(listener)

    def close(self) -> None:
        # the last added first: an embedded simulator's debug port lives on the IR port's cluster
        for ch in reversed(list(self.channels.values())):
            ch.link.close()
        if self.log:
            self.log.close()

    def __enter__(self) -> Host:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    # --- time and journal ---------------------------------------------------

    def elapsed(self) -> float:
        """Seconds since the session started: the simulator's time on its
        port, 0 before its clock runs (the port's "connecting" line carried
        a wall-clock 0.001 s, and two runs of a seed differed)."""
        ch = self.channels.get(IR)
        if isinstance(self.clock, WallClock) and ch is not None and ch.link.in_process:
            return 0.0
        return self.clock.now()

    def mark(self) -> int:
        """A position in the journal; wait/collect from here on."""
        with self.lock:
            return len(self._journal)

    def since(self, mark: int) -> list[Observed]:
        with self.lock:
            return self._journal[mark:]

    # --- traffic (called by channels, from reader threads) -----------------

    def received(self, port: str, data: bytes) -> float:
        t = self.log.received(port, data) if self.log else self.elapsed()
        self._notify(Traffic(port, TrafficDirection.RX, t, data))
        return t

    def cut(self, port: str, stamp: float) -> None:
        """The decoder of ``port`` gave up on a half reply (a quiet second),
        stamping it ``stamp``: recorded, so that a replay cuts it there too."""
        if self.log:
            self.log.cut(port, stamp)

    def sent(self, port: str, data: bytes) -> float:
        t = self.log.sent(port, data) if self.log else self.elapsed()
        self._notify(Traffic(port, TrafficDirection.TX, t, data))
        return t

    def observe(self, t: float, port: str, ev: Event) -> None:
        with self.changed:
            obs = Observed(len(self._journal), t, port, ev)
            self._journal.append(obs)
            self.model.apply(port, ev, t)
            self.changed.notify_all()
        if self.log:
            self.log.event(t, port, ev)
        self._notify(obs)
        if (isinstance(ev, StatusReport) and ev.module_id not in self._schema_checked
                and not self.replaying):  # a recorded module is no module of this host's
            self._schema_checked.add(ev.module_id)
            why = schema_mismatch(ev.schema)
            if why is not None:
                self.warn(t, f"module {ev.module_id}: {why}")
        if isinstance(ev, StatusReport):
            self._warn_restart(t, ev)

    def _warn_restart(self, t: float, ev: StatusReport) -> None:
        """A board that restarted on its own says so in its last error
        (docs/firmware.md); tell the user once per module and cause."""
        said = self._restarts_told.get(ev.module_id)
        if ev.error not in _RESTARTS:
            self._restarts_told.pop(ev.module_id, None)
            return
        if said != ev.error:
            self._restarts_told[ev.module_id] = ev.error
            self.warn(t, f"module {ev.module_id}: {_RESTARTS[ev.error]}")

    def warn(self, t: float, text: str) -> None:
        """Tell the user once, in the log and to every listener."""
        self.warnings.append(text)
        if self.log:
            self.log.note("host", f"warning: {text}")
        self._notify(HostWarning(t, text))

    def _verdict(self, verdict: PlantVerdict) -> None:
        if self.log:
            self.log.note("sim", verdict.describe())
        if isinstance(verdict, Moved) and verdict.split:
            self.warn(verdict.t, f"the cluster split: {verdict.describe()}")
        with self.changed:
            self.changed.notify_all()  # a workflow may be waiting for it
        self._notify(SimVerdict(verdict))

    def link_state(self, port: str, state: LinkState, detail: str) -> None:
        if state is LinkState.CONNECTED:
            # a simulated port's clock from its first event on: its log must
            # not carry wall-clock times, or two runs of a seed differ
            self._choose_clock()
        text = f"{state.value} {detail}".strip()
        t = self.log.state(port, text) if self.log else self.elapsed()
        with self.changed:
            self.changed.notify_all()  # a waiter may be waiting on this port
        self._notify(PortChanged(port, state, detail, t))

    def _notify(self, event: HostEvent) -> None:
        for listener in list(self._listeners):
            listener(event)

    # --- replay ----------------------------------------------------------------

    def replay(self, records: Iterable[Record], *, control: ReplayControl | None = None,
               cancel: threading.Event | None = None,
               after_record: Callable[[], None] | None = None) -> int:
        """Play capture records into the host as if they happened now, with
        their recorded time stamps (the console's ``--replay``): received
        bytes go through a parser, sent bytes and state changes to the
        listeners. Nothing is written to a port. ``control`` paces it
        (speed, pause, seek); without, as fast as it goes. ``after_record``
        runs after each record's events went to the listeners (the console
        waits there until it has shown them). Returns records played. A
        replayed module's protocol schema is not checked against this
        host's: the capture's own host spoke to it."""
        self.replaying = True
        decoders = ReplayDecoders()
        n = 0
        stop = cancel or threading.Event()
        for rec in records:
            if stop.is_set():
                break
            if control is not None and not control.wait_until(rec.t, stop):
                break
            n += 1
            if rec.kind == "rx":
                self._notify(Traffic(rec.port, TrafficDirection.RX, rec.t, rec.data))
            for t, ev in decoders.play(rec):  # rx and cut records
                self.observe(t, rec.port, ev)
            if rec.kind == "tx":
                self._notify(Traffic(rec.port, TrafficDirection.TX, rec.t, rec.data))
            elif rec.kind == "state":
                word, _, detail = rec.text.partition(" ")
                try:
                    state = LinkState(word)
                except ValueError:
                    continue
                self._notify(PortChanged(rec.port, state, detail, rec.t))
            if after_record is not None:
                after_record()
        for port, t, ev in decoders.flush():
            self.observe(t, port, ev)
        return n

    # --- sending ------------------------------------------------------------

    def channel(self, port: str = IR) -> Channel:
        try:
            return self.channels[port]
        except KeyError:
            raise LinkUnavailableError(f"no {port} port configured") from None

    def encode(self, command: Command, port: str = IR, *, strict: bool = True,
               target: int = 0) -> bytes:
        """The command's frame in this host's framing (MAVLink on the IR port
        only: a debug port speaks board frames). ``target``: a MAVLink
        target_system (0: the modules the last Select chose)."""
        if port == IR and self.framing is Framing.MAVLINK and self._mavlink is not None:
            return self._mavlink.encode(command, target=target, strict=strict)
        return frames.encode_pc(command, strict=strict)

    def send(self, command: Command | bytes, port: str = IR, *, strict: bool = True,
             target: int = 0) -> int:
        """Send a command (or raw bytes); returns the journal mark taken just
        before, so replies can be awaited from there."""
        data = command if isinstance(command, bytes) else self.encode(command, port,
                                                                      strict=strict,
                                                                      target=target)
        mark = self.mark()
        self.channel(port).write(data)
        return mark
