"""The one send-and-wait layer: a frame out, the replies it implies, a typed outcome.

Everything that talks to modules goes through :class:`Session`: the
console, ``hexbot send/monitor/run``, plan execution, the pytest plugin and
the firmware tests. It works the same over hardware, a pty and the
embedded simulator, on the wall clock or the simulator's virtual time (the
host's :mod:`~hexbot.host.clock` decides); it waits on conditions, never in
sleep loops.

Which replies a command implies follows the addressing of the protocol
(docs/protocol.md): after ``Select(ids)`` every selected module answers
once, in the order of the list; after ``Select(0)`` every module of the
cluster answers (so the session must know the cluster's ids: from the boot
texts, from status replies, or from the caller); before any ``Select`` the
modules speak the thesis' legacy dialect without ids and one reply is
awaited. How long to wait comes from the protocol's timing
(:func:`hexbot.protocol.timing.reply_timeout_s`), not from the caller.

An :class:`Outcome` says what happened: acknowledged, refused (an ERR, the
unused-code ACK ``N``, the control board's time-out ``~``), timed out
(naming the modules that did not answer), port lost, or cancelled.
"""

from __future__ import annotations

import enum
import functools
import itertools
import re
import threading
from collections.abc import Callable, Collection, Iterable
from dataclasses import dataclass, field

from hexbot.errors import (
    CancelledError,
    CommandRefusedError,
    FrameError,
    HexBotTimeoutError,
    LinkUnavailableError,
)
from hexbot.host.describe import describe_event
from hexbot.host.events import Observed
from hexbot.host.host import IR, Host
from hexbot.host.link import LinkState
from hexbot.protocol import frames, timing, wire
from hexbot.protocol.codes import CODES, ErrorCode, lookup
from hexbot.protocol.frames import Command
from hexbot.protocol.mavlink_codec import MAX_FRAME_LEN, Framing, MavStatus
from hexbot.protocol.parser import Ack, ErrorReply, Garbage, StatusReport, Text

#: ``ID=`` of a boot text's tail, as a regular expression (``wire.BOOT_ID_TAIL``)
_BOOT_ID = r"\b" + re.escape(wire.BOOT_ID_TAIL.strip())

SELECT = lookup("Select").code
STATUS = lookup("Status").code
#: Before the first Select nobody has an id on the air: one reply is awaited.
LEGACY = None
#: Listen this long after a broadcast whose answers cannot be counted.
QUIET_S = 1.5
#: After the last reply, listen this long for replies nobody asked for.
SETTLE_S = 0.0


class OutcomeKind(enum.Enum):
    ACKNOWLEDGED = "acknowledged"
    REFUSED = "refused"
    TIMED_OUT = "timed out"
    GARBLED = "garbled"  # too few replies, and bytes no module can have sent (a collision)
    PORT_LOST = "port lost"
    CANCELLED = "cancelled"


class RefusalCause(enum.Enum):
    ERROR = "error reply"  # ERR code reason
    UNUSED_CODE = "unused code"  # ACK 'N': the module knows no such function
    CONTROL_TIMEOUT = "control board time-out"  # ACK '~'


@dataclass(frozen=True)
class Refusal:
    module: int | None
    cause: RefusalCause
    error: ErrorCode | None = None

    def describe(self) -> str:
        who = f"module {self.module}" if self.module is not None else "a module"
        if self.cause is RefusalCause.ERROR:
            name = self.error.name if self.error is not None else "?"
            return f"{who}: ERR {name}"
        return f"{who}: {self.cause.value}"


