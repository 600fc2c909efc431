"""Timing of the HexBot protocol: the tick, reply slots, boot slots, the
localization window, and the bounds a PC derives from them.

The firmware is built from these numbers (``hexbot gen-header`` writes them
into ``firmware/include/hexbot_codes.h``) and the simulator and the host
import them, so a bound computed here is a bound on what the real images do.

Units: the firmware counts in ticks of Timer0 (prescaler 64, reload 0x64 at
1 MHz: 156 counts of 64 us = 9.984 ms, the thesis' "10 ms"). Bounds convert
ticks with the nominal ``TICK_S`` = 10 ms, which is longer than the real
tick, so they stay upper bounds. Where the firmware computes with integer
ticks (reply slots, boot slots), the functions below use the same integer
arithmetic as the generated C macros, not a float estimate of it.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Sequence

from hexbot.protocol import wire
from hexbot.protocol.codes import CODES, Board, lookup
from hexbot.protocol.wire import BAUD_BOARD, BAUD_DEBUG, BAUD_IR, F_CPU

__all__ = [
    "ACK_SLOT_S", "ACK_SLOT_TICKS", "BAUD_BOARD", "BAUD_DEBUG", "BAUD_IR", "BAUD_MAX",
    "BAUD_MIN", "BAUD_TOLERANCE", "F_CPU",
    "LOCALIZE_WINDOW_S", "TICK_S", "boot_seconds", "reply_timeout_s",
]

# --- the tick -----------------------------------------------------------------

TIMER0_PRESCALER = 64
TIMER0_RELOAD = 0x64  # thesis listings: TCNT0 reloaded with 0x64 on every overflow
TICK_TRUE_S = TIMER0_PRESCALER * (256 - TIMER0_RELOAD) / F_CPU  # 9.984 ms
TICK_S = 0.010  # nominal tick; every delay argument counts in it
TICKS_PER_S = 100

#: The modules run on the internal RC oscillator (Table 3-6), not a crystal.
#: Their 300-baud link to the PC only works while their clock is within the
#: few per cent an 8N1 receiver tolerates, so a module that answers at all
#: runs at most this much slower than nominal; bounds on hardware allow it.
CLOCK_TOLERANCE = 0.05

#: Largest baud-rate mismatch an 8N1 receiver takes: ATmega162 datasheet,
#: "Asynchronous Operational Range", 8 data bits (D = 8) at U2X = 0: the
#: incoming rate may be 95.36 % .. 104.58 % of the receiver's, +-4.5 % when
#: taken symmetric. The simulator's wires (C) and IR medium use this number.
BAUD_TOLERANCE = 0.045

# --- bytes on the air -----------------------------------------------------------

BYTE_BITS = 10  # 8N1: start, 8 data, stop
#: Ticks one IR byte occupies, x10 and rounded up (3.33 ticks -> 3.4).
IR_BYTE_TICKS_X10 = -(-BYTE_BITS * 10 * TICKS_PER_S // BAUD_IR)


def ir_ticks(nbytes: int) -> int:
    """Ticks that ``nbytes`` back-to-back bytes occupy on the IR link, rounded
    up (the firmware's ``HB_IR_TICKS``)."""
    return (nbytes * IR_BYTE_TICKS_X10 + 9) // 10


def ubrr(baud: int, hz: int = F_CPU) -> int:
    """The USART's divisor for ``baud`` (normal speed), rounded to nearest;
    the firmware's ``HB_UBRR_*`` are generated from it."""
    return (hz + 8 * baud) // (16 * baud) - 1


#: The rates a module's USART (ATmega162, asynchronous) can make at F_CPU:
#: F_CPU / 16 / (UBRR + 1) with its 12-bit UBRR, up to F_CPU / 8 at double
#: speed (U2X, UBRR 0). A PC port outside BAUD_MIN..BAUD_MAX talks to no
#: module's UART, whatever its firmware (the IR transceiver and the debug
#: port both end at one), so the host refuses such a ``--baud`` or
#: ``--debug-baud`` as a usage error. BAUD_MIN is 15: the slowest rate,
#: 15.26 baud, is 1.7 % faster, within BAUD_TOLERANCE.
UBRR_MAX = 4095
BAUD_MIN = F_CPU // (16 * (UBRR_MAX + 1))
BAUD_MAX = F_CPU // 8


def bit_cycles(baud: int, hz: int = F_CPU) -> int:
    """CPU cycles of one bit as the USART makes it: 16 a count of UBRR, so
    4800 baud at 1 MHz is 208 cycles, 4807.7 baud, not 208.3."""
    return 16 * (ubrr(baud, hz) + 1)


def wire_seconds(nbytes: int, baud: int) -> float:
    """Time on the wire of ``nbytes`` 8N1 bytes at ``baud``."""
    return nbytes * BYTE_BITS / baud


# --- replies to the PC and their slots ------------------------------------------

CONTROL_ACK_TIMEOUT_TICKS = 250  # 2.5 s for the control board's echo (thesis)
SUBSTRATE_ACK_DELAY_TICKS = 100  # thesis: the substrate waits 1 s (legacy mode)
ACK_SLOT_TICKS = 60  # addressed mode: rank r answers r slots after rank 0
ACK_SLOT_S = ACK_SLOT_TICKS * TICK_S

ADDRESSED_PREFIX = b"M" + b"n" * wire.ID_MAX_DIGITS + b": "  # longest: role letter, id
ACK_BODY = wire.REPLY_ACK + bytes([0]) + wire.EOL
ERR_BODY = wire.REPLY_ERR + bytes([0, 0]) + wire.EOL
STATUS_FIELDS = 7  # id, role, localized, x, y, yref, last error
SCHEMA_DIGITS = 8  # the schema hash as hex text (docs/protocol.md, "Status")
STATUS_BODY_BYTES = len(wire.REPLY_STATUS) + STATUS_FIELDS + SCHEMA_DIGITS + len(wire.EOL)
#: What a module that localized itself reports (comm/reply.c, reply_localized()).
LOCALIZE_REPORT = (wire.PREAMBLE + wire.TEXT_LOCALIZED.encode() + wire.EOL
                   + wire.LOC_SIDE + b"1" + wire.EOL + wire.LOC_YREF + b"0" + wire.EOL
                   + wire.LOC_POS + b"+00+00" + wire.EOL)

_HEAD = len(wire.PREAMBLE) + len(ADDRESSED_PREFIX)
REPLY_BYTES_ACK = _HEAD + len(ACK_BODY)
REPLY_BYTES_ERR = _HEAD + len(ERR_BODY)
REPLY_BYTES_STATUS = _HEAD + STATUS_BODY_BYTES
REPLY_BYTES_LOCALIZE = len(LOCALIZE_REPORT) + REPLY_BYTES_ACK


def reply_slots(nbytes: int) -> int:
    """ACK slots a reply of ``nbytes`` needs (the firmware's ``HB_REPLY_SLOTS``)."""
    return -(-ir_ticks(nbytes) // ACK_SLOT_TICKS)


SLOTS_ACK = reply_slots(REPLY_BYTES_ERR)  # an ACK or an ERR: the longer of the two
SLOTS_STATUS = reply_slots(REPLY_BYTES_STATUS)
SLOTS_LOCALIZE = reply_slots(REPLY_BYTES_LOCALIZE)

# --- boot --------------------------------------------------------------------------

#: Every module of a cluster boots at once; the boot texts that carry the id
#: go out in slot (id - 1) mod BOOT_SLOTS, the first BOOT_FIRST_SLOT_TICKS
#: after reset (the handshake and the LED shows are over by 1.7 s), each as
#: long as its text at 300 baud plus a guard.
BOOT_SLOTS = 8
BOOT_FIRST_SLOT_TICKS = 200
#: Bytes of the longest slot text (preamble, CTR. BOARD READY ID=nnn, CTR.
#: LISTENING, COMM. LISTENING ID=nnn FW=) without the version string: every
#: slot holds a three-digit id's text, whatever the module's own id.
_ID = "n" * wire.ID_MAX_DIGITS
BOOT_TEXT_FIXED_BYTES = len(
    wire.PREAMBLE
    + f"{wire.TEXT_CTR_READY}{wire.BOOT_ID_TAIL}{_ID}".encode() + wire.EOL
    + wire.TEXT_CTR_LISTENING.encode() + wire.EOL
    + f"{wire.TEXT_COMM_LISTENING}{wire.BOOT_ID_TAIL}{_ID}{wire.BOOT_FW_TAIL}".encode() + wire.EOL
)
#: The slots are counted on each module's own RC clock. They are designed
#: for clocks within +-CLOCK_SPREAD of nominal (the internal oscillator after
#: factory calibration; the simulator tests them so): the guard covers a slow
#: module in one slot running into a fast one in the next, at the last slot,
#: where the drift is largest: guard (1 + s) >= 2 s (first + (slots - 1)
#: (text + guard)), for version strings of up to 16 characters.
CLOCK_SPREAD = 0.02
_BOOT_TEXT_TICKS_MAX = ir_ticks(BOOT_TEXT_FIXED_BYTES + 16)
BOOT_GUARD_TICKS = math.ceil(
    2 * CLOCK_SPREAD * (BOOT_FIRST_SLOT_TICKS + (BOOT_SLOTS - 1) * _BOOT_TEXT_TICKS_MAX)
    / (1 + CLOCK_SPREAD - 2 * CLOCK_SPREAD * (BOOT_SLOTS - 1))
)


def boot_rank(module_id: int) -> int:
    """The boot slot of a module (id 0, no handshake id, takes slot 0)."""
    return (module_id - 1) % BOOT_SLOTS if module_id else 0


def boot_slot_ticks(version: str = wire.FW_VERSION) -> int:
    """Length of one boot slot for firmware built with ``VERSION=version``."""
    return ir_ticks(BOOT_TEXT_FIXED_BYTES + len(version)) + BOOT_GUARD_TICKS


def boot_seconds(ids: Iterable[int], version: str = wire.FW_VERSION) -> float:
    """Simulated time from reset until every module in ``ids`` has sent its
    ``COMM. LISTENING`` boot text (both boards present): the end of the last
    boot slot any of them uses."""
    ranks = [boot_rank(i) for i in ids]
    if not ranks:
        raise ValueError("boot_seconds needs at least one module id")
    ticks = BOOT_FIRST_SLOT_TICKS + (max(ranks) + 1) * boot_slot_ticks(version)
    return ticks * TICK_S


# --- localization (code 66) --------------------------------------------------------

#: A listener stays LISTEN ticks on each side waiting for any byte (one byte
#: time plus the teacher's gap between messages, plus one tick of rounding);
#: when one comes it stays up to CATCH ticks to collect eight consecutive
#: bytes, which hold one whole MSG1 in some rotation. A teacher repeats MSG1
#: on each side for DWELL ticks: a listener may need a full cycle of its six
#: sides to come round, then CATCH ticks.
LOC_LISTEN_TICKS = 6
LOC_CATCH_TICKS = 40
LOC_DWELL_TICKS = 6 * LOC_LISTEN_TICKS + LOC_CATCH_TICKS + 4
LOC_SWEEP_TICKS = 6 * LOC_DWELL_TICKS
#: The flood runs for a fixed window from the end of the 66 frame, long
#: enough for LOC_HOPS hops from a localized module (the thesis' Fig. 5-8
#: cluster is 4 hops deep from its base); then every module reports in its slot.
LOC_HOPS = 4
LOC_WINDOW_TICKS = LOC_HOPS * (LOC_SWEEP_TICKS + 6 * LOC_LISTEN_TICKS) + 20
LOCALIZE_WINDOW_S = LOC_WINDOW_TICKS * TICK_S

# --- the two boards of a module: handshake and board link ------------------------

#: At boot the control board says 'R' and its id every HANDSHAKE_RETRY_TICKS
#: (the thesis' 100 ms), at most HANDSHAKE_MAX_TRIES times; the comm board
#: waits HANDSHAKE_TICKS for it. A control board that booted with the comm
#: board says 'R' after its 0.7 s self-test: past HANDSHAKE_PROBE_TICKS it is
#: already listening (only the comm board restarted), and the comm board asks.
HANDSHAKE_TICKS = 300
HANDSHAKE_RETRY_TICKS = 10
HANDSHAKE_MAX_TRIES = 50
HANDSHAKE_PROBE_TICKS = 100
#: The id byte follows 'R' / 'L' at once; board frames drop after a gap of
#: about six byte times at 4,800 baud.
LINK_ID_TICKS = 3
BOARD_BYTE_TIMEOUT_TICKS = 3

# --- other firmware time-outs the PC can see -----------------------------------

PC_BYTE_TIMEOUT_TICKS = 34  # a PC frame with a gap of 10 byte times is dropped
#: LYref (code 30) shows global +Y on the side facing it: one LED pole, then
#: the other, for YREF_BLINK_TICKS each; Ref (code 65) shows it REF_SHOWS times.
YREF_BLINK_TICKS = 10
REF_SHOWS = 3
IRSEL_HOLD_TICKS = 1000  # IrSel falls back to the centre after 10 s of silence

# --- how long a function keeps the comm board before it replies ---------------


#: What one step of a walk costs the comm board beyond its delay t: the LED
#: writes and a poll of both links, 0.45 ms (LCircle) to 2.65 ms (LFlash2)
#: measured at 1 MHz on the simulator; with t = 0 that is all a walk takes
#: (LCircle(255, 0): 9,180 steps, 4.6 s). A bound for every walk.
WALK_STEP_TICKS = 0.3


def _walk(steps_per_round: int):
    # seq_walk / flash1: n rounds of steps_per_round outputs, each on t then off t.
    return lambda a: a[0] * steps_per_round * 2 * (a[1] + WALK_STEP_TICKS)


def _rotation(a: Sequence[int]) -> int:
    return a[1] + a[2] + a[3]  # t1 + t2 + t3 (Table 3-1)


#: Ticks each function runs before its reply, from its arguments (firmware:
#: common/sequence.c, comm/leds.c). Control functions count too: the comm
#: board mirrors them on its LEDs after the echo and only then replies.
_RUN_BY_NAME = {
    "JTest": _walk(6), "SPTest": _walk(6), "SNTest": _walk(6),
    "MCW": _rotation, "MCCW": _rotation, "SCW": _rotation, "SCCW": _rotation,
    "SidePTest": _walk(6), "SideNTest": _walk(6), "JointTest": _walk(6),
    "LCircle": _walk(18), "LColor": _walk(3), "LFlash1": _walk(1), "LFlash2": _walk(1),
    "LYref": lambda a: 2 * YREF_BLINK_TICKS,  # two blinks
    "LMCW": _rotation, "LMCCW": _rotation, "LSCW": _rotation, "LSCCW": _rotation,
    "Ref": lambda a: REF_SHOWS * 2 * YREF_BLINK_TICKS,  # LYref REF_SHOWS times
    "CW": lambda a: max(_rotation(a[0:4]), _rotation(a[4:8])),  # the longer half
    "CCW": lambda a: max(_rotation(a[0:4]), _rotation(a[4:8])),
}
_RUN_TICKS = {lookup(name).code: run for name, run in _RUN_BY_NAME.items()}
_LOCALIZE, _STATUS = lookup("Localize").code, lookup("Status").code
_FORWARDED = {lookup("CW").code, lookup("CCW").code}  # comm functions that forward a half


def run_ticks(code: int, args: Sequence[int] = ()) -> int:
    """Ticks function ``code`` runs before its module replies. Without
    ``args`` every argument is taken at the top of its range (a bound for
    any arguments)."""
    fn = CODES[code]
    if not args:
        args = [a.hi for a in fn.args]
    run = _RUN_TICKS.get(code)
    return math.ceil(run(list(args) + [0] * 8)) if run else 0


def reply_timeout_s(code: int, replies: int, args: Sequence[int] = (),
                    last_rank: int | None = None) -> float:
    """Upper bound, in seconds, from the end of a PC frame until the last of
    ``replies`` addressed replies to function ``code`` has arrived at the PC.

    The sum of, in firmware ticks:

    - dispatch: 2 ticks (the frame completes between two ticks, the main
      loop wakes on the next interrupt);
    - forward (control functions, and 67/68 which forward their half): the
      board frame at 4800 baud plus the control board's echo, bounded by its
      2.5 s time-out (after which the comm board answers ``~`` at once);
    - run: what the function does before the reply (``run_ticks``): walks
      take count x steps x 2 x delay, rotations t1 + t2 + t3; for 67/68 the
      longer half; without ``args`` the top of every argument range;
      Localize (66) runs the whole localization window instead;
    - turn: the reply slot; rank r answers r x slots x ACK_SLOT_TICKS after
      rank 0 (addressed mode; ``last_rank`` defaults to ``replies - 1``, the
      rank of the last of a Select list; after Select(0) ranks are id - 1, so
      pass the highest id - 1), and a legacy-mode substrate waits 1 s (or
      its slots) -- the larger of the two;
    - air: the longest reply of that kind (ACK/ERR 1 slot, Status 2,
      Localize: the LOCALIZED report plus its ACK, 4) at 300 baud.

    The total allows CLOCK_TOLERANCE for a slow RC oscillator. With
    ``replies`` 0 nothing is awaited and the bound is 0.
    """
    if replies < 0:
        raise ValueError(f"replies must be >= 0, got {replies}")
    if replies == 0:
        return 0.0
    fn = CODES[code]
    rank = replies - 1 if last_rank is None else last_rank
    dispatch = 2
    forward = 0
    if fn.board is Board.CONTROL or code in _FORWARDED:
        frame_and_echo = wire_seconds(wire.BOARD_FRAME_LEN + 1, BAUD_BOARD)
        forward = math.ceil(frame_and_echo / TICK_S) + CONTROL_ACK_TIMEOUT_TICKS
    if code == _LOCALIZE:
        run, slots, nbytes = LOC_WINDOW_TICKS, SLOTS_LOCALIZE, REPLY_BYTES_LOCALIZE
    elif code == _STATUS:
        run, slots, nbytes = 0, SLOTS_STATUS, REPLY_BYTES_STATUS
    else:
        run, slots, nbytes = run_ticks(code, args), SLOTS_ACK, REPLY_BYTES_ERR
    legacy_substrate = SUBSTRATE_ACK_DELAY_TICKS if slots == 1 else slots * ACK_SLOT_TICKS
    turn = max(rank * slots * ACK_SLOT_TICKS, legacy_substrate)
    ticks = dispatch + forward + run + turn + ir_ticks(nbytes)
    return ticks * TICK_S * (1 + CLOCK_TOLERANCE)
