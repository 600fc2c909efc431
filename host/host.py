"""The host side of a session: ports, parser, logs, cluster model, waiting.

One :class:`Channel` per port joins a :class:`~hexbot.host.link.Link`
(bytes), a :class:`~hexbot.protocol.parser.ReplyParser` (events) and the
session log. :class:`Host` holds the channels, keeps a journal of every
event for code that waits for replies (CLI, scripts, console workers) and
feeds the :class:`~hexbot.host.cluster.ClusterModel`. Listeners (the
console) are called from the reader threads and must hand work over to
their own thread.
"""

from __future__ import annotations

import json
import threading
import time
from collections.abc import Callable, Iterable
from dataclasses import dataclass
from typing import Any

from hexbot.errors import LinkUnavailableError
from hexbot.host.capture import Record
from hexbot.host.cluster import ClusterModel
from hexbot.host.link import Link, LinkState, PortSettings
from hexbot.host.session_log import SessionLog
from hexbot.protocol import frames
from hexbot.protocol.frames import Command
from hexbot.protocol.parser import Event, ReplyParser

#: Port names: the central IR transceiver and one control board's UART1.
IR, DEBUG = "ir", "debug"
QUIET_FLUSH_S = 1.0
SIM_PLANT_EVENTS = ("moved", "refused")  # a half reply older than this becomes garbage


@dataclass(frozen=True)
class Observed:
    seq: int
    t: float
    port: str
    event: Event


#: (kind, port, payload): "tx"/"rx" -> (t, bytes); "event" -> Observed;
#: "state" -> (LinkState, detail, t); "sim" -> the simulator's event dict
Listener = Callable[[str, str, Any], None]


