"""Generate ``firmware/include/hexbot_codes.h`` from the protocol.

The firmware includes only this header for codes, argument ranges, wire
constants, timing, Table 4-1, error reasons and fuse values (pins come from
``hexbot_pins.h``, see ``pins_header.py``); a test fails when a checked-in
copy is stale (regenerate with ``hexbot gen-header``).

The schema hash covers every value of both headers: the comm firmware
reports it in its Status reply, so the PC can tell firmware built from
another protocol (``schema_mismatch``).
"""

from __future__ import annotations

import hashlib
import re
from pathlib import Path

from hexbot.protocol import image_mark, lattice, pins_header, radio, timing, wire
from hexbot.protocol.codes import CODES, ErrorCode, Role, Status

HEADER_PATH = Path(__file__).resolve().parent.parent / "firmware" / "include" / "hexbot_codes.h"
#: The build's defaults, included by firmware/Makefile.
MAKE_PATH = HEADER_PATH.with_name("hexbot.mk")
SCHEMA_LINE = "@SCHEMA@"


def _c_string(text: str | bytes) -> str:
    if isinstance(text, bytes):
        text = text.decode("ascii")
    escaped = text.replace("\\", "\\\\").replace('"', '\\"')
    return '"' + escaped.replace("\n", "\\n").replace("\r", "\\r") + '"'


def _offsets() -> list[lattice.Cell]:
    return [lattice.SIDE_OFFSETS[s] for s in lattice.SIDES]


