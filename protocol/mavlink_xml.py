"""Render ``protocol/hexbot.xml``, the MAVLink 2 dialect of the PC <-> module
link, from the function table (``codes.py``): one source, so the enums of
the dialect are the table's codes, error reasons and roles.

The messages carry what the legacy frames and replies carry (see
docs/protocol.md, "MAVLink 2 framing"). Every field is one byte wide except
the schema hash, so MAVLink's reordering by type size keeps the declared
order; fields that are usually zero come last, because MAVLink 2 drops
trailing zero bytes of a payload on the wire.
"""

from __future__ import annotations

from pathlib import Path
from xml.sax.saxutils import escape

from hexbot.protocol.codes import CODES, ErrorCode, Role
from hexbot.protocol.wire import MAX_MODULE_ID

XML_PATH = Path(__file__).resolve().parent / "hexbot.xml"
DIALECT = "hexbot"
#: MAVLink's own minimal dialect (HEARTBEAT, MAV_TYPE...), which tools such
#: as mavutil and mavlogdump.py expect of any dialect; a copy of pymavlink's
#: sits beside ours so that mavgen finds the include.
MINIMAL = "minimal.xml"
MINIMAL_PATH = XML_PATH.parent / MINIMAL


def render_minimal() -> str:
    """pymavlink's minimal.xml, as our include."""
    import pymavlink

    return (Path(pymavlink.__file__).parent / "dialects" / "v20" / MINIMAL).read_text()

#: Message ids: a block of our own, far from common.xml's.
MSG_COMMAND = 14000
MSG_ACK = 14001
MSG_STATUS = 14002
MSG_LOCALIZED = 14003

#: HEXBOT_RESULT: how a module answered a command (the legacy ACK/ERR forms).
RESULTS = (
    ("DONE", "The function ran (legacy ACK with the command's code)."),
    ("ERROR", "Refused with an error reason in field error (legacy ERR)."),
    ("UNUSED_CODE", "The code names no function; nothing done (legacy ACK 'N')."),
    ("CONTROL_TIMEOUT", "The control board did not echo within 2.5 s (legacy ACK '~')."),
)


def _enum(name: str, description: str, entries: list[tuple[str, int, str]]) -> list[str]:
    lines = [f'    <enum name="{name}">', f"      <description>{escape(description)}</description>"]
    for entry, value, text in entries:
        lines.append(f'      <entry value="{value}" name="{name}_{entry}">')
        lines.append(f"        <description>{escape(text)}</description>")
        lines.append("      </entry>")
    lines.append("    </enum>")
    return lines


def _function_entries() -> list[tuple[str, int, str]]:
    out = []
    for fn in CODES.values():
        if fn.executable:
            out.append((fn.c_name.removeprefix("HB_FN_"), fn.code,
                        f"{fn.signature()}: {fn.comment} ({fn.board.value} board)."))
    return out


def _field(ftype: str, name: str, text: str, enum: str | None = None) -> str:
    attr = f' enum="{enum}"' if enum else ""
    return f'      <field type="{ftype}" name="{name}"{attr}>{escape(text)}</field>'


def _messages() -> list[str]:
    fn, res, err, role = "HEXBOT_FUNCTION", "HEXBOT_RESULT", "HEXBOT_ERROR", "HEXBOT_ROLE"
    messages = [
        (MSG_COMMAND, "HEXBOT_COMMAND",
         "PC to module: run a function of the table (legacy frame '*' B1..B9 '#').", [
             _field("uint8_t", "target_system",
                    f"Module id (DIP switches, 1..{MAX_MODULE_ID}); 0 = the modules the last "
                    "Select chose (all after Select(0)), as a legacy frame."),
             _field("uint8_t", "code", "Function code (B1).", fn),
             _field("uint8_t[8]", "args", "Argument bytes B2..B9; unused ones 0."),
         ]),
        (MSG_ACK, "HEXBOT_ACK", "Module to PC: the answer to one HEXBOT_COMMAND.", [
            _field("uint8_t", "code", "Code of the command answered.", fn),
            _field("uint8_t", "role", "The module's role.", role),
            _field("uint8_t", "result", "What happened.", res),
            _field("uint8_t", "error", "Error reason when result is ERROR.", err),
        ]),
        (MSG_STATUS, "HEXBOT_STATUS", "Module to PC: answer to Status (code 70).", [
            _field("uint32_t", "schema",
                   "Protocol schema hash the firmware was built from (HB_SCHEMA_HASH)."),
            _field("uint8_t", "role", "The module's role.", role),
            _field("uint8_t", "localized", "1 when x, y and yref are known."),
            _field("int8_t", "x", "Cell x (Table 4-1 coordinates)."),
            _field("int8_t", "y", "Cell y."),
            _field("uint8_t", "yref", "Orientation 0..5: global side = body side + yref."),
            _field("uint8_t", "error", "Last error.", err),
            _field("uint8_t", "crc_errors",
                   "MAVLink frames dropped for a bad checksum since boot (saturates at 255)."),
        ]),
        (MSG_LOCALIZED, "HEXBOT_LOCALIZED",
         "Module to PC: localization learned (legacy LOCALIZED, Side, Yref, Pos lines).", [
             _field("uint8_t", "side", "Global side 1..6 the neighbour's message came through."),
             _field("uint8_t", "yref", "Orientation 0..5."),
             _field("int8_t", "x", "Cell x."),
             _field("int8_t", "y", "Cell y."),
         ]),
    ]
    lines = ["  <messages>"]
    for ident, name, text, fields in messages:
        lines.append(f'    <message id="{ident}" name="{name}">')
        lines.append(f"      <description>{escape(text)}</description>")
        lines.extend(fields)
        lines.append("    </message>")
    lines.append("  </messages>")
    return lines


def render() -> str:
    lines = [
        '<?xml version="1.0"?>',
        "<!-- GENERATED by `hexbot gen-header` from protocol/codes.py and",
        "     protocol/mavlink_xml.py. Do not edit: a test checks this file. -->",
        "<mavlink>",
        f"  <include>{MINIMAL}</include>",
        "  <version>1</version>",
        "  <dialect>0</dialect>",
        "  <enums>",
        *_enum("HEXBOT_FUNCTION", "Function codes of Table 3-7 and our extensions.",
               _function_entries()),
        *_enum("HEXBOT_RESULT", "How a module answered a command.",
               [(name, i, text) for i, (name, text) in enumerate(RESULTS)]),
        *_enum("HEXBOT_ERROR", "Error reasons (legacy ERR reason byte).",
               [(e.name, e.value, e.name.replace("_", " ").lower()) for e in ErrorCode]),
        *_enum("HEXBOT_ROLE", "Role of a module in combined rotations.",
               [(r.name, r.value, f"'{r.letter}'") for r in Role]),
        "  </enums>",
        *_messages(),
        "</mavlink>",
        "",
    ]
    return "\n".join(lines)
