"""Frame codecs of the HexBot links, each a pure encode/decode pair.

- PC -> module (IR, 300 baud): ``*`` B1..B9 ``#``; B1 the function code,
  B2..B9 its arguments as raw bytes, unused ones ``N`` (Table 3-8).
- comm board -> control board (UART0, 4800 baud): ``*`` code a1..a4 ``#``;
  the control board answers with one byte, the code it will execute.
- MSG1 localization (IR, neighbour to neighbour): ``*`` sX X X sY Y Y S in
  ASCII: signs ``+``/``-``, two decimal digits each, S the side ``1``..``6``.

Every decoder raises :class:`~hexbot.errors.FrameError` with the reason.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

from hexbot.errors import FrameError
from hexbot.protocol import wire
from hexbot.protocol.codes import CODES, FunctionCode, lookup


@dataclass(frozen=True)
class Command:
    """A function call as the PC sends it: code and its argument values."""

    code: int
    args: tuple[int, ...] = ()

    @property
    def function(self) -> FunctionCode:
        return CODES[self.code]

    def __str__(self) -> str:
        fn = CODES.get(self.code)
        name = fn.name if fn else f"code{self.code}"
        return f"{name}({', '.join(str(a) for a in self.args)})"


def _check_byte(value: int, what: str) -> int:
    if not isinstance(value, int) or isinstance(value, bool):
        raise FrameError(f"{what} must be an integer, got {value!r}")
    if not 0 <= value <= 255:
        raise FrameError(f"{what} must fit in one byte (0..255), got {value}")
    return value


def validate(command: Command, *, strict: bool = True) -> Command:
    """Check code and argument ranges against the table.

    With ``strict=False`` unused codes and out-of-range arguments pass (the
    firmware must then answer them; tests use this to send bad input on
    purpose), but every value must still be a byte.
    """
    _check_byte(command.code, "function code")
    for i, value in enumerate(command.args):
        _check_byte(value, f"argument {i + 1}")
    if len(command.args) > wire.PC_ARGS:
        raise FrameError(f"at most {wire.PC_ARGS} arguments, got {len(command.args)}")
    if not strict:
        return command
    fn = CODES.get(command.code)
    if fn is None or not fn.executable:
        what = "reserved" if fn is not None and fn.status.value == "reserved" else "unused"
        raise FrameError(f"function code {command.code} is {what}")
    required = [a for a in fn.args if "none" not in a.meaning]
    if not len(required) <= len(command.args) <= len(fn.args):
        raise FrameError(
            f"{fn.signature()} takes {len(required)} argument(s), got {len(command.args)}"
        )
    for arg, value in zip(fn.args, command.args, strict=False):
        if not arg.check(value):
            raise FrameError(
                f"{fn.name}: {arg.name} ({arg.meaning}) must be {arg.lo}..{arg.hi}, got {value}"
            )
    if fn.name == "Select":
        _check_select(command.args)
    return command


def _check_select(ids: Sequence[int]) -> None:
    """What a Select list means only one way: the firmware takes a first 0 as
    "all" and drops the rest, and gives a repeated id the rank of its first
    place, while a host would wait for a reply per place."""
    if 0 in ids and len(ids) > 1:
        raise FrameError("id 0 (all modules) cannot be combined with other ids")
    if len(set(ids)) != len(ids):
        raise FrameError(f"duplicate module ids in {list(ids)}")


def make(key: int | str, *args: int, strict: bool = True) -> Command:
    """Build and validate a command from a code or a function name."""
    try:
        code = lookup(key).code if strict else int(key)
    except (KeyError, ValueError) as exc:
        raise FrameError(f"unknown function {key!r}") from exc
    return validate(Command(code, tuple(args)), strict=strict)


# --- PC -> module ---------------------------------------------------------


def encode_pc(command: Command, *, strict: bool = True) -> bytes:
    """``*`` B1..B9 ``#``: 11 bytes, unused argument bytes ``N``."""
    validate(command, strict=strict)
    args = list(command.args) + [wire.UNUSED] * (wire.PC_ARGS - len(command.args))
    return bytes([wire.START, command.code, *args, wire.END])


def decode_pc(frame: bytes, strict: bool = True) -> Command:
    """Inverse of :func:`encode_pc`; trailing ``N`` bytes beyond the
    function's arity are dropped, everything is range-checked (the frame's
    shape always; the arguments' ranges only when ``strict``, as encode_pc)."""
    if len(frame) != wire.PC_FRAME_LEN:
        raise FrameError(f"PC frame must be {wire.PC_FRAME_LEN} bytes, got {len(frame)}")
    if frame[0] != wire.START:
        raise FrameError(f"PC frame must start with '*', got 0x{frame[0]:02X}")
    if frame[-1] != wire.END:
        raise FrameError(f"PC frame must end with '#', got 0x{frame[-1]:02X}")
    code = frame[1]
    fn = CODES.get(code)
    if fn is None or not fn.executable:
        raise FrameError(f"function code {code} is not a function")
    raw = frame[2:-1]
    arity = len(fn.args)
    if any(b != wire.UNUSED for b in raw[arity:]):
        raise FrameError(f"{fn.name}: bytes beyond its {arity} argument(s) must be 'N'")
    args = list(raw[:arity])
    # Optional trailing arguments (Select's further ids) are 'N' when absent.
    while args and len(args) > _required_count(fn) and args[-1] == wire.UNUSED:
        args.pop()
    command = Command(code, tuple(args))
    return validate(command) if strict else command


