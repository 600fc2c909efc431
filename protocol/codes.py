"""The function-code table of the HexBot protocol: the one source of truth.

Table 3-7 of the thesis (codes 1..68 and 126) plus our extensions in the
codes it left unused (69..72). Host menus, firmware dispatch (through the
generated ``firmware/include/hexbot_codes.h``), frame validation and the
protocol documentation are all derived from ``CODES``.
"""

from __future__ import annotations

import enum
from dataclasses import dataclass, field

from hexbot.protocol.wire import MAX_SELECT_ID


class Board(enum.Enum):
    """Which microcontroller of a module executes a function."""

    CONTROL = "control"  # solenoid joints and electromagnets; reached via the comm board
    COMM = "comm"  # IR selector, LEDs, localization, addressing
    NONE = "none"  # unused and reserved codes


class Status(enum.Enum):
    USED = "used"  # a function of Table 3-7
    EXTENSION = "extension"  # ours, in a code Table 3-7 left unused
    UNUSED = "unused"  # "Not Used" in Table 3-7: the module answers ACK 'N'
    RESERVED = "reserved"  # a byte value with a framing meaning; never a function


@dataclass(frozen=True)
class Arg:
    """One argument byte of a function: its valid range and what it means."""

    name: str
    meaning: str
    lo: int = 0
    hi: int = 255
    unit: str = ""  # "tick" = 10 ms

    def check(self, value: int) -> bool:
        return self.lo <= value <= self.hi


@dataclass(frozen=True)
class FunctionCode:
    code: int
    name: str
    board: Board
    status: Status
    comment: str
    args: tuple[Arg, ...] = field(default_factory=tuple)

    @property
    def c_name(self) -> str:
        """Name of the firmware macro, e.g. ``HB_FN_JX_OPEN``."""
        out = []
        for i, ch in enumerate(self.name):
            if ch.isupper() and i and (self.name[i - 1].islower() or self.name[i - 1].isdigit()):
                out.append("_")
            out.append(ch.upper())
        return "HB_FN_" + "".join(out)

    @property
    def executable(self) -> bool:
        return self.status in (Status.USED, Status.EXTENSION)

    def signature(self) -> str:
        return f"{self.name}({', '.join(a.name for a in self.args)})"


# --- argument vocabulary (ranges checked by host and firmware alike) -------
JOINT = Arg("i", "joint number", 1, 6)
SIDE = Arg("i", "side number", 1, 6)
COUNT = Arg("n", "number of repetitions", 1, 255)
DELAY = Arg("t", "delay between actuations", 0, 255, "tick")
T1 = Arg("t1", "delay before the magnets start", 0, 255, "tick")
T2 = Arg("t2", "delay before the joints are exchanged", 0, 255, "tick")
T3 = Arg("t3", "delay before the magnets stop", 0, 255, "tick")
ROT_JOINT = Arg("i", "rotation joint (body frame)", 1, 6)
CHANNEL = Arg("i", "IR channel: 0 centre (PC), 1..6 side", 0, 6)
LYREF_DIR = Arg("i", "0 show Yref, 1 CCW sweep, 2 CW sweep (thesis: -1)", 0, 2)
MODULE_ID = Arg("id", "module id (DIP switches), 0 = all modules", 0, MAX_SELECT_ID)
MODULE_ID_OPT = Arg("id", f"further module id, 1..{MAX_SELECT_ID}; 'N' (78) = none", 1,
                    MAX_SELECT_ID)
ROLE = Arg("role", "1 mobile (M), 2 substrate (S)", 1, 2)

NO_ARGS: tuple[Arg, ...] = ()
ROTATION_ARGS = (ROT_JOINT, T1, T2, T3)
COMBINED_ARGS = (
    Arg("si", "substrate rotation joint (body frame)", 1, 6),
    Arg("st1", "substrate: delay before the magnets start", 0, 255, "tick"),
    Arg("st2", "substrate: delay before the joints are exchanged", 0, 255, "tick"),
    Arg("st3", "substrate: delay before the magnets stop", 0, 255, "tick"),
    Arg("mi", "mobile rotation joint (body frame)", 1, 6),
    Arg("mt1", "mobile: delay before the magnets start", 0, 255, "tick"),
    Arg("mt2", "mobile: delay before the joints are exchanged", 0, 255, "tick"),
    Arg("mt3", "mobile: delay before the magnets stop", 0, 255, "tick"),
)

