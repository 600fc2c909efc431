"""Streaming parser for what modules send to the PC.

Bytes arrive one at a time, possibly with noise, from several modules
interleaved on the IR link or from one control board's debug port. The
parser turns them into typed events and never raises on bad input: bytes
that form nothing become a :class:`Garbage` event, emitted before the next
valid event so that garbage never swallows it.

Reply grammar (``\\n\\r`` = LF CR, as the firmware ends its lines)::

    preamble   LF CR LF CR                        (sync only, no event)
    prefix     ('M'|'S') [id] ': '                (applies to the next reply; id
                                                  two digits, three from 100)
    ack        'ACK' code LF CR                   code 'N' = did nothing,
                                                  '~' = control board time-out
    error      'ERR' code reason LF CR
    status     'STA' id role localized x y yref error [schema] LF CR
               (x, y signed bytes; schema: 8 hex digits, absent before it existed)
    msg        'MSG' code a1 a2 a3 a4 LF CR       (control board debug port)
    side       'Side: ' digit LF CR               (localization report)
    yref       'Yref: ' digit LF CR
    position   'Pos: ' sXX sYY LF CR
    text       known phrase [tail] LF CR          (boot and status texts)

Like pyserial's ``serial.threaded.Protocol`` the parser does no I/O: feed
it bytes from any reader (pty, pyserial URL, capture file, simulator).
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Iterator
from dataclasses import dataclass, field

from hexbot.protocol import wire
from hexbot.protocol.codes import CODES, ErrorCode, Role

EOL = wire.EOL

#: Phrases that start a text line; the firmware may append a short tail
#: such as `` ID=03 FW=0.1.0`` (`` ID=200`` from id 100 on).
KNOWN_TEXTS = (
    wire.TEXT_COMM_READY,
    wire.TEXT_CTR_READY,
    wire.TEXT_CTR_LISTENING,
    wire.TEXT_COMM_LISTENING,
    wire.TEXT_LOCALIZED,
    wire.TEXT_RF12_READY,
)
_TAIL_CHARS = re.compile(rb"[ A-Za-z0-9=._:+\-/]*")
_MAX_TAIL = 40


@dataclass(frozen=True)
class Event:
    raw: bytes = field(repr=False, compare=False)


@dataclass(frozen=True)
class Ack(Event):
    code: int = 0
    role: str | None = None  # 'M', 'S' or None without a prefix
    module: int | None = None  # id from an addressed-mode prefix

    @property
    def did_nothing(self) -> bool:
        return self.code == wire.UNUSED

    @property
    def timed_out(self) -> bool:
        return self.code == wire.TIMEOUT

    def describe(self) -> str:
        if self.timed_out:
            return "ACK ~ (control board time-out)"
        if self.did_nothing:
            return "ACK N (nothing done)"
        fn = CODES.get(self.code)
        return f"ACK {self.code} {fn.name if fn else '?'}"


@dataclass(frozen=True)
class ErrorReply(Event):
    code: int = 0
    reason: int = 0
    role: str | None = None
    module: int | None = None

    def describe(self) -> str:
        try:
            why = ErrorCode(self.reason).name
        except ValueError:
            why = f"reason {self.reason}"
        return f"ERR {self.code}: {why}"


@dataclass(frozen=True)
class StatusReport(Event):
    module_id: int = 0
    role: str = "-"
    localized: bool = False
    x: int = 0
    y: int = 0
    yref: int = 0
    error: int = 0
    prefix_role: str | None = None
    schema: int | None = None  # protocol schema hash; None from firmware that predates it


@dataclass(frozen=True)
class ControlMessage(Event):
    """``MSG`` on the control board's debug port: what it received."""

    code: int = 0
    args: tuple[int, ...] = ()


@dataclass(frozen=True)
class Text(Event):
    phrase: str = ""  # one of KNOWN_TEXTS
    tail: str = ""


@dataclass(frozen=True)
class SideReport(Event):
    side: int = 0


@dataclass(frozen=True)
class YrefReport(Event):
    yref: int = 0


@dataclass(frozen=True)
class PositionReport(Event):
    x: int = 0
    y: int = 0


@dataclass(frozen=True)
class Garbage(Event):
    """Bytes that formed no reply (noise, collisions, truncated replies)."""


# --- matchers: each returns (length, event) on a match, PARTIAL if the
# buffer is a proper prefix of a possible match, or None. -----------------

PARTIAL = "partial"
_STATUS_FIELDS = 7  # id, role, localized, x, y, yref, last error
_SCHEMA_DIGITS = 8
_HEX = re.compile(rb"[0-9a-f]{8}")
_ID = rb"\d{%d,%d}" % (wire.ID_MIN_DIGITS, wire.ID_MAX_DIGITS)
#: A reply's prefix: the replying module's role letter (mobile or substrate)
#: and, once addressed, its id.
_PREFIX_ROLES = b"[" + (Role.MOBILE.letter + Role.SUBSTRATE.letter).encode() + b"]"
_PREFIX = re.compile(b"(" + _PREFIX_ROLES + b")(" + _ID + rb")?: ")
_PREFIX_PARTIAL = re.compile(_PREFIX_ROLES + rb"(\d{0,%d}|" % wire.ID_MAX_DIGITS + _ID + rb":|:)")
#: The role byte of a status reply: any role's letter.
_ROLE_LETTERS = frozenset(role.letter for role in Role)


