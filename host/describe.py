"""One way to show a protocol event: as a short line and as a JSON object.

Used by the console's terminals, ``hexbot monitor``, ``hexbot replay`` and
the decoded session log, so all of them read the same.
"""

from __future__ import annotations

from dataclasses import asdict
from typing import Any

from hexbot.errors import FrameError
from hexbot.protocol import frames, wire
from hexbot.protocol.codes import CODES, ErrorCode
from hexbot.protocol.mavlink_codec import MavInfo, describe_mavlink_tx
from hexbot.protocol.parser import (
    Ack,
    ControlMessage,
    ErrorReply,
    Event,
    Garbage,
    PositionReport,
    SideReport,
    StatusReport,
    Text,
    YrefReport,
)


def who(role: str | None, module: int | None) -> str:
    """``M03 ``, ``S `` or nothing (no prefix: a control board's debug port)."""
    if role is None:
        return ""
    return (f"{role}{module:02d}" if module is not None else role) + " "


def code_name(code: int) -> str:
    if code in (wire.UNUSED, wire.TIMEOUT):  # "did nothing", control board time-out
        return chr(code)
    fn = CODES.get(code)
    return f"{code} {fn.name}" if fn else f"{code} ?"


def error_name(reason: int) -> str:
    try:
        return ErrorCode(reason).name
    except ValueError:
        return f"reason {reason}"


def describe_event(ev: Event) -> str:
    """One line; a reply that came as MAVLink shows its decoded message beside."""
    line = _describe(ev)
    mav = getattr(ev, "mav", None)
    return f"{line}  [{mav.describe()}]" if mav is not None else line


def _describe(ev: Event) -> str:  # noqa: C901 - one line per event kind
    if isinstance(ev, Ack):
        return f"{who(ev.role, ev.module)}{ev.describe()}"
    if isinstance(ev, ErrorReply):
        return f"{who(ev.role, ev.module)}ERR {code_name(ev.code)}: {error_name(ev.reason)}"
    if isinstance(ev, StatusReport):
        loc = f"at ({ev.x:+03d},{ev.y:+03d}) yref {ev.yref}" if ev.localized else "not localized"
        unknown = (" (no id: replies that collided, or a comm board without its control "
                   "board)" if ev.module_id == 0 else "")
        return (f"STA id {ev.module_id}{unknown} role {ev.role} {loc} "
                f"last error {error_name(ev.error)}")
    if isinstance(ev, ControlMessage):
        return f"MSG {code_name(ev.code)} args {' '.join(str(a) for a in ev.args)}"
    if isinstance(ev, Text):
        return f"TEXT {ev.phrase}" + (f" [{ev.tail}]" if ev.tail else "")
    if isinstance(ev, SideReport):
        return f"LOC side {ev.side}"
    if isinstance(ev, YrefReport):
        return f"LOC yref {ev.yref}"
    if isinstance(ev, PositionReport):
        return f"LOC position ({ev.x:+03d},{ev.y:+03d})"
    if isinstance(ev, Garbage):
        return f"GARBAGE {len(ev.raw)} bytes {ev.raw[:16].hex(' ')}"
    return type(ev).__name__


def event_json(ev: Event) -> dict[str, Any]:
    """A flat JSON object: ``kind`` plus the event's fields and raw hex."""
    out: dict[str, Any] = {"kind": type(ev).__name__.lower()}
    for name in getattr(ev, "__dataclass_fields__", {}):
        if name == "raw":
            continue
        value = getattr(ev, name)
        if isinstance(value, MavInfo):
            value = {**asdict(value), "fields": dict(value.fields)}
        out[name] = list(value) if isinstance(value, tuple) else value
    if isinstance(ev, (Ack, ErrorReply, ControlMessage)):
        fn = CODES.get(ev.code)
        out["function"] = fn.name if fn else None
    if isinstance(ev, ErrorReply):
        out["reason_name"] = error_name(ev.reason)
    out["raw"] = ev.raw.hex()
    return out


def describe_tx(data: bytes) -> str:
    """What the PC sent: ``Select(3)`` for a valid frame (``MAV to 3 seq 7:
    Status()`` for a MAVLink one), else hex."""
    if (sent := describe_mavlink_tx(data)) is not None:
        return sent
    try:
        return str(frames.decode_pc(data))
    except FrameError as exc:
        try:  # a well-formed frame with an argument out of range (--unchecked)
            return f"{frames.decode_pc(data, strict=False)} (unchecked: {exc})"
        except FrameError:
            return f"raw {data.hex(' ')}"