def _required_count(fn: FunctionCode) -> int:
    return sum(1 for a in fn.args if "none" not in a.meaning)


# --- comm board -> control board -----------------------------------------


def encode_board(command: Command) -> bytes:
    """``*`` code a1..a4 ``#`` (7 bytes) for a control-board function."""
    fn = validate(command).function
    if fn.board.value != "control":
        raise FrameError(f"{fn.name} runs on the {fn.board.value} board, not the control board")
    args = list(command.args) + [wire.UNUSED] * (wire.BOARD_ARGS - len(command.args))
    return bytes([wire.START, command.code, *args, wire.END])


def decode_board(frame: bytes) -> Command:
    if len(frame) != wire.BOARD_FRAME_LEN:
        raise FrameError(f"board frame must be {wire.BOARD_FRAME_LEN} bytes, got {len(frame)}")
    if frame[0] != wire.START or frame[-1] != wire.END:
        raise FrameError("board frame must be framed by '*' and '#'")
    fn = CODES.get(frame[1])
    if fn is None or fn.board.value != "control":
        raise FrameError(f"code {frame[1]} is not a control-board function")
    arity = len(fn.args)
    if any(b != wire.UNUSED for b in frame[2 + arity : -1]):  # as the control firmware checks
        raise FrameError(f"{fn.name}: bytes beyond its {arity} argument(s) must be 'N'")
    return validate(Command(frame[1], tuple(frame[2 : 2 + arity])))


def encode_board_ack(code: int) -> bytes:
    """The control board's acknowledgement: the code byte it executes."""
    return bytes([_check_byte(code, "acknowledged code")])


def decode_board_ack(data: bytes, sent_code: int) -> int:
    """The echoed code; FrameError if missing, a time-out or another code."""
    if len(data) != 1:
        raise FrameError(f"board acknowledgement is one byte, got {len(data)}")
    if data[0] == wire.TIMEOUT:
        raise FrameError("control board did not acknowledge (time-out '~')")
    if data[0] != sent_code:
        raise FrameError(f"control board echoed {data[0]}, expected {sent_code}")
    return data[0]


# --- MSG1: localization --------------------------------------------------


@dataclass(frozen=True)
class LocationMessage:
    """What a localized module tells the neighbour on one of its sides:
    the neighbour's position and the global side through which it hears."""

    x: int
    y: int
    side: int


def _coord(value: int, what: str) -> bytes:
    if not -wire.LOC_COORD_LIMIT <= value <= wire.LOC_COORD_LIMIT:
        raise FrameError(f"{what} must be within ±{wire.LOC_COORD_LIMIT}, got {value}")
    return f"{'-' if value < 0 else '+'}{abs(value):02d}".encode()


def encode_location(msg: LocationMessage) -> bytes:
    if not 1 <= msg.side <= 6:
        raise FrameError(f"side must be 1..6, got {msg.side}")
    return b"*" + _coord(msg.x, "X") + _coord(msg.y, "Y") + str(msg.side).encode()


def _parse_coord(chunk: bytes, what: str) -> int:
    sign, digits = chunk[:1], chunk[1:]
    if sign not in (b"+", b"-") or not digits.isdigit():
        raise FrameError(f"{what} must be a sign and two digits, got {chunk!r}")
    value = int(digits)
    return -value if sign == b"-" else value


def decode_location(frame: bytes) -> LocationMessage:
    if len(frame) != wire.LOC_FRAME_LEN:
        raise FrameError(f"MSG1 must be {wire.LOC_FRAME_LEN} bytes, got {len(frame)}")
    if frame[0] != wire.START:
        raise FrameError("MSG1 must start with '*'")
    x = _parse_coord(frame[1:4], "X")
    y = _parse_coord(frame[4:7], "Y")
    if frame[7:8] not in [str(s).encode() for s in range(1, 7)]:
        raise FrameError(f"MSG1 side must be '1'..'6', got {frame[7:8]!r}")
    return LocationMessage(x, y, frame[7] - ord("0"))


# --- addressing ------------------------------------------------------------


def select(ids: Sequence[int]) -> Command:
    """SELECT(id...): the following commands are for these modules; [0] = all.
    The order is the acknowledgement order (rank r answers after r slots)."""
    ids = list(ids)
    if not ids:
        raise FrameError("select needs at least one module id (0 = all)")
    return make("Select", *ids)