@dataclass(frozen=True)
class Outcome:
    command: Command | bytes  # bytes: a raw frame, sent as it is (bad input on purpose)
    kind: OutcomeKind
    replies: tuple[Observed, ...] = ()
    extra: tuple[Observed, ...] = ()  # replies nobody asked for (heard while settling)
    missing: tuple[int, ...] = ()  # modules that did not answer in time
    refusals: tuple[Refusal, ...] = ()
    waited: float = 0.0  # session seconds from sending to the verdict
    detail: str = ""  # port lost: why
    garbage: tuple[Observed, ...] = ()  # undecodable or unattributable, heard while waiting

    @property
    def ok(self) -> bool:
        return self.kind is OutcomeKind.ACKNOWLEDGED

    @property
    def reason(self) -> str:
        """One line: what happened."""
        if isinstance(self.command, bytes):
            head = f"frame {self.command!r}"
        else:
            name = CODES[self.command.code].name if self.command.code in CODES else "?"
            head = f"{name} ({self.command.code})"
        n = len(self.replies)
        if self.kind is OutcomeKind.ACKNOWLEDGED:
            return f"{head}: {n} repl{'y' if n == 1 else 'ies'}, acknowledged"
        if self.kind is OutcomeKind.REFUSED:
            return f"{head}: refused: " + "; ".join(r.describe() for r in self.refusals)
        if self.kind is OutcomeKind.TIMED_OUT:
            who = (f"no reply from module{'s' if len(self.missing) > 1 else ''} "
                   f"{', '.join(map(str, self.missing))}" if self.missing else "no reply")
            why = f"; {self.detail}" if self.detail else ""
            return f"{head}: {who} within {self.waited:.1f} s ({n} received){why}"
        if self.kind is OutcomeKind.PORT_LOST:
            return f"{head}: port lost ({self.detail})" if self.detail else f"{head}: port lost"
        if self.kind is OutcomeKind.GARBLED:
            what = "; ".join(_garbled(g.event) for g in self.garbage)
            why = f"; {self.detail}" if self.detail else ""
            return f"{head}: garbled reply: {what} (replies collided?); {n} decoded{why}"
        return f"{head}: cancelled"

    def lines(self) -> list[str]:
        return [describe_event(r.event) for r in self.replies]

    def raise_for_status(self) -> Outcome:
        """The outcome if acknowledged; otherwise the matching error."""
        if self.kind is OutcomeKind.ACKNOWLEDGED:
            return self
        if self.kind is OutcomeKind.REFUSED:
            raise CommandRefusedError(self.reason)
        if self.kind is OutcomeKind.TIMED_OUT:
            raise HexBotTimeoutError(self.reason)
        if self.kind is OutcomeKind.PORT_LOST:
            raise LinkUnavailableError(self.reason)
        if self.kind is OutcomeKind.GARBLED:
            raise FrameError(self.reason)
        raise CancelledError(self.reason)


@dataclass
class Waiting:
    """What the session is waiting for right now (for progress displays)."""

    what: str
    need: int
    started: float  # session seconds
    timeout: float
    replied: int = 0


@dataclass
class _Owed:
    """A reply a module still owes to an earlier command whose wait ended
    without it (cancelled, timed out): when it comes, it is that command's,
    not the answer to whatever was sent next. ``module`` None: legacy mode
    (no id on the air)."""

    module: int | None
    code: int
    until: float  # session seconds: past this, nobody expects it any more

    def describe(self) -> str:
        who = f"module {self.module}" if self.module is not None else "a module"
        name = CODES[self.code].name if self.code in CODES else str(self.code)
        return f"{who} may still be running {name}, abandoned before"

    def pays(self, event: object) -> bool:
        if isinstance(event, Ack):
            code = event.code
        elif isinstance(event, ErrorReply):
            code = event.code
        elif isinstance(event, StatusReport):
            code = STATUS
        else:
            return False
        return code == self.code and self.module in (None, _module_of(event))


def _pay(owed: list[_Owed], event: object) -> bool:
    """Strike the oldest debt ``event`` pays off; True if it paid one."""
    for debt in owed:
        if debt.pays(event):
            owed.remove(debt)
            return True
    return False


@dataclass
class _Collector:
    """The replies to one command, as they arrive."""

    code: int | None  # None: a raw frame, any ACK/ERR/STA is its reply
    wanted: set[int] | None  # module ids still to answer; None = count only
    need: int
    port: str
    replies: list[Observed] = field(default_factory=list)
    extra: list[Observed] = field(default_factory=list)
    garbage: list[Observed] = field(default_factory=list)
    checked: int = 0
    mark: int = 0  # the journal's length when the command went out
    roll_call: bool = False  # every module's answer counts
    anonymous_ok: bool = False  # a module without id (ID=00 at boot) is on this port
    owed: list[_Owed] = field(default_factory=list)  # the session's, struck as paid

    def take(self, journal: list[Observed]) -> None:
        for obs in journal[self.checked:]:
            if obs.port == self.port and isinstance(obs.event, Garbage):
                self.garbage.append(obs)
            if obs.port == self.port and _pay(self.owed, obs.event):
                self.extra.append(obs)  # an earlier command's late reply
                continue
            if self._is_reply(obs) and _module_of(obs.event) == 0 and not self.anonymous_ok:
                self.garbage.append(obs)  # no module here has id 0: replies collided
                continue
            if self.roll_call and self._is_reply(obs):
                self.replies.append(obs)
                if self.wanted is not None:
                    self.wanted.discard(_module_of(obs.event))  # type: ignore[arg-type]
            elif self._is_reply(obs):
                ident = _module_of(obs.event)
                if self.wanted is not None and ident not in self.wanted:
                    self.extra.append(obs)
                    continue
                if self.wanted is not None:
                    self.wanted.discard(ident)  # type: ignore[arg-type]
                if len(self.replies) < self.need:
                    self.replies.append(obs)
                else:
                    self.extra.append(obs)
        self.checked = len(journal)

    @property
    def complete(self) -> bool:
        if self.roll_call and self.wanted:
            return False  # a module we know of has not answered yet
        return len(self.replies) >= self.need

    def _is_reply(self, obs: Observed) -> bool:
        if obs.port != self.port:  # a control board's debug port echoes too
            return False
        ev = obs.event
        if self.code is None:
            return isinstance(ev, (Ack, ErrorReply, StatusReport))
        if isinstance(ev, Ack):
            return ev.code in (self.code, wire.UNUSED, wire.TIMEOUT)
        if isinstance(ev, ErrorReply):
            return ev.code == self.code
        return isinstance(ev, StatusReport) and self.code == STATUS