def _timing() -> list[str]:
    t = timing
    return [
        "/* Timing (protocol/timing.py). A tick is Timer0 at F_CPU / 64 reloaded with",
        " * HB_TICK_RELOAD: 156 x 64 us = 9.984 ms, the thesis' 10 ms. */",
        f"#define HB_F_CPU            {wire.F_CPU}UL",
        f"#define HB_TICK_RELOAD      0x{t.TIMER0_RELOAD:02X}u",
        "/* Ticks of one 300-baud byte, x10 and rounded up */",
        f"#define HB_IR_BYTE_TICKS_X10 {t.IR_BYTE_TICKS_X10}u",
        "#define HB_IR_TICKS(bytes)  (((bytes) * HB_IR_BYTE_TICKS_X10 + 9u) / 10u)",
        f"#define HB_CONTROL_ACK_TIMEOUT_TICKS {t.CONTROL_ACK_TIMEOUT_TICKS}u",
        f"#define HB_SUBSTRATE_ACK_DELAY_TICKS {t.SUBSTRATE_ACK_DELAY_TICKS}u",
        f"#define HB_ACK_SLOT_TICKS   {t.ACK_SLOT_TICKS}u",
        f"#define HB_PC_BYTE_TIMEOUT_TICKS {t.PC_BYTE_TIMEOUT_TICKS}u",
        "/* The boards' handshake and link */",
        f"#define HB_HANDSHAKE_TICKS  {t.HANDSHAKE_TICKS}u",
        f"#define HB_HANDSHAKE_RETRY_TICKS {t.HANDSHAKE_RETRY_TICKS}u",
        f"#define HB_HANDSHAKE_MAX_TRIES {t.HANDSHAKE_MAX_TRIES}u",
        f"#define HB_HANDSHAKE_PROBE_TICKS {t.HANDSHAKE_PROBE_TICKS}u",
        f"#define HB_LINK_ID_TICKS    {t.LINK_ID_TICKS}u",
        f"#define HB_BOARD_BYTE_TIMEOUT_TICKS {t.BOARD_BYTE_TIMEOUT_TICKS}u",
        f"#define HB_IRSEL_HOLD_TICKS {t.IRSEL_HOLD_TICKS}u",
        f"#define HB_YREF_BLINK_TICKS {t.YREF_BLINK_TICKS}u",
        f"#define HB_REF_SHOWS        {t.REF_SHOWS}u",
        "/* Longest replies in addressed mode (preamble, 'M255: ', body) and their slots */",
        f"#define HB_REPLY_BYTES_ACK  {t.REPLY_BYTES_ACK}u",
        f"#define HB_REPLY_BYTES_ERR  {t.REPLY_BYTES_ERR}u",
        f"#define HB_REPLY_BYTES_STATUS {t.REPLY_BYTES_STATUS}u",
        f"#define HB_REPLY_BYTES_LOCALIZE {t.REPLY_BYTES_LOCALIZE}u",
        f"#define HB_SLOTS_ACK        {t.SLOTS_ACK}u",
        f"#define HB_SLOTS_STATUS     {t.SLOTS_STATUS}u",
        f"#define HB_SLOTS_LOCALIZE   {t.SLOTS_LOCALIZE}u",
        "/* Boot slots: rank (id - 1) mod HB_BOOT_SLOTS; the slot text is",
        " * HB_BOOT_TEXT_FIXED_BYTES + the length of the version string. */",
        f"#define HB_BOOT_SLOTS       {t.BOOT_SLOTS}u",
        f"#define HB_BOOT_FIRST_SLOT_TICKS {t.BOOT_FIRST_SLOT_TICKS}u",
        f"#define HB_BOOT_GUARD_TICKS {t.BOOT_GUARD_TICKS}u",
        f"#define HB_BOOT_TEXT_FIXED_BYTES {t.BOOT_TEXT_FIXED_BYTES}u",
        "#define HB_BOOT_SLOT_TICKS(text_bytes) (HB_IR_TICKS(text_bytes) + HB_BOOT_GUARD_TICKS)",
        "/* Localization (code 66) */",
        f"#define HB_LOC_LISTEN_TICKS {t.LOC_LISTEN_TICKS}u",
        f"#define HB_LOC_CATCH_TICKS  {t.LOC_CATCH_TICKS}u",
        f"#define HB_LOC_DWELL_TICKS  {t.LOC_DWELL_TICKS}u",
        f"#define HB_LOC_HOPS         {t.LOC_HOPS}u",
        f"#define HB_LOC_WINDOW_TICKS {t.LOC_WINDOW_TICKS}u",
        "",
        "/* Handshake between the boards, each byte followed by the module id */",
        f"#define HB_LINK_READY       {wire.LINK_READY}  /* '{chr(wire.LINK_READY)}' */",
        f"#define HB_LINK_LISTENING   {wire.LINK_LISTENING}  /* '{chr(wire.LINK_LISTENING)}' */",
        "/* Boot texts */",
        f"#define HB_TEXT_COMM_READY  {_c_string(wire.TEXT_COMM_READY)}",
        f"#define HB_TEXT_CTR_READY   {_c_string(wire.TEXT_CTR_READY)}",
        f"#define HB_TEXT_CTR_LISTENING {_c_string(wire.TEXT_CTR_LISTENING)}",
        f"#define HB_TEXT_COMM_LISTENING {_c_string(wire.TEXT_COMM_LISTENING)}",
        f"#define HB_TEXT_ID_TAIL     {_c_string(wire.BOOT_ID_TAIL)}",
        f"#define HB_TEXT_FW_TAIL     {_c_string(wire.BOOT_FW_TAIL)}",
        f"#define HB_TEXT_RF12_READY  {_c_string(wire.TEXT_RF12_READY)}",
        f"#define HB_TEXT_RF12_LINK_READY {_c_string(wire.TEXT_RF12_LINK_READY)}",
        f"#define HB_TEXT_RF12_RX_START {_c_string(wire.TEXT_RF12_RX_START)}",
        f"#define HB_MAV_COMPONENT_COMM {wire.MAV_COMPONENT_COMM}u",
        "/* Replies: preamble, line end, reply words, the localization report */",
        f"#define HB_PREAMBLE         {_c_string(wire.PREAMBLE)}",
        f"#define HB_EOL              {_c_string(wire.EOL)}",
        f"#define HB_REPLY_ACK        {_c_string(wire.REPLY_ACK)}",
        f"#define HB_REPLY_ERR        {_c_string(wire.REPLY_ERR)}",
        f"#define HB_REPLY_STATUS     {_c_string(wire.REPLY_STATUS)}",
        f"#define HB_REPLY_MSG        {_c_string(wire.REPLY_MSG)}",
        f"#define HB_TEXT_LOCALIZED   {_c_string(wire.TEXT_LOCALIZED)}",
        f"#define HB_LOC_SIDE         {_c_string(wire.LOC_SIDE)}",
        f"#define HB_LOC_YREF         {_c_string(wire.LOC_YREF)}",
        f"#define HB_LOC_POS          {_c_string(wire.LOC_POS)}",
        "",
        "/* Table 4-1: neighbour offset of global side 1..6 (index side - 1) */",
        f"#define HB_SIDE_DX {{{', '.join(str(dx) for dx, _ in _offsets())}}}",
        f"#define HB_SIDE_DY {{{', '.join(str(dy) for _, dy in _offsets())}}}",
        "",
    ]