C, M, N = Board.CONTROL, Board.COMM, Board.NONE
U, E = Status.USED, Status.EXTENSION


def _fn(code, name, board, comment, args=NO_ARGS, status=U) -> FunctionCode:
    return FunctionCode(code, name, board, status, comment, tuple(args))


_DEFINED = [
    # Control board functions (Table 3-7, upper part)
    _fn(1, "JxOpen", C, "Open a solenoid", [JOINT]),
    _fn(2, "JxClose", C, "Close a solenoid", [JOINT]),
    _fn(3, "JxOpenAll", C, "Open all solenoids"),
    _fn(4, "JxCloseAll", C, "Close all solenoids"),
    _fn(5, "JTest", C, "Open all solenoids alternately", [COUNT, DELAY]),
    _fn(11, "SxP", C, "Turn on a magnet (positive pole)", [SIDE]),
    _fn(12, "SxN", C, "Turn on a magnet (negative pole)", [SIDE]),
    _fn(13, "SxOff", C, "Turn off a magnet", [SIDE]),
    _fn(14, "SxOffAll", C, "Turn off all magnets"),
    _fn(15, "SPTest", C, "Turn on all magnets alternately (positive pole)", [COUNT, DELAY]),
    _fn(16, "SNTest", C, "Turn on all magnets alternately (negative pole)", [COUNT, DELAY]),
    _fn(20, "TurnOffAll", C, "Turn off all actuators"),
    _fn(21, "MCW", C, "Mobile module clockwise rotation", ROTATION_ARGS),
    _fn(22, "MCCW", C, "Mobile module counterclockwise rotation", ROTATION_ARGS),
    _fn(23, "SCW", C, "Substrate clockwise support", ROTATION_ARGS),
    _fn(24, "SCCW", C, "Substrate counterclockwise support", ROTATION_ARGS),
    # Communication board functions (Table 3-7, lower part)
    _fn(25, "IrSel", M, "UART1 (IR) channel selection", [CHANNEL]),
    _fn(28, "SideOnP", M, "Positive magnet on LED", [SIDE]),
    _fn(29, "SideOffP", M, "Positive magnet off LED", [SIDE]),
    _fn(30, "SideOnAllP", M, "All positive LEDs on"),
    _fn(31, "SideOffAllP", M, "All positive LEDs off"),
    _fn(32, "SideOnN", M, "Negative magnet on LED", [SIDE]),
    _fn(33, "SideOffN", M, "Negative magnet off LED", [SIDE]),
    _fn(34, "SideOnAllN", M, "All negative LEDs on"),
    _fn(35, "SideOffAllN", M, "All negative LEDs off"),
    _fn(36, "SidePTest", M, "Positive magnet LEDs in turn", [COUNT, DELAY]),
    _fn(37, "SideNTest", M, "Negative magnet LEDs in turn", [COUNT, DELAY]),
    _fn(38, "JointOn", M, "Joint on LED", [JOINT]),
    _fn(39, "JointOff", M, "Joint off LED", [JOINT]),
    _fn(40, "JointOnAll", M, "All joint LEDs on"),
    _fn(41, "JointOffAll", M, "All joint LEDs off"),
    _fn(43, "JointTest", M, "Joint LEDs in turn", [COUNT, DELAY]),
    _fn(44, "LOn", M, "All LEDs on"),
    _fn(45, "LOff", M, "All LEDs off"),
    _fn(46, "LCircle", M, "Rotating LEDs", [COUNT, DELAY]),
    _fn(47, "LColor", M, "Rotating LED colours", [COUNT, DELAY]),
    _fn(48, "LFlash1", M, "Flashing LEDs, pattern 1", [COUNT, DELAY]),
    _fn(49, "LFlash2", M, "Flashing LEDs, pattern 2", [COUNT, DELAY]),
    _fn(50, "LYref", M, "Reference (orientation) indicating LEDs", [LYREF_DIR]),
    _fn(56, "LMCW", M, "Mobile clockwise rotation LEDs", ROTATION_ARGS),
    _fn(57, "LMCCW", M, "Mobile counterclockwise rotation LEDs", ROTATION_ARGS),
    _fn(58, "LSCW", M, "Substrate clockwise support LEDs", ROTATION_ARGS),
    _fn(59, "LSCCW", M, "Substrate counterclockwise support LEDs", ROTATION_ARGS),
    _fn(65, "Ref", M, "Set the module as the reference at (0,0), Yref 0, role S"),
    _fn(66, "Localize", M, "Start localization; spreads over the connected cluster"),
    _fn(67, "CW", M, "Combined clockwise rotation; each module runs its role's half",
        COMBINED_ARGS),
    _fn(68, "CCW", M, "Combined counterclockwise rotation; each module runs its role's half",
        COMBINED_ARGS),
    # Our extensions in codes Table 3-7 left unused
    _fn(69, "Select", M, "Address the following commands to these modules (0 = all)",
        [MODULE_ID, *([MODULE_ID_OPT] * 7)], status=E),
    _fn(70, "Status", M, "Report id, role, localized flag, X, Y, Yref and last error",
        status=E),
    _fn(71, "SetRole", M, "Set the module's role for combined rotations", [ROLE], status=E),
    _fn(72, "ClearError", M, "Clear the last error", status=E),
]