def _module_of(event: object) -> int | None:
    if isinstance(event, StatusReport):
        return event.module_id
    return getattr(event, "module", None)


def _garbled(event: object) -> str:
    if isinstance(event, StatusReport):
        return "STA from id 0, which no module here has"
    return f"{len(getattr(event, 'raw', b''))} bytes that decode as no reply"


def _refusal(obs: Observed) -> Refusal | None:
    ev = obs.event
    if isinstance(ev, ErrorReply):
        try:
            error = ErrorCode(ev.reason)
        except ValueError:
            error = None
        return Refusal(ev.module, RefusalCause.ERROR, error)
    if isinstance(ev, Ack) and ev.code == wire.UNUSED:
        return Refusal(ev.module, RefusalCause.UNUSED_CODE)
    if isinstance(ev, Ack) and ev.code == wire.TIMEOUT:
        return Refusal(ev.module, RefusalCause.CONTROL_TIMEOUT)
    return None


class Session:
    """Send and wait over a started :class:`~hexbot.host.host.Host`.

    ``modules`` are the cluster's ids when the caller knows them (a
    scenario, a previous run); the session also learns them from boot
    texts and replies.
    """

    def __init__(self, host: Host, modules: Iterable[int] = ()) -> None:
        self.host = host
        #: the cluster's ids for sure (given, or every expected boot text heard)
        self.cluster: frozenset[int] = frozenset(modules)
        #: ids seen in replies and boot texts: a hint, there may be more
        self.known: set[int] = set(modules)
        self._reference: int | None = None  # see the property
        #: after Select: the ids that answer, in rank order (ALL -> every known id)
        self.selection: tuple[int, ...] | None = LEGACY
        self.all_selected = False  # the last Select was Select(0): ranks are id - 1
        self.cancel = threading.Event()
        #: the exchange under way, read by progress displays (None: idle)
        self.waiting: Waiting | None = None
        #: replies still owed to commands whose wait ended without them
        self._owed: list[_Owed] = []
        self._owed_checked = 0  # journal events already matched against them
        self._boots_checked = 0  # journal events already searched for restarts
        #: journal seqs of boot texts reading ID=00 that came in a slot which
        #: several modules share: a collision, not a module without an id
        self._collided_boot_texts: set[int] = set()

    @property
    def reference(self) -> int | None:
        """The module the last localization took as origin (workflows.localize);
        None once its boot text says it restarted (it forgot its Ref), seen
        even before the next exchange looks at the restarts."""
        if self._reference is not None and self._reference in self._boot_ids(IR):
            self._reference = None
        return self._reference

    @reference.setter
    def reference(self, ident: int | None) -> None:
        self._reference = ident

    # --- time ----------------------------------------------------------------

    @property
    def clock(self):
        return self.host.clock

    def now(self) -> float:
        return self.host.clock.now()

    def sleep(self, seconds: float) -> None:
        """Let ``seconds`` pass (replies keep arriving); returns early on cancel."""
        self.host.clock.wait(self.cancel.is_set, seconds)

    def wait_for(self, predicate: Callable[[Observed], bool], since: int,
                 timeout: float) -> Observed | None:
        """The first journal event from ``since`` on that satisfies ``predicate``."""
        found: list[Observed] = []
        checked = since

        def ready() -> bool:
            nonlocal checked
            for obs in self.host.since(checked):
                checked = obs.seq + 1
                if predicate(obs):
                    found.append(obs)
                    return True
            return self.cancel.is_set() or self._lost(IR) is not None

        self.host.clock.wait(ready, timeout)
        return found[0] if found else None

    def collect(self, since: int, quiet: float = QUIET_S, timeout: float = 60.0) -> list[Observed]:
        """Events from ``since`` until none arrived for ``quiet`` seconds (or
        ``timeout`` passed): for answers whose number nobody can know."""
        end = self.now() + timeout
        seen = [self.host.mark()]

        def news() -> bool:
            return self.host.mark() != seen[0] or self.cancel.is_set()

        while self.now() < end and not self.cancel.is_set():
            if not self.host.clock.wait(news, min(quiet, end - self.now())):
                break  # quiet
            seen[0] = self.host.mark()
        return self.host.since(since)

    def wake(self) -> None:
        """Cancel the current wait (the console's Escape)."""
        self.cancel.set()
        self.host.clock.wake()

    # --- the cluster's ids -----------------------------------------------------

    def learn(self) -> set[int]:
        """Add the ids the replies so far revealed to ``known``."""
        for obs in self.host.since(0):
            ident = _module_of(obs.event) or listening_id(obs.event)
            if ident:
                self.known.add(ident)
        return self.known

    def wait_booted(self, expected: Collection[int] | None = None,
                    timeout: float | None = None, quiet: float = 2.0,
                    on_boot: Callable[[int], None] | None = None) -> set[int]:
        """Wait for a freshly started cluster's boot texts. With ``expected``
        ids, until each has said ``COMM. LISTENING ID=nn`` (the firmware
        staggers those texts in per-id slots, so silence alone can end too
        early when ids leave gaps); otherwise until ``quiet`` seconds pass
        without an event. Commands sent while modules boot are lost. Returns
        the ids heard (``on_boot`` is called with each as it is); raises
        LinkUnavailableError if the port is lost meanwhile.

        On an embedded simulator, whose clock counts from the modules'
        reset, a text counts only if no other expected module shares its
        slot and, when a collision can read as its id, only in its own
        slot (a text read late is no collision otherwise): modules whose
        ids are 8 apart send
        at the same time, and their bytes AND on the IR link into one
        well-formed text with a wrong id (1, 9, 17 and 25 read ``ID=01``; 2,
        10, 18 and 26 ``ID=00``; 6 and 14 ``ID=04``), which names a module
        whose own text was lost, or none. Such modules are left out of the
        result (ask them: :meth:`confirm_booted`), and the wait for a slot
        ends with the slot (stretched by the clock tolerance), not at the
        time-out.

        On hardware and ptys, whose clock does not start at the modules'
        reset, a text is judged by its id alone: one that a collision of
        the texts of ids sharing a slot could read as (:func:`collision_ids`)
        is left out of the result too, so that :meth:`boot` asks that module,
        but it ends the wait for that id."""
        heard: set[int] = set()
        if not expected:
            self.collect(0, quiet, timeout or 60.0)
        else:
            missing = set(expected)
            checked = 0
            sim = self.host.simulator
            reads = _collision_reads(expected)  # what collided texts read as
            suspects = reads - {0}
            slots = _BootSlots(expected, suspects) if sim is not None else None
            t0 = sim.now() - self.now() if sim is not None else 0.0  # since reset, at 0

            def ready() -> bool:
                nonlocal checked
                for obs in self.host.since(checked):
                    checked = obs.seq + 1
                    ident = listening_id(obs.event)
                    if _without_id(obs.event) and 0 in reads:
                        # texts of a shared slot can read ID=00 (2 and 10): this
                        # one says nothing of a comm board without an id
                        self._collided_boot_texts.add(obs.seq)
                    if slots is not None:
                        slots.learn_version(obs.event)
                        if obs.port != IR or not slots.own(ident, t0 + obs.t,
                                                           _fw_version(obs.event)):
                            continue
                    elif ident in suspects:  # ends the wait, but boot() asks it
                        missing.discard(ident)
                        continue
                    if ident is not None and ident not in heard:
                        heard.add(ident)
                        missing.discard(ident)
                        if on_boot is not None and ident in expected:
                            on_boot(ident)
                if not missing or self.cancel.is_set() or self._lost(IR) is not None:
                    return True
                return slots is not None and slots.over(missing, sim.now())

            limit = timeout if timeout is not None else timing.boot_seconds(expected) + 5.0
            self.host.clock.wait(ready, limit)
            lost = self._lost(IR)
            if lost is not None and not self.cancel.is_set():
                raise LinkUnavailableError(f"{IR} port lost while the modules booted ({lost})")
        self.known |= heard
        if expected and heard >= set(expected):
            self.cluster = frozenset(expected)
        return heard

    def boot(self, ids: Collection[int], on_boot: Callable[[int], None] | None = None,
             ask: bool = True) -> tuple[set[int], set[int]]:
        """A freshly started cluster's boot: :meth:`wait_booted` for ``ids``,
        then, with ``ask``, :meth:`confirm_booted` for those whose texts were
        not heard whole (ids 8 apart share a boot slot, and their texts
        collide into one with a wrong id). Returns (ids heard by boot text,
        ids that answered a Status)."""
        heard = self.wait_booted(ids, on_boot=on_boot)
        rest = sorted(set(ids) - heard)
        answered: set[int] = set()
        if ask and rest and not self.cancel.is_set():
            answered = self.confirm_booted(rest, on_boot=on_boot)
        if ids and heard | answered >= set(ids):
            self.cluster = frozenset(ids)
        return heard, answered

    def confirm_booted(self, ids: Iterable[int],
                       on_boot: Callable[[int], None] | None = None) -> set[int]:
        """Ask each of ``ids`` for its Status, after the boot, when its boot
        text was not heard whole (:meth:`wait_booted`); returns those that
        answered (``on_boot`` is called with each). The request is a MAVLink
        frame whose ``target_system`` is the module: it alone answers, at
        once, and no module's ``Select`` state changes (a legacy Status
        would need a Select, which ends every module's legacy mode); the
        session's framing is left as it was. A module whose answer came
        garbled is asked once more. If no boot text came at all,
        whole or collided, one Status that is not answered ends it (a link
        that carries nothing: the first tells whether anybody is there).
        Raises LinkUnavailableError if the port is lost meanwhile."""
        answered: set[int] = set()
        ids = list(ids)
        if not ids:
            return answered
        phrase = wire.TEXT_COMM_LISTENING.rstrip()
        spoke = any(obs.port == IR and isinstance(obs.event, Text) and obs.event.phrase == phrase
                    for obs in self.host.since(0))
        earlier = {id(d) for d in self._owed}
        framing = self.host.framing
        if framing is not Framing.MAVLINK:
            self.host.set_framing(Framing.MAVLINK)
        try:
            for ident in ids:
                if self.cancel.is_set():
                    break
                out = self.exchange(frames.make("Status"), target=ident)
                if out.kind is OutcomeKind.GARBLED and not self.cancel.is_set():
                    out = self.exchange(frames.make("Status"), target=ident)  # once more
                if out.kind is OutcomeKind.PORT_LOST:
                    raise LinkUnavailableError(
                        f"{IR} port lost while asking the modules whether they booted "
                        f"({out.detail})")
                if any(_module_of(r.event) == ident for r in out.replies):
                    answered.add(ident)
                    if on_boot is not None:
                        on_boot(ident)
                elif not spoke and not answered:
                    break
        finally:
            if framing is not Framing.MAVLINK:
                self.host.set_framing(framing)
            # a module that did not answer is taken for one that did not
            # boot, not for one still busy with the Status
            self._owed[:] = [d for d in self._owed if id(d) in earlier]
        self.known |= answered
        return answered

    # --- send and wait -----------------------------------------------------------

    def expected_replies(self, command: Command) -> tuple[int, ...] | None:
        """The ids that answer ``command`` (rank order); None: legacy mode, one reply."""
        if command.code == SELECT:
            ids = [a for a in command.args if a != wire.UNUSED]
            if ids[:1] == [0]:
                return tuple(sorted(self.cluster)) if self.cluster else None
            return tuple(ids)
        return self.selection

    def exchange(self, command: Command | bytes, *, modules: Iterable[int] | None = None,
                 count: int | None = None, timeout: float | None = None,
                 settle: float = SETTLE_S, strict: bool = True, port: str = IR,
                 target: int = 0) -> Outcome:
        """Send ``command`` and wait for the replies its addressing implies
        (or one from each of ``modules``, or ``count`` of any module).
        ``command`` may be raw bytes (a corrupted frame on purpose): then any
        ACK, ERR or STA is its reply and ``timeout`` must be given. With
        ``settle``, listen that much longer for replies nobody asked for.
        ``target`` (MAVLink framing): the one module that runs and answers
        the command, whatever the last Select said."""
        if self.host.framing is Framing.AUTO and port == IR:
            self.settle_framing()
        if target and not isinstance(command, bytes) and self.host.framing is Framing.MAVLINK:
            modules = (target,) if modules is None else modules
        if isinstance(command, bytes):
            if timeout is None:
                raise ValueError("a raw frame has no protocol time-out: give timeout=")
            code: int | None = None
            ids: tuple[int, ...] | None = tuple(modules) if modules is not None else None
            count = count if count is not None or ids is not None else 1
        elif modules is not None:
            ids: tuple[int, ...] | None = tuple(modules)
        elif count is not None:
            ids = None
        else:
            ids = self.expected_replies(command)
        if not isinstance(command, bytes):
            code = command.code
        need = len(ids) if ids is not None else (count or 1)
        if ids is not None and not ids:
            raise CommandRefusedError(f"{command}: no module would answer")
        # Select(0) to a cluster of unknown ids: every answer counts; wait for
        # each id seen so far (its reply slot is id - 1: the bound is the
        # highest's), then until the link is quiet.
        roll_call = ids is None and count is None and code == SELECT
        seen: tuple[int, ...] = ()
        if roll_call:
            seen = tuple(sorted(self.learn()))
            need = max(1, len(seen))
        if timeout is None:
            timeout = self.reply_timeout(command, seen or ids, need)
        # Legacy mode (no Select yet): every module runs the command and
        # answers without an id, a substrate 1 s later, one without its
        # control board with '~' after 2.5 s. Unless the cluster is known to
        # be one module, listen for the whole bound and judge every answer.
        legacy_all = (ids is None and count is None and not roll_call and code is not None
                      and len(self.cluster) != 1)
        restarted = self._restarted(port)
        if self.reference in restarted:  # it forgot its Ref: no origin any more
            self.reference = None
        if restarted and code not in (None, SELECT) and self.selection is not LEGACY:
            # a module that restarted forgot the Select: it would run (and
            # answer) everything; say the selection again first
            ids_again = (0,) if self.all_selected else self.selection
            self.host.warn(self.now(), f"module(s) {', '.join(map(str, restarted))} "
                           f"restarted: Select({', '.join(map(str, ids_again))}) again")
            again = self.exchange(select(*ids_again), port=port)
            if not again.ok:
                return again
        self.cancel.clear()
        started = self.now()
        self._settle_debts(port, started)
        try:
            mark = self.host.send(command, port, strict=strict, target=target)
        except LinkUnavailableError as exc:
            return Outcome(command, OutcomeKind.PORT_LOST, detail=str(exc))
        wanted = set(ids) if ids is not None else set(seen) if roll_call else None
        got = _Collector(code, wanted, need, port,
                         checked=mark, mark=mark, roll_call=roll_call,
                         anonymous_ok=self._anonymous(port), owed=self._owed)
        waiting = self.waiting = Waiting(
            str(command) if isinstance(command, Command) else f"frame {command.hex(' ')}",
            need, started, timeout)

        def ready() -> bool:
            with self.host.lock:
                got.take(self.host.since(0))
            waiting.replied = len(got.replies)
            return ((got.complete and not legacy_all) or self.cancel.is_set()
                    or self._lost(port) is not None)

        try:
            self.host.clock.wait(ready, timeout)
        finally:
            self.waiting = None
        if roll_call and got.replies:
            self.collect(mark, max(QUIET_S, 2 * timing.ACK_SLOT_S), timeout)
            with self.host.lock:
                got.take(self.host.since(0))
            got.need = len(got.replies)
            # whoever answered is the selection; an id heard once (a boot
            # text two modules garbled into a third id) does not fail it
            got.wanted = set()
            ids = tuple(sorted({i for r in got.replies if (i := _module_of(r.event))}))
            self.known |= set(ids)
        if legacy_all and got.complete:
            got.replies += [o for o in got.extra if got._is_reply(o)]
            got.extra = [o for o in got.extra if not got._is_reply(o)]
            got.need = len(got.replies)
        if got.complete and settle > 0 and not self.cancel.is_set():
            self.host.clock.wait(lambda: self.cancel.is_set() or self._lost(port) is not None,
                                 settle)
            with self.host.lock:
                got.take(self.host.since(0))
        self._owed_checked = got.checked
        outcome = self._judge(command, got, ids, started, port)
        if (code is not None and port == IR
                and outcome.kind in (OutcomeKind.CANCELLED, OutcomeKind.TIMED_OUT)):
            # its replies may still come: twice its time-out from the send
            owers = outcome.missing or ((None,) if not outcome.replies else ())
            until = started + 2 * timeout
            self._owed += [_Owed(m, code, until) for m in owers]
        if (isinstance(command, Command) and command.code == SELECT and not target
                and ids is not None and outcome.kind is not OutcomeKind.PORT_LOST):
            # the modules that heard it switched, answered or not: a module
            # of the list that did not answer is missed by what follows
            self.selection = ids
            self.all_selected = command.args[0] == 0
        return outcome

    def _restarted(self, port: str) -> list[int]:
        """Modules whose boot text (``COMM. LISTENING ID=nn``) came since
        the last look: they restarted and forgot any Select and role."""
        with self.host.lock:
            journal = self.host.since(self._boots_checked)
        if journal:
            self._boots_checked = journal[-1].seq + 1
        return _listening_ids(journal, port)

    def _boot_ids(self, port: str) -> list[int]:
        """The ids of the boot texts since the last look, without looking."""
        with self.host.lock:
            return _listening_ids(self.host.since(self._boots_checked), port)

    def _settle_debts(self, port: str, now: float) -> None:
        """Forget debts past their time; strike those that replies heard
        since the last exchange paid."""
        self._owed[:] = [d for d in self._owed if d.until > now]
        with self.host.lock:
            journal = self.host.since(self._owed_checked)
        for obs in journal:
            if obs.port == port:
                _pay(self._owed, obs.event)
            self._owed_checked = obs.seq + 1

    def settle_framing(self) -> Framing:
        """``--framing auto``: a MAVLink Status request to one known module
        (or to all); MAVLink if a HEXBOT_STATUS answers, legacy otherwise."""
        self.host.set_framing(Framing.MAVLINK)
        ids = sorted(self.cluster or self.known)
        probe = frames.make("Status")
        if ids:
            out = self.exchange(probe, target=ids[0])
        else:
            out = self.exchange(probe, count=1)
        spoke = out.ok and any(isinstance(r.event, MavStatus) for r in out.replies)
        if not spoke:
            self.host.set_framing(Framing.LEGACY)
        return self.host.framing

    def request(self, command: Command, **kwargs) -> Outcome:
        """:meth:`exchange`, raising the outcome's error unless acknowledged."""
        return self.exchange(command, **kwargs).raise_for_status()

    def send(self, command: Command | bytes, *, strict: bool = True, port: str = IR) -> int:
        """Send without waiting (the composer's Send, a script's ``post``);
        returns the journal mark taken just before. A Select sent this way
        still changes who answers what follows."""
        mark = self.host.send(command, port, strict=strict)
        if isinstance(command, Command) and command.code == SELECT and port == IR:
            ids = self.expected_replies(command)
            self.selection = ids if ids is not None else tuple(sorted(self.learn()))
            self.all_selected = command.args[0] == 0
        return mark

    def reply_timeout(self, command: Command, ids: tuple[int, ...] | None, need: int) -> float:
        """Transmission of the frame plus the protocol's bound for its replies
        (MAVLink replies are never longer than the legacy ones they replace:
        they fit the same slots)."""
        length = MAX_FRAME_LEN if self.host.framing is Framing.MAVLINK else wire.PC_FRAME_LEN
        frame = timing.wire_seconds(length, timing.BAUD_IR)
        code = command.code if command.code in CODES else STATUS
        select_all = command.code == SELECT and list(command.args[:1]) == [0]
        if ids and (select_all or (command.code != SELECT and self.all_selected)):
            # Select(0) and what follows it: a module's rank is its id - 1
            last_rank = max(ids) - 1
        else:
            last_rank = None
        return frame + timing.reply_timeout_s(code, max(need, 1), command.args,
                                              last_rank=last_rank)

    def _anonymous(self, port: str) -> bool:
        """Whether a module without an id answers on ``port``: a comm board
        that got no id from its control board says ``COMM. LISTENING ID=00``
        at boot and then sends ``STA`` with id 0. Otherwise a STA with id 0 is
        two replies that collided (their bytes AND on the IR link)."""
        return any(obs.port == port and _without_id(obs.event)
                   and obs.seq not in self._collided_boot_texts
                   for obs in self.host.since(0))

    def port_lost(self, port: str = IR) -> str | None:
        """Why ``port`` is lost or closed; None while it is connected."""
        return self._lost(port)

    def _lost(self, port: str) -> str | None:
        ch = self.host.channels.get(port)
        if ch is None:
            return f"no {port} port"
        if ch.link.state in (LinkState.LOST, LinkState.CLOSED):
            return ch.link.detail or ch.link.state.value
        return None

    def _judge(self, command: Command | bytes, got: _Collector, ids: tuple[int, ...] | None,
               started: float, port: str) -> Outcome:
        waited = self.now() - started
        replies, extra = tuple(got.replies), tuple(got.extra)
        refusals = tuple(r for obs in replies if (r := _refusal(obs)) is not None)
        if refusals:
            return Outcome(command, OutcomeKind.REFUSED, replies, extra, refusals=refusals,
                           waited=waited)
        if got.complete:
            return Outcome(command, OutcomeKind.ACKNOWLEDGED, replies, extra, waited=waited)
        missing = tuple(sorted(got.wanted)) if got.wanted else ()
        if self.cancel.is_set():
            return Outcome(command, OutcomeKind.CANCELLED, replies, extra, missing, waited=waited)
        lost = self._lost(port)
        if lost is not None:
            return Outcome(command, OutcomeKind.PORT_LOST, replies, extra, missing,
                           waited=waited, detail=lost)
        booting = self._booting(got.mark, port)
        if got.garbage:
            return Outcome(command, OutcomeKind.GARBLED, replies, extra, missing,
                           waited=waited, garbage=tuple(got.garbage), detail=booting)
        busy = sorted({d.describe() for d in self._owed
                       if d.module is None or d.module in missing})
        return Outcome(command, OutcomeKind.TIMED_OUT, replies, extra, missing, waited=waited,
                       detail="; ".join(busy + ([booting] if booting else [])))

    def _booting(self, mark: int, port: str) -> str:
        """Why a command got no clean answer when modules were booting while
        it waited (a boot text, or the tail of one cut by the command's own
        frame): "" if none was. A command sent during a boot is lost."""
        with self.host.lock:
            heard = [o for o in self.host.since(mark) if o.port == port]
        for obs in heard:
            ev = obs.event
            if isinstance(ev, Text) and ev.phrase in wire.BOOT_TEXTS:
                what = f"'{ev.phrase}' at {obs.t:.1f} s"
            elif isinstance(ev, Garbage) and wire.BOOT_FW_TAIL.strip().encode() in ev.raw:
                what = f"a boot text's tail at {obs.t:.1f} s"
            else:
                continue
            return (f"modules were booting (heard {what}): a command sent during a boot "
                    f"is lost; send it again after '{wire.TEXT_COMM_LISTENING}'")
        return ""


