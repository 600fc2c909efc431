"""Tables of the docs generated from the protocol (``generated.py`` splices
them between their markers): the function codes of docs/protocol.md, the
pin map and the timing of docs/firmware.md."""

from __future__ import annotations

from hexbot.protocol import pins, timing, wire
from hexbot.protocol.codes import CODES, Status


def _args(fn) -> str:
    if not fn.args:
        return "-"
    parts = []
    for a in fn.args:
        unit = " ×10 ms" if a.unit == "tick" else ""
        parts.append(f"`{a.name}` {a.lo}..{a.hi}{unit}: {a.meaning}")
    return "<br>".join(parts)


def render_table() -> str:
    rows = ["| code | function | board | arguments | what it does |",
            "|---:|---|---|---|---|"]
    for fn in CODES.values():
        if fn.status is Status.UNUSED:
            continue
        name = f"`{fn.signature()}`" if fn.executable else f"*{fn.status.value}*"
        tag = " (extension)" if fn.status is Status.EXTENSION else ""
        rows.append(f"| {fn.code} | {name} | {fn.board.value} | {_args(fn)} | "
                    f"{fn.comment}{tag} |")
    unused = [str(fn.code) for fn in CODES.values() if fn.status is Status.UNUSED]
    rows.append("")
    rows.append(f"Not used (the module answers `ACK N`): {', '.join(unused)}.")
    return "\n".join(rows)


def render_pin_table() -> str:
    rows = ["| board | signal | 1 | 2 | 3 | 4 | 5 | 6 |", "|---|---|---|---|---|---|---|---|"]
    for board, signal, _cname, table in pins.TABLES:
        rows.append(f"| {board} | {signal} | " + " | ".join(pins.name(p) for p in table) + " |")
    return "\n".join(rows)


def _ticks(n: int) -> str:
    return f"{n} ticks ({n * timing.TICK_S:g} s)"


def render_timing_table() -> str:
    t = timing
    slot = t.boot_slot_ticks()
    rows = [
        "| what | value |",
        "|---|---|",
        f"| tick | Timer0 overflow, prescaler {t.TIMER0_PRESCALER}, reload "
        f"0x{t.TIMER0_RELOAD:02X}: {256 - t.TIMER0_RELOAD} × 64 µs = {t.TICK_TRUE_S * 1e3:g} ms |",
        f"| IR link (comm UART1) | {wire.BAUD_IR} baud 8N1; one byte "
        f"{t.wire_seconds(1, wire.BAUD_IR) * 1e3:.1f} ms, counted as "
        f"{t.IR_BYTE_TICKS_X10 / 10:g} ticks |",
        f"| board link (UART0) | {wire.BAUD_BOARD} baud 8N1 |",
        f"| debug port (control UART1) | {wire.BAUD_DEBUG} baud 8N1 |",
        f"| PC frame inter-byte time-out | {t.PC_BYTE_TIMEOUT_TICKS} ticks (10 byte times) |",
        f"| control echo time-out | {_ticks(t.CONTROL_ACK_TIMEOUT_TICKS)} → `ACK ~` |",
        f"| handshake bytes | `{chr(wire.LINK_READY)}` id (ready), "
        f"`{chr(wire.LINK_LISTENING)}` id (listening) |",
        f"| handshake | control sends `{chr(wire.LINK_READY)}` id every "
        f"{_ticks(t.HANDSHAKE_RETRY_TICKS)}, at most {t.HANDSHAKE_MAX_TRIES} times; comm waits "
        f"{_ticks(t.HANDSHAKE_TICKS)} for it, and asks after {_ticks(t.HANDSHAKE_PROBE_TICKS)} |",
        f"| board frame inter-byte time-out | {t.BOARD_BYTE_TIMEOUT_TICKS} ticks |",
        f"| boot slot | rank (id − 1) mod {t.BOOT_SLOTS}; slot k starts "
        f"{t.BOOT_FIRST_SLOT_TICKS} + k × {slot} ticks after reset (VERSION {wire.FW_VERSION}; "
        f"{t.IR_BYTE_TICKS_X10 / 10:g} ticks more per extra version character) |",
        f"| `IrSel(side)` hold | back on the centre after {_ticks(t.IRSEL_HOLD_TICKS)} "
        "without an IR byte |",
        f"| ACK slot | {_ticks(t.ACK_SLOT_TICKS)}; ACK/ERR {t.SLOTS_ACK} slot, status "
        f"{t.SLOTS_STATUS}, localization report {t.SLOTS_LOCALIZE} |",
        f"| legacy substrate delay | {_ticks(t.SUBSTRATE_ACK_DELAY_TICKS)} (thesis) |",
        f"| localization window | {_ticks(t.LOC_WINDOW_TICKS)} ({t.LOC_HOPS} hops), "
        "then the answer slots |",
    ]
    return "\n".join(rows)