def _render(schema: str) -> str:
    lines = [
        "/* hexbot_codes.h - GENERATED by `hexbot gen-header` from protocol/codes.py.",
        " * Do not edit: change the table and regenerate (a test checks this file).",
        " */",
        "#ifndef HEXBOT_CODES_H",
        "#define HEXBOT_CODES_H",
        "",
        schema,
        "/* What an image is, in its flash (protocol/image_mark.py): every image",
        " * defines one, HB_IMAGE_MARK(\"comm\") and so on */",
        image_mark.c_macro(),
        "",
        "/* Wire constants (Table 3-8, Appendix A) */",
        f"#define HB_START            {wire.START}  /* '*' */",
        f"#define HB_END              {wire.END}  /* '#' */",
        f"#define HB_UNUSED           {wire.UNUSED}  /* 'N' */",
        f"#define HB_TIMEOUT          {wire.TIMEOUT} /* '~' */",
        f"#define HB_PC_FRAME_LEN     {wire.PC_FRAME_LEN}",
        f"#define HB_PC_ARGS          {wire.PC_ARGS}",
        f"#define HB_BOARD_FRAME_LEN  {wire.BOARD_FRAME_LEN}",
        f"#define HB_BOARD_ARGS       {wire.BOARD_ARGS}",
        f"#define HB_LOC_FRAME_LEN    {wire.LOC_FRAME_LEN}",
        "/* UBRR of each link at F_CPU (protocol/timing.py ubrr: rounded to nearest) */",
        f"#define HB_UBRR_IR          {timing.ubrr(wire.BAUD_IR)}u",
        f"#define HB_UBRR_BOARD       {timing.ubrr(wire.BAUD_BOARD)}u",
        f"#define HB_UBRR_DEBUG       {timing.ubrr(wire.BAUD_DEBUG)}u",
        f"#define HB_MAX_MODULE_ID    {wire.MAX_MODULE_ID}",
        f"#define HB_ID_MAX_DIGITS    {wire.ID_MAX_DIGITS}u",
        f"#define HB_MAX_SELECT_ID    {wire.MAX_SELECT_ID}",
        f"#define HB_LOC_COORD_LIMIT  {wire.LOC_COORD_LIMIT}",
        "",
        "/* RF12 radio (protocol/radio.py): the listing's channel words and packet;",
        " * the first payload byte counts the link bytes after it */",
        f"#define HB_RF12_CMD_CONFIG  0x{radio.CMD_CONFIG:04X}u",
        f"#define HB_RF12_CMD_FREQ    0x{radio.CMD_FREQUENCY:04X}u",
        f"#define HB_RF12_CMD_RATE    0x{radio.CMD_DATA_RATE:04X}u",
        f"#define HB_RF12_CMD_SYNC    0x{radio.CMD_SYNC_LOW:04X}u",
        f"#define HB_RF12_PAYLOAD     {radio.PAYLOAD}u",
        "/* a packet: preamble and sync, the payload, its checksum, the trailer */",
        f"#define HB_RF12_HEAD {{{', '.join(f'0x{b:02X}' for b in radio.PREAMBLE + radio.SYNC)}}}",
        f"#define HB_RF12_TRAILER {{{', '.join(f'0x{b:02X}' for b in radio.TRAILER)}}}",
        f"#define HB_RF12_LINK_BYTES  {radio.LINK_BYTES}u",
        "",
        "/* Fuses (Table 3-6) and part */",
        f"#define HB_FUSE_LOW      0x{wire.FUSE_LOW:02X}",
        f"#define HB_FUSE_HIGH     0x{wire.FUSE_HIGH:02X}",
        f"#define HB_FUSE_EXTENDED 0x{wire.FUSE_EXTENDED:02X}",
        "",
        *_timing(),
        "/* Function codes (Table 3-7 and extensions) */",
    ]
    for fn in CODES.values():
        if fn.status in (Status.USED, Status.EXTENSION):
            args = ", ".join(f"{a.name} {a.lo}..{a.hi}" for a in fn.args) or "-"
            tag = " [ext]" if fn.status is Status.EXTENSION else ""
            lines.append(f"#define {fn.c_name:<22} {fn.code:3d}  /* {fn.comment}; {args}{tag} */")
    lines += [
        "",
        "/* Boards */",
        "#define HB_BOARD_NONE    0",
        "#define HB_BOARD_CONTROL 1",
        "#define HB_BOARD_COMM    2",
        "",
        "/* X-macro over every executable function: X(code, board, nargs). Expand it",
        " * into the dispatch table so that the firmware never repeats the table. */",
        "#define HB_FUNCTIONS(X) \\",
    ]
    boards = {"control": "HB_BOARD_CONTROL", "comm": "HB_BOARD_COMM", "none": "HB_BOARD_NONE"}
    for fn in CODES.values():
        if fn.executable:
            lines.append(f"    X({fn.c_name}, {boards[fn.board.value]}, {len(fn.args)}) \\")
    lines += [
        "",
        "/* X-macro over argument ranges narrower than a byte: X(code, arg, lo, hi),",
        " * arg counted from 1; the firmware's range checks expand it. */",
        "#define HB_ARG_RANGES(X) \\",
    ]
    for fn in CODES.values():
        if fn.executable:
            for i, a in enumerate(fn.args):
                if (a.lo, a.hi) != (0, 255):
                    lines.append(f"    X({fn.c_name}, {i + 1}, {a.lo}, {a.hi}) \\")
    lines += ["", "/* Argument ranges */"]
    seen: set[str] = set()
    for fn in CODES.values():
        if not fn.executable:
            continue
        for i, a in enumerate(fn.args):
            key = f"{fn.c_name}_ARG{i + 1}"
            if key in seen:
                continue
            seen.add(key)
            lines.append(f"#define {key}_MIN {a.lo}")
            lines.append(f"#define {key}_MAX {a.hi}")
    lines += ["", "/* Error reasons of ERR replies and of the status' last error */"]
    for e in ErrorCode:
        lines.append(f"#define HB_ERR_{e.name:<18} {e.value}")
    lines += ["", "/* Roles */"]
    for r in Role:
        lines.append(f"#define HB_ROLE_{r.name:<10} {r.value}  /* '{r.letter}' */")
    for r in Role:  # as the replies spell them (the prefix, the status' role byte)
        lines.append(f"#define HB_ROLE_LETTER_{r.name:<10} '{r.letter}'")
    lines += ["", "#endif /* HEXBOT_CODES_H */", ""]
    return "\n".join(lines)