#: A version string as long as the boot slots allow (timing.BOOT_GUARD_TICKS):
#: the slots' ends while no text has named the firmware's version yet.
_LONGEST_VERSION = "v" * 16


def _fw_version(event: object) -> str | None:
    """The firmware version in a boot text's tail (``FW=0.1.0``), if any."""
    if isinstance(event, Text):
        m = re.search(re.escape(wire.BOOT_FW_TAIL.strip()) + r"(\S+)", event.tail)
        if m:
            return m.group(1)
    return None


class _BootSlots:
    """Where the boot texts of a simulated cluster's ``ids`` fall in time
    (seconds from reset): a module's id-bearing texts end in its slot,
    ``timing.boot_rank``, on a clock within ``timing.CLOCK_TOLERANCE``."""

    def __init__(self, ids: Iterable[int], suspects: set[int]) -> None:
        self.ranks: dict[int, set[int]] = {}
        for ident in ids:
            self.ranks.setdefault(timing.boot_rank(ident), set()).add(ident)
        self.suspects = suspects  # the ids a collision may read as (collision_ids)
        self.version: str | None = None  # the firmware's, from the first text naming it

    def learn_version(self, event: object) -> None:
        if self.version is None:
            self.version = _fw_version(event)

    def own(self, ident: int | None, t: float, version: str | None) -> bool:
        """Whether a ``COMM. LISTENING ID=ident`` text that ended at ``t`` is
        that module's own: no other module shares its slot (their texts
        would have collided into this one), and, if a collision of another
        slot's texts can read as this id, it came in this id's slot."""
        if ident is None or self.ranks.get(timing.boot_rank(ident)) != {ident}:
            return False
        if ident not in self.suspects:
            # no collision reads as this id: when the text came does not
            # matter (a reader that ran late stamps it late)
            return True
        return self._in_slot(timing.boot_rank(ident), ident, t, version)

    def _in_slot(self, rank: int, ident: int, t: float, version: str | None) -> bool:
        version = version or self.version or wire.FW_VERSION
        slot = timing.boot_slot_ticks(version)
        text = (timing.BOOT_TEXT_FIXED_BYTES + len(version)
                - 2 * (wire.ID_MAX_DIGITS - len(f"{ident:02d}")))
        end = timing.BOOT_FIRST_SLOT_TICKS + rank * slot + timing.ir_ticks(text)
        return abs(t / timing.TICK_S - end) < slot / 2

    def over(self, ids: Iterable[int], now: float) -> bool:
        """Whether the slots of ``ids`` are over at ``now``: every module of
        theirs has sent its texts, if it booted at all."""
        slot = timing.boot_slot_ticks(self.version or _LONGEST_VERSION)
        last = max(timing.boot_rank(i) for i in ids)
        end = (timing.BOOT_FIRST_SLOT_TICKS + (last + 1) * slot) * timing.TICK_S
        return now >= end * (1 + timing.CLOCK_TOLERANCE)