def _fixed(buf: bytes, head: bytes, nbody: int) -> bytes | str | None:
    """Match head + nbody arbitrary bytes + EOL; return the body bytes."""
    n = min(len(buf), len(head))
    if buf[:n] != head[:n]:
        return None
    eol_at = len(head) + nbody
    got = buf[eol_at : eol_at + len(EOL)]
    if got != EOL[: len(got)]:
        return None
    if len(buf) < eol_at + len(EOL):
        return PARTIAL
    body = buf[len(head) : eol_at]
    # No valid reply body holds a whole preamble: one inside means the "head"
    # was noise and a real reply starts there, which must not be swallowed.
    if wire.PREAMBLE in body:
        return None
    return body


def _signed(b: int) -> int:
    return b - 256 if b > 127 else b


class ReplyParser:
    """Feed bytes, get events. ``flush()`` gives up on a half reply (call it
    when the line has been quiet, e.g. one second)."""

    def __init__(self) -> None:
        self._buf = bytearray()
        self._garbage = bytearray()
        self._role: str | None = None
        self._module: int | None = None

    def feed(self, data: bytes | Iterable[int]) -> list[Event]:
        self._buf.extend(data)
        return list(self._drain(final=False))

    def flush(self) -> list[Event]:
        """Emit whatever is pending (a half reply becomes garbage)."""
        events = list(self._drain(final=True))
        if self._buf:
            self._garbage.extend(self._buf)
            self._buf.clear()
        if self._garbage:
            events.append(self._take_garbage())
        return events

    @property
    def pending(self) -> bytes:
        return bytes(self._buf)

    def _take_garbage(self) -> Garbage:
        g = Garbage(raw=bytes(self._garbage))
        self._garbage.clear()
        return g

    def _drain(self, final: bool) -> Iterator[Event]:
        while self._buf:
            result = self._match(bytes(self._buf))
            if result == PARTIAL:
                if not final:
                    return
                result = None
            if result is None:
                self._garbage.append(self._buf.pop(0))
                continue
            length, event = result
            del self._buf[:length]
            if self._garbage:
                yield self._take_garbage()
            if event is not None:
                yield event

    def _match(self, buf: bytes):  # noqa: C901 - one branch per reply kind, kept flat
        partial = False
        for matcher in (
            self._m_preamble,
            self._m_prefix,
            self._m_ack,
            self._m_err,
            self._m_status,
            self._m_msg,
            self._m_report,
            self._m_text,
            self._m_blank,
        ):
            r = matcher(buf)
            if r == PARTIAL:
                partial = True
            elif r is not None:
                return r
        return PARTIAL if partial else None

    # Each matcher below recognises one reply kind.

    def _m_preamble(self, buf: bytes):
        if buf.startswith(wire.PREAMBLE):
            self._role = self._module = None
            return len(wire.PREAMBLE), None
        return PARTIAL if wire.PREAMBLE.startswith(buf) else None

    def _m_blank(self, buf: bytes):
        # Stray LF / CR between replies are line noise of the text protocol.
        if buf[:1] in (b"\n", b"\r") and not wire.PREAMBLE.startswith(buf):
            return 1, None
        return None

    def _m_prefix(self, buf: bytes):
        m = _PREFIX.match(buf)
        if m:
            self._role = m.group(1).decode()
            self._module = int(m.group(2)) if m.group(2) else None
            return m.end(), None
        # Partial: "M", "M:", "M0", "M03", "M03:", "M200:"
        if _PREFIX_PARTIAL.fullmatch(buf):
            return PARTIAL
        return None

    def _m_ack(self, buf: bytes):
        body = _fixed(buf, wire.REPLY_ACK, 1)
        if body is None or body == PARTIAL:
            return body
        ev = Ack(raw=buf[:6], code=body[0], role=self._role, module=self._module)
        self._role = self._module = None  # a prefix belongs to one reply only
        return 6, ev

    def _m_err(self, buf: bytes):
        body = _fixed(buf, wire.REPLY_ERR, 2)
        if body is None or body == PARTIAL:
            return body
        ev = ErrorReply(raw=buf[:7], code=body[0], reason=body[1], role=self._role,
                        module=self._module)
        self._role = self._module = None
        return 7, ev

    def _m_status(self, buf: bytes):
        # Seven fields, then either LF CR (firmware before the schema) or the
        # schema's hex digits and LF CR: a hex digit is never LF, so the byte
        # after the fields tells the two apart.
        fields = len(wire.REPLY_STATUS) + _STATUS_FIELDS
        if len(buf) > fields and buf[fields] != EOL[0]:
            body = _fixed(buf, wire.REPLY_STATUS, _STATUS_FIELDS + _SCHEMA_DIGITS)
            if body is None or body == PARTIAL:
                return body
            digits = bytes(body[_STATUS_FIELDS:])
            if not _HEX.fullmatch(digits):
                return None
            schema: int | None = int(digits, 16)
        else:
            body = _fixed(buf, wire.REPLY_STATUS, _STATUS_FIELDS)
            if body is None or body == PARTIAL:
                return body
            schema = None
        ident, role, loc, x, y, yref, err = body[:_STATUS_FIELDS]
        if chr(role) not in _ROLE_LETTERS or loc > 1 or yref > 5:  # the id byte takes any value
            return None
        end = len(wire.REPLY_STATUS) + len(body) + len(EOL)
        ev = StatusReport(raw=buf[:end], module_id=ident, role=chr(role), localized=bool(loc),
                          x=_signed(x), y=_signed(y), yref=yref, error=err,
                          prefix_role=self._role, schema=schema)
        self._role = self._module = None
        return end, ev

    def _m_msg(self, buf: bytes):
        body = _fixed(buf, wire.REPLY_MSG, 5)
        if body is None or body == PARTIAL:
            return body
        return 10, ControlMessage(raw=buf[:10], code=body[0], args=tuple(body[1:]))

    _REPORTS = (
        (re.compile(re.escape(wire.LOC_SIDE) + rb"([1-6])" + re.escape(EOL)),
         wire.LOC_SIDE + b"6" + EOL,
         lambda m, raw: SideReport(raw=raw, side=int(m.group(1)))),
        (re.compile(re.escape(wire.LOC_YREF) + rb"([0-5])" + re.escape(EOL)),
         wire.LOC_YREF + b"5" + EOL,
         lambda m, raw: YrefReport(raw=raw, yref=int(m.group(1)))),
        (re.compile(re.escape(wire.LOC_POS) + rb"([+-]\d\d)([+-]\d\d)" + re.escape(EOL)),
         wire.LOC_POS + b"+00+00" + EOL,
         lambda m, raw: PositionReport(raw=raw, x=int(m.group(1)), y=int(m.group(2)))),
    )

    def _m_report(self, buf: bytes):
        partial = False
        for pattern, template, build in self._REPORTS:
            m = pattern.match(buf)
            if m:
                return m.end(), build(m, buf[: m.end()])
            head = template.split(b" ")[0]
            n = min(len(buf), len(head))
            if buf[:n] == head[:n] and len(buf) < len(template) and pattern.match(
                buf + template[len(buf) :]
            ):
                partial = True
        return PARTIAL if partial else None

    def _m_text(self, buf: bytes):
        partial = False
        for phrase in KNOWN_TEXTS:
            p = phrase.encode()
            if len(buf) < len(p):
                if p.startswith(buf):
                    partial = True
                continue
            if not buf.startswith(p):
                continue
            rest = buf[len(p) :]
            tail = _TAIL_CHARS.match(rest[:_MAX_TAIL]).group(0)
            after = rest[len(tail) :]
            if after.startswith(EOL):
                end = len(p) + len(tail) + len(EOL)
                return end, Text(raw=buf[:end], phrase=phrase, tail=tail.decode().strip())
            if (after == b"" or after == EOL[:1]) and len(tail) < _MAX_TAIL:
                partial = True
        return PARTIAL if partial else None


