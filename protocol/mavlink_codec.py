"""The PC's side of the two framings on the IR link, without I/O.

Legacy framing is ``frames.encode_pc`` and ``parser.ReplyParser``. MAVLink
framing packs and unpacks with the Python module mavgen generated from
``protocol/hexbot.xml`` (``hexbot_mavlink``): no codec of our own.

:class:`FramedParser` reads the mixed byte stream a PC hears (legacy text
replies, MAVLink 2 frames, noise): a MAVLink frame starts with 0xFD; its
header is checked against the dialect (length, flags, message id) as soon
as its bytes are there, then pymavlink decodes it and checks the CRC with
CRC_EXTRA. Whatever is not a valid frame goes to the legacy parser, so a
0xFD inside a legacy status reply costs nothing. MAVLink replies become
the same typed events as their legacy forms (``MavAck`` is an ``Ack``...),
so the session waits for them the same way, and carry the frame's header
(:class:`MavInfo`): system id, sequence number, and how many messages of
that system were missed before it (a gap in the sequence). A legacy reply
of several lines gives several events: so does the message that replaces
it (:func:`to_events`: ``HEXBOT_LOCALIZED`` is the ``LOCALIZED`` report's
four), and whatever reads events (the cluster model, a script's ``expect
text LOCALIZED``) reads both framings alike.
"""

from __future__ import annotations

import enum
import io
from collections.abc import Iterable
from dataclasses import dataclass, field

from hexbot.errors import FrameError
from hexbot.protocol import frames, hexbot_mavlink, wire
from hexbot.protocol.codes import CODES, Role, lookup
from hexbot.protocol.frames import Command
from hexbot.protocol.parser import (
    Ack,
    ErrorReply,
    Event,
    PositionReport,
    ReplyParser,
    SideReport,
    StatusReport,
    Text,
    YrefReport,
)

STX = hexbot_mavlink.PROTOCOL_MARKER_V2  # 0xFD
HEADER_LEN = 10  # STX len incompat compat seq sysid compid msgid(3)
CRC_LEN = 2
SIGNATURE_LEN = 13
#: The PC's MAVLink identity: GCS-style system id, our own component id.
PC_SYSTEM = 255
PC_COMPONENT = 190
SELECT = lookup("Select").code
#: Longest payload of the dialect: a longer length byte is no frame of ours.
MAX_PAYLOAD = max(cls.unpacker.size for cls in hexbot_mavlink.mavlink_map.values())
#: Longest HEXBOT_COMMAND on the wire (unsigned).
MAX_FRAME_LEN = (HEADER_LEN + hexbot_mavlink.MAVLink_hexbot_command_message.unpacker.size
                 + CRC_LEN)


class Framing(enum.Enum):
    LEGACY = "legacy"  # '*' B1..B9 '#', text replies
    MAVLINK = "mavlink"  # HEXBOT_COMMAND, HEXBOT_* replies
    AUTO = "auto"  # probe with a Status request, then one of the above


@dataclass(frozen=True)
class MavInfo:
    """The MAVLink header of a received message, and what the PC made of it."""

    name: str  # message name, e.g. HEXBOT_ACK
    sysid: int
    compid: int
    seq: int
    fields: tuple[tuple[str, object], ...] = ()
    missed: int = 0  # messages of this system lost before this one (sequence gap)

    def describe(self) -> str:
        body = ", ".join(f"{k}: {v}" for k, v in self.fields)
        gap = f", {self.missed} lost before" if self.missed else ""
        return f"MAV {self.name} sys {self.sysid} seq {self.seq}{gap} {{{body}}}"


@dataclass(frozen=True)
class MavAck(Ack):
    mav: MavInfo | None = None


@dataclass(frozen=True)
class MavErrorReply(ErrorReply):
    mav: MavInfo | None = None


@dataclass(frozen=True)
class MavStatus(StatusReport):
    crc_errors: int = 0  # commands the module dropped for a bad checksum
    mav: MavInfo | None = None


@dataclass(frozen=True)
class MavLocalized(PositionReport):
    side: int = 0
    yref: int = 0
    mav: MavInfo | None = None