# Byte values that carry framing meaning and never name a function.
_RESERVED = {
    42: ("Start", "'*' starts every message"),
    126: ("Timeout", "'~' the control board did not acknowledge within 2.5 s"),
}

#: Highest code of Table 3-7's numbered list; 126 is reserved beyond it.
LAST_TABLE_CODE = 75


def _build() -> dict[int, FunctionCode]:
    table: dict[int, FunctionCode] = {}
    for fn in _DEFINED:
        if fn.code in table:
            raise AssertionError(f"duplicate function code {fn.code}")
        table[fn.code] = fn
    for code, (name, comment) in _RESERVED.items():
        table[code] = FunctionCode(code, name, N, Status.RESERVED, comment)
    for code in range(1, LAST_TABLE_CODE + 1):
        table.setdefault(code, FunctionCode(code, f"Unused{code}", N, Status.UNUSED, "Not used"))
    return dict(sorted(table.items()))


#: Every code 1..75 and 126, in order.
CODES: dict[int, FunctionCode] = _build()
BY_NAME: dict[str, FunctionCode] = {fn.name.lower(): fn for fn in CODES.values()}


def lookup(key: int | str) -> FunctionCode:
    """A function by code number or (case-insensitive) name; KeyError if none."""
    if isinstance(key, int):
        return CODES[key]
    text = key.strip()
    if text.isdigit():
        return CODES[int(text)]
    return BY_NAME[text.lower()]


#: After an ACK of one of these the module that acknowledged stands elsewhere:
#: the mobile halves of a rotation (21, 22), and the combined rotations (67,
#: 68) for the module whose role is mobile.
MOBILE_HALF_CODES = frozenset(lookup(name).code for name in ("MCW", "MCCW"))
COMBINED_ROTATION_CODES = frozenset(lookup(name).code for name in ("CW", "CCW"))


def moves_the_module(code: int, role: str | None) -> bool:
    """Does an ACK of ``code`` from a module of ``role`` (its letter) mean it moved?"""
    return code in MOBILE_HALF_CODES or (code in COMBINED_ROTATION_CODES and role == "M")


def executable_codes() -> list[FunctionCode]:
    return [fn for fn in CODES.values() if fn.executable]


# --- reply vocabulary shared with the firmware ---------------------------


class ErrorCode(enum.IntEnum):
    """Reason byte of an ``ERR`` reply (and of the status' last-error field)."""

    NONE = 0
    ARG_RANGE = 1  # an argument outside its documented range
    CONTROL_TIMEOUT = 2  # the control board did not echo within 2.5 s
    CONTROL_MISMATCH = 3  # the control board echoed another code
    NOT_LOCALIZED = 4  # a function needs a localized module
    BAD_FRAME = 5  # end byte missing: the frame was truncated or corrupted
    NO_ROLE = 6  # a combined rotation reached a module without a role
    NOT_HEARD = 7  # localization: no neighbour message heard on any side
    BUSY = 8  # frames came faster than the module ran them: the newest was dropped
    STOPPED = 9  # a newer control command stopped this sequence before its end
    WATCHDOG_RESET = 10  # the comm board restarted by its watchdog: role, place lost
    BROWN_OUT = 11  # the comm board restarted after its supply sagged
    CONTROL_RESTARTED = 12  # the control board restarted: every actuator dropped


class Role(enum.IntEnum):
    NONE = 0
    MOBILE = 1
    SUBSTRATE = 2

    @property
    def letter(self) -> str:
        return {Role.NONE: "-", Role.MOBILE: "M", Role.SUBSTRATE: "S"}[self]