class Channel:
    def __init__(self, host: Host, name: str, settings: PortSettings, retry_s: float) -> None:
        self.host = host
        self.name = name
        self.parser = ReplyParser()
        self._last_rx = 0.0
        self._unflushed = False
        self.link = Link(settings, self._on_data, self._on_state, self._on_idle, retry_s=retry_s)

    @property
    def settings(self) -> PortSettings:
        return self.link.settings

    def _on_data(self, data: bytes) -> None:
        self._last_rx = time.monotonic()
        self._unflushed = True
        t = self.host.received(self.name, data)
        for ev in self.parser.feed(data):
            self.host.observe(t, self.name, ev)

    def _on_idle(self) -> None:
        # The parser holds a half reply (and garbage, until the next reply)
        # back: after a quiet second, nothing more is coming to complete it.
        if self._unflushed and time.monotonic() - self._last_rx > QUIET_FLUSH_S:
            self._unflushed = False
            t = self.host.elapsed()
            for ev in self.parser.flush():
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
        self._changed = threading.Condition(self.lock)
        self._journal: list[Observed] = []
        self._listeners: list[Listener] = []
        self._t0 = time.monotonic()

    # --- set-up -----------------------------------------------------------

    def add_port(self, name: str, settings: PortSettings, retry_s: float = 1.0) -> Channel:
        if name in self.channels:
            self.channels[name].link.close()
        ch = Channel(self, name, settings, retry_s)
        self.channels[name] = ch
        if self.log:
            self.log.port(name, settings.describe())
        return ch

    def start(self, wait_s: float = 0.0) -> Host:
        """Start every port; with ``wait_s`` raise LinkUnavailableError if a
        port is not connected by then."""
        for ch in self.channels.values():
            ch.link.start()
        if wait_s:
            for ch in self.channels.values():
                ch.link.start(wait_s)
        return self

    def add_listener(self, listener: Listener) -> None:
        self._listeners.append(listener)

    def close(self) -> None:
        for ch in self.channels.values():
            ch.link.close()
        if self.log:
            self.log.close()

    def __enter__(self) -> Host:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    # --- time and journal ---------------------------------------------------

    def elapsed(self) -> float:
        if self.log:
            return self.log.capture.elapsed()
        return time.monotonic() - self._t0

    def mark(self) -> int:
        """A position in the journal; wait/collect from here on."""
        with self.lock:
            return len(self._journal)

    def since(self, mark: int) -> list[Observed]:
        with self.lock:
            return self._journal[mark:]

    def wait_for(self, pred: Callable[[Observed], bool], since: int,
                 timeout: float) -> Observed | None:
        """The first observed event at or after ``since`` satisfying ``pred``,
        waiting up to ``timeout`` seconds; None on time-out."""
        deadline = time.monotonic() + timeout
        checked = since
        with self._changed:
            while True:
                for obs in self._journal[checked:]:
                    if pred(obs):
                        return obs
                checked = len(self._journal)
                left = deadline - time.monotonic()
                if left <= 0:
                    return None
                self._changed.wait(left)

    # --- traffic (called by channels, from reader threads) -----------------

    def received(self, port: str, data: bytes) -> float:
        t = self.log.received(port, data) if self.log else self.elapsed()
        self._notify("rx", port, (t, data))
        return t

    def sent(self, port: str, data: bytes) -> float:
        t = self.log.sent(port, data) if self.log else self.elapsed()
        self._notify("tx", port, (t, data))
        return t

    def observe(self, t: float, port: str, ev: Event) -> None:
        with self._changed:
            obs = Observed(len(self._journal), t, port, ev)
            self._journal.append(obs)
            self.model.apply(port, ev, t)
            self._changed.notify_all()
        if self.log:
            self.log.event(t, port, ev)
        self._notify("event", port, obs)

    def sim_event(self, event: dict) -> None:
        """An event of the embedded simulator (called from its own thread).
        Only plant events (moved, refused) are kept: the bus events (one
        per collided byte) would drown them."""
        if event.get("event") not in SIM_PLANT_EVENTS:
            return
        with self.lock:
            self.model.apply_sim(event)
        if self.log:
            self.log.note("sim", json.dumps(event, sort_keys=True))
        self._notify("sim", "sim", event)

    def link_state(self, port: str, state: LinkState, detail: str) -> None:
        text = f"{state.value} {detail}".strip()
        t = self.log.state(port, text) if self.log else self.elapsed()
        self._notify("state", port, (state, detail, t))

    def _notify(self, kind: str, port: str, payload: Any) -> None:
        for listener in list(self._listeners):
            listener(kind, port, payload)

    # --- replay ----------------------------------------------------------------

    def replay(self, records: Iterable[Record], *, realtime: bool = False,
               cancel: threading.Event | None = None) -> int:
        """Play capture records into the host as if they happened now, with
        their recorded time stamps (the console's ``--replay``): received
        bytes go through a parser, sent bytes and state changes to the
        listeners. Nothing is written to a port. Returns records played."""
        parsers: dict[str, ReplyParser] = {}
        start, n, last = time.monotonic(), 0, 0.0
        for rec in records:
            if cancel is not None and cancel.is_set():
                break
            if realtime:
                time.sleep(max(0.0, rec.t - (time.monotonic() - start)))
            last = rec.t
            n += 1
            if rec.kind == "rx":
                self._notify("rx", rec.port, (rec.t, rec.data))
                for ev in parsers.setdefault(rec.port, ReplyParser()).feed(rec.data):
                    self.observe(rec.t, rec.port, ev)
            elif rec.kind == "tx":
                self._notify("tx", rec.port, (rec.t, rec.data))
            elif rec.kind == "state":
                word, _, detail = rec.text.partition(" ")
                try:
                    state = LinkState(word)
                except ValueError:
                    continue
                self._notify("state", rec.port, (state, detail, rec.t))
        for port, parser in parsers.items():
            for ev in parser.flush():
                self.observe(last, port, ev)
        return n

    # --- sending ------------------------------------------------------------

    def channel(self, port: str = IR) -> Channel:
        try:
            return self.channels[port]
        except KeyError:
            raise LinkUnavailableError(f"no {port} port configured") from None

    def send(self, command: Command | bytes, port: str = IR, *, strict: bool = True) -> int:
        """Send a command (or raw bytes); returns the journal mark taken just
        before, so replies can be awaited from there."""
        data = command if isinstance(command, bytes) else frames.encode_pc(command,
                                                                           strict=strict)
        mark = self.mark()
        self.channel(port).write(data)
        return mark