@dataclass(frozen=True)
class MavMessage(Event):
    """Any other valid message of the dialect (e.g. another PC's command)."""

    mav: MavInfo | None = None


# --- PC -> module -----------------------------------------------------------


class MavlinkEncoder:
    """HEXBOT_COMMAND frames from the PC, numbered by pymavlink's sequence."""

    def __init__(self, system: int = PC_SYSTEM, component: int = PC_COMPONENT) -> None:
        self._out = io.BytesIO()  # pymavlink's send() writes here and numbers the frame
        self.mav = hexbot_mavlink.MAVLink(self._out, srcSystem=system, srcComponent=component)

    def encode(self, command: Command, *, target: int = 0, strict: bool = True) -> bytes:
        """The command as one MAVLink 2 frame to module ``target`` (0: the
        modules the last Select chose, as a legacy frame). Unused argument
        bytes are 0, so MAVLink 2 leaves them off the wire."""
        frames.validate(command, strict=strict)
        if not 0 <= target <= wire.MAX_MODULE_ID:
            raise FrameError(f"target module must be 0..{wire.MAX_MODULE_ID}, got {target}")
        args = [0 if (command.code == SELECT and a == wire.UNUSED) else a
                for a in command.args]
        args += [0] * (wire.PC_ARGS - len(args))
        self._out.seek(0)
        self._out.truncate()
        self.mav.hexbot_command_send(target, command.code, args)
        return self._out.getvalue()


def describe_mavlink_tx(data: bytes) -> str | None:
    """``MAV to 3 seq 7: Status()`` for a HEXBOT_COMMAND frame; None if
    ``data`` is not one."""
    if data[:1] != bytes([STX]):
        return None
    try:
        msg = hexbot_mavlink.MAVLink(None).decode(bytearray(data))
    except hexbot_mavlink.MAVError:
        return None
    if not isinstance(msg, hexbot_mavlink.MAVLink_hexbot_command_message):
        return f"MAV {msg.get_type()} seq {msg.get_seq()}"
    fn = CODES.get(msg.code)
    args = list(msg.args[:len(fn.args)] if fn is not None else [])
    while msg.code == SELECT and len(args) > 1 and args[-1] == 0:
        args.pop()  # Select's further ids are optional
    call = f"{fn.name}({', '.join(map(str, args))})" if fn else f"code{msg.code}"
    to = f"to {msg.target_system}" if msg.target_system else "to the selected"
    return f"MAV {to} seq {msg.get_seq()}: {call}"


# --- module -> PC -------------------------------------------------------------

_ROLE_LETTER = {r.value: r.letter for r in Role}


def _fields(msg) -> tuple[tuple[str, object], ...]:
    return tuple((name, getattr(msg, name)) for name in msg.get_fieldnames())


def to_event(raw: bytes, msg, missed: int = 0) -> Event:
    """A decoded message as the event its legacy form would give."""
    info = MavInfo(msg.get_type(), msg.get_srcSystem(), msg.get_srcComponent(), msg.get_seq(),
                   _fields(msg), missed)
    role = _ROLE_LETTER.get(getattr(msg, "role", 0), "-")
    module = msg.get_srcSystem()
    if isinstance(msg, hexbot_mavlink.MAVLink_hexbot_ack_message):
        if msg.result == hexbot_mavlink.HEXBOT_RESULT_ERROR:
            return MavErrorReply(raw, msg.code, msg.error, role, module, mav=info)
        code = {hexbot_mavlink.HEXBOT_RESULT_UNUSED_CODE: wire.UNUSED,
                hexbot_mavlink.HEXBOT_RESULT_CONTROL_TIMEOUT: wire.TIMEOUT}.get(msg.result,
                                                                                 msg.code)
        return MavAck(raw, code, role, module, mav=info)
    if isinstance(msg, hexbot_mavlink.MAVLink_hexbot_status_message):
        return MavStatus(raw, module, role, bool(msg.localized), msg.x, msg.y, msg.yref,
                         msg.error, role, msg.schema, crc_errors=msg.crc_errors, mav=info)
    if isinstance(msg, hexbot_mavlink.MAVLink_hexbot_localized_message):
        return MavLocalized(raw, msg.x, msg.y, side=msg.side, yref=msg.yref, mav=info)
    return MavMessage(raw, mav=info)