def _values(text: str) -> list[str]:
    """A header without comments or spacing: what the firmware is built
    from, not how the file is laid out."""
    code = re.sub(r"/\*.*?\*/", "", text, flags=re.S)
    return [" ".join(line.split()) for line in code.splitlines() if line.strip()]


def schema_hash() -> str:
    """Eight hex digits over every value of hexbot_codes.h and hexbot_pins.h."""
    h = hashlib.sha256()
    for line in _values(_render(SCHEMA_LINE)) + _values(pins_header.render()):
        h.update(line.encode() + b"\n")
    return h.hexdigest()[:8]


#: The schema of this host's protocol, as the firmware reports it in Status.
SCHEMA_HASH = int(schema_hash(), 16)


def schema_mismatch(reported: int | None) -> str | None:
    """A one-line warning when a module's firmware was built from another
    protocol than this host's; None when the schemas agree. ``reported`` is
    ``StatusReport.schema`` (None: firmware too old to report one)."""
    if reported is None:
        return (f"module firmware reports no protocol schema (older build); this host "
                f"speaks schema {SCHEMA_HASH:08x}: rebuild and flash the firmware")
    if reported != SCHEMA_HASH:
        return (f"module firmware speaks protocol schema {reported:08x}, this host "
                f"{SCHEMA_HASH:08x}: rebuild and flash the firmware, or update the host")
    return None


def render() -> str:
    h = schema_hash()
    return _render(f"#define HB_SCHEMA_HASH 0x{h}UL\n#define HB_SCHEMA_HASH_TEXT \"{h}\"")


def render_make() -> str:
    """firmware/include/hexbot.mk: the clock and the default version string,
    so that the Makefile does not retype them."""
    return "\n".join([
        "# Generated by `hexbot gen-header` from protocol/wire.py. Do not edit.",
        f"F_CPU    := {wire.F_CPU}UL",
        f"VERSION  ?= {wire.FW_VERSION}",
        "",
    ])