def collision_ids(ids: Iterable[int]) -> set[int]:
    """The ids that the boot texts of ``ids`` can read as when the texts of
    modules sharing a boot slot (ids 8 apart) go out together: their bytes
    AND on the IR link, digit by digit (6 and 14 read ``04``)."""
    return _collision_reads(ids) - {0}


def _collision_reads(ids: Iterable[int]) -> set[int]:
    """:func:`collision_ids`, and 0 when some collision reads ``ID=00``
    (2 and 10), which is no id."""
    ranks: dict[int, list[int]] = {}
    for ident in ids:
        ranks.setdefault(timing.boot_rank(ident), []).append(ident)
    found: set[int] = set()
    for group in ranks.values():
        texts = [f"{i:0{wire.ID_MAX_DIGITS}d}".encode() for i in sorted(group)]
        for size in range(2, len(texts) + 1):
            for chosen in itertools.combinations(texts, size):
                digits = bytes(functools.reduce(lambda a, b: a & b, column)
                               for column in zip(*chosen, strict=True))
                found.add(int(digits))
    return found


def _without_id(event: object) -> bool:
    """Whether ``event`` is a ``COMM. LISTENING ID=00`` boot text."""
    return (isinstance(event, Text) and event.phrase == wire.TEXT_COMM_LISTENING.rstrip()
            and re.search(_BOOT_ID + r"0+\b", event.tail) is not None)


def _listening_ids(journal: list[Observed], port: str) -> list[int]:
    return [i for obs in journal if obs.port == port
            and (i := listening_id(obs.event)) is not None]


def listening_id(event: object) -> int | None:
    """The module id of a ``COMM. LISTENING ID=nn ...`` boot text."""
    if isinstance(event, Text) and event.phrase == wire.TEXT_COMM_LISTENING.rstrip():
        m = re.search(_BOOT_ID + r"(\d+)", event.tail)
        if m and int(m.group(1)):
            return int(m.group(1))
    return None


def select(*ids: int) -> Command:
    return frames.select(list(ids))