def to_events(raw: bytes, msg, missed: int = 0) -> list[Event]:
    """A decoded message as the events its legacy form gives, in their
    order: the one of :func:`to_event`, except for ``HEXBOT_LOCALIZED``,
    which replaces the four lines of the legacy localization report
    (``LOCALIZED``, ``Side:``, ``Yref:``, ``Pos:``) and so gives their four
    events; the last, the position, carries the frame and its header."""
    event = to_event(raw, msg, missed)
    if isinstance(event, MavLocalized):
        return [Text(b"", phrase=wire.TEXT_LOCALIZED), SideReport(b"", side=event.side),
                YrefReport(b"", yref=event.yref), event]
    return [event]


@dataclass
class FramedParser:
    """Bytes in, events out, for both framings at once (the ReplyParser
    interface: ``feed``, ``flush``, ``pending``)."""

    legacy: ReplyParser = field(default_factory=ReplyParser)
    mav: object = field(default_factory=lambda: hexbot_mavlink.MAVLink(None))
    _buf: bytearray = field(default_factory=bytearray)
    _last_seq: dict[int, int] = field(default_factory=dict)

    def feed(self, data: bytes | Iterable[int]) -> list[Event]:
        self._buf.extend(data)
        return self._drain(final=False)

    def flush(self) -> list[Event]:
        events = self._drain(final=True)
        return events + self.legacy.flush()

    @property
    def pending(self) -> bytes:
        return bytes(self._buf) + self.legacy.pending

    def _drain(self, final: bool) -> list[Event]:
        out: list[Event] = []
        while self._buf:
            start = self._buf.find(STX)
            if start != 0:
                cut = len(self._buf) if start < 0 else start
                out += self.legacy.feed(bytes(self._buf[:cut]))
                del self._buf[:cut]
                continue
            size = self._frame_size()
            if size is None or (size > len(self._buf) and final):
                out += self.legacy.feed(bytes(self._buf[:1]))  # not a frame after all
                del self._buf[:1]
                continue
            if size > len(self._buf):
                break  # wait for the rest
            frame = bytes(self._buf[:size])
            try:
                msg = self.mav.decode(bytearray(frame))
            except hexbot_mavlink.MAVError:
                out += self.legacy.feed(frame[:1])  # bad CRC: the 0xFD was not a start
                del self._buf[:1]
                continue
            del self._buf[:size]
            # legacy bytes still pending before a whole MAVLink frame can
            # never complete: report them (as garbage) before the frame
            out += self.legacy.flush()
            out += to_events(frame, msg, self._gap(msg))
        return out

    def _frame_size(self) -> float | None:
        """Length of the frame starting the buffer; None if its header is
        not the dialect's; inf while the header is incomplete."""
        buf = self._buf
        if len(buf) >= 2 and buf[1] > MAX_PAYLOAD:
            return None
        if len(buf) >= 3 and buf[2] & ~hexbot_mavlink.MAVLINK_IFLAG_SIGNED:
            return None
        if len(buf) < HEADER_LEN:
            return float("inf")
        msgid = buf[7] | buf[8] << 8 | buf[9] << 16
        if msgid not in hexbot_mavlink.mavlink_map:
            return None
        signed = SIGNATURE_LEN if buf[2] & hexbot_mavlink.MAVLINK_IFLAG_SIGNED else 0
        return HEADER_LEN + buf[1] + CRC_LEN + signed

    def _gap(self, msg) -> int:
        """Messages of the sender missed since its last one (sequence numbers)."""
        sysid, seq = msg.get_srcSystem(), msg.get_seq()
        last = self._last_seq.get(sysid)
        self._last_seq[sysid] = seq
        return 0 if last is None else (seq - last - 1) % 256