def parse_all(data: bytes) -> list[Event]:
    """Parse a complete capture (flushes at the end)."""
    parser = ReplyParser()
    return parser.feed(data) + parser.flush()


# --- encoders of replies, used by tests and the docs ----------------------


def reply_ack(code: int, role: str | None = None, module: int | None = None) -> bytes:
    return wire.PREAMBLE + _prefix(role, module) + wire.REPLY_ACK + bytes([code]) + EOL


def reply_error(code: int, reason: int, role: str | None = None,
                module: int | None = None) -> bytes:
    return wire.PREAMBLE + _prefix(role, module) + wire.REPLY_ERR + bytes([code, reason]) + EOL


def reply_status(module_id: int, role: str, localized: bool, x: int, y: int, yref: int,
                 error: int, prefix_role: str | None = None,
                 schema: int | None = None) -> bytes:
    """A STA reply; ``schema`` None gives the format of firmware before the schema."""
    body = bytes([module_id, ord(role), int(localized), x & 0xFF, y & 0xFF, yref, error])
    if schema is not None:
        body += f"{schema:08x}".encode()
    return (wire.PREAMBLE + _prefix(prefix_role, module_id if prefix_role else None)
            + wire.REPLY_STATUS + body + EOL)


def _prefix(role: str | None, module: int | None) -> bytes:
    if role is None:
        return b""
    ident = f"{module:0{wire.ID_MIN_DIGITS}d}" if module is not None else ""
    return f"{role}{ident}: ".encode()
