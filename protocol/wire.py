"""Byte-level constants of the HexBot links (Table 3-8, Appendix A/B).

Baud rates: IR link (comm UART1) 300, board-to-board (UART0) 4800, control
board debug port (UART1) 4800; all 8N1. Ticks, slots and time-outs are in
``timing.py``.
"""

from hexbot.protocol.pins import DIP_SWITCHES

START = ord("*")  # first byte of every message
END = ord("#")  # last byte of PC and board-to-board messages
UNUSED = ord("N")  # filler for unused argument bytes; also the "did nothing" ACK
TIMEOUT = ord("~")  # ACK code when the control board did not echo in 2.5 s

PC_FRAME_LEN = 11  # '*' B1..B9 '#'
PC_ARGS = 8  # B2..B9
BOARD_FRAME_LEN = 7  # '*' code a1..a4 '#'
BOARD_ARGS = 4
LOC_FRAME_LEN = 8  # '*' sX X X sY Y Y S

PREAMBLE = b"\n\r\n\r"  # LF CR LF CR before every reply
EOL = b"\n\r"  # the firmware ends lines LF CR, as the thesis does

# Reply words after the role/id prefix (``M03: ``), then their binary fields.
REPLY_ACK = b"ACK"  # + function code
REPLY_ERR = b"ERR"  # + function code, reason
REPLY_STATUS = b"STA"  # + id, role letter, localized, x, y, yref, last error, schema
REPLY_MSG = b"MSG"  # control board debug port: + the board frame it got (code, 4 args)
# A module that localized itself reports four lines (comm firmware, localize()).
TEXT_LOCALIZED = "LOCALIZED"
LOC_SIDE = b"Side: "  # + the side it heard (1..6)
LOC_YREF = b"Yref: "  # + its orientation (0..5)
LOC_POS = b"Pos: "  # + sXX sYY

BAUD_IR = 300
BAUD_BOARD = 4800
BAUD_DEBUG = 4800

# Handshake between the two boards of a module (UART0), each byte followed
# by the module id: the control board sends READY until the comm board
# answers READY, then LISTENING (thesis, Appendix A).
LINK_READY = ord("R")
LINK_LISTENING = ord("L")

# Boot texts, in the order a module sends them (the PC's parser knows them).
TEXT_COMM_READY = "COMM. BOARD READY"
TEXT_CTR_READY = "CTR. BOARD READY"
TEXT_CTR_LISTENING = "CTR. LISTENING"
TEXT_COMM_LISTENING = "COMM. LISTENING"
#: The texts a module prints while it boots (its comm and control boards').
BOOT_TEXTS = (TEXT_COMM_READY, TEXT_CTR_READY, TEXT_CTR_LISTENING, TEXT_COMM_LISTENING)
BOOT_ID_TAIL = " ID="  # + the id, two or three digits
BOOT_FW_TAIL = " FW="  # + the firmware version
TEXT_RF12_READY = "RF12 READY"  # the RF12 wireless board's boot text (its UART1)
TEXT_RF12_LINK_READY = "RF12 LINK READY"  # the radio-link bridge's boot text (its UART1)
TEXT_RF12_RX_START = "START"  # the RF12 receive test: START, payload, sum matched 1/0
#: MAVLink component id of a module's messages: its communication board.
MAV_COMPONENT_COMM = 1

#: A module id is its control board's 8 DIP switches (PC0..PC7): 1..255, 0 =
#: no switch on. The legacy Select frame addresses 1..63 only (the thesis'
#: frame; 'N' = 78 fills its unused bytes); MAVLink frames address every id.
MAX_MODULE_ID = (1 << DIP_SWITCHES) - 1
MAX_SELECT_ID = 63
#: Ids are printed in decimal with at least two digits ("ID=07", "M07: "),
#: so ids 1..99 keep the thesis' bytes and 100..255 take a third digit.
ID_MIN_DIGITS = 2
ID_MAX_DIGITS = len(str(MAX_MODULE_ID))
LOC_COORD_LIMIT = 99  # MSG1 carries two decimal digits per coordinate

FUSE_LOW = 0x62  # Table 3-6: internal RC 8 MHz, CKDIV8 -> 1 MHz
FUSE_HIGH = 0xD9  # JTAG off, SPIEN on, BOOTSZ=00
FUSE_EXTENDED = 0xFF  # BOD off
SIGNATURE = bytes((0x1E, 0x94, 0x04))  # ATmega162
FLASH_BYTES = 16 * 1024  # ATmega162: 16 KiB of program flash
#: The version string the firmware is built with unless ``make VERSION=...``
#: says otherwise; its length sets the boot slots (protocol/timing.py).
FW_VERSION = "0.1.0"
F_CPU = 1_000_000
