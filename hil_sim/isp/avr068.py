"""Constants of the STK500 communication protocol, version 2 (Atmel AVR068).

Only the ISP subset is listed: the HexBot boards are programmed through
their SPI pins, never in parallel or high-voltage serial mode.
"""

from __future__ import annotations

from enum import IntEnum

MESSAGE_START = 0x1B
TOKEN = 0x0E
# Largest message body the STK500 accepts (its receive buffer): a command
# header of 10 bytes plus 256 data bytes, rounded up as in the firmware.
MAX_BODY = 275
SIGN_ON_NAME = b"STK500_2"


class Cmd(IntEnum):
    SIGN_ON = 0x01
    SET_PARAMETER = 0x02
    GET_PARAMETER = 0x03
    SET_DEVICE_PARAMETERS = 0x04
    OSCCAL = 0x05
    LOAD_ADDRESS = 0x06
    FIRMWARE_UPGRADE = 0x07
    ENTER_PROGMODE_ISP = 0x10
    LEAVE_PROGMODE_ISP = 0x11
    CHIP_ERASE_ISP = 0x12
    PROGRAM_FLASH_ISP = 0x13
    READ_FLASH_ISP = 0x14
    PROGRAM_EEPROM_ISP = 0x15
    READ_EEPROM_ISP = 0x16
    PROGRAM_FUSE_ISP = 0x17
    READ_FUSE_ISP = 0x18
    PROGRAM_LOCK_ISP = 0x19
    READ_LOCK_ISP = 0x1A
    READ_SIGNATURE_ISP = 0x1B
    READ_OSCCAL_ISP = 0x1C
    SPI_MULTI = 0x1D


# Not a command: the answer id (and status) of a frame whose checksum failed.
ANSWER_CKSUM_ERROR = 0xB0


class Status(IntEnum):
    CMD_OK = 0x00
    CMD_TOUT = 0x80
    RDY_BSY_TOUT = 0x81
    SET_PARAM_MISSING = 0x82
    CMD_FAILED = 0xC0
    CKSUM_ERROR = 0xC1
    CMD_UNKNOWN = 0xC9


class Param(IntEnum):
    BUILD_NUMBER_LOW = 0x80
    BUILD_NUMBER_HIGH = 0x81
    HW_VER = 0x90
    SW_MAJOR = 0x91
    SW_MINOR = 0x92
    VTARGET = 0x94
    VADJUST = 0x95
    OSC_PSCALE = 0x96
    OSC_CMATCH = 0x97
    SCK_DURATION = 0x98
    TOPCARD_DETECT = 0x9A
    STATUS = 0x9C
    DATA = 0x9D
    RESET_POLARITY = 0x9E
    CONTROLLER_INIT = 0x9F


# Bits of the "mode" byte of CMD_PROGRAM_FLASH_ISP / CMD_PROGRAM_EEPROM_ISP.
MODE_PAGE = 0x01  # 0: word (byte) mode, 1: page mode
MODE_WORD_TIMED = 0x02
MODE_WORD_VALUE_POLL = 0x04
MODE_WORD_RDY_BSY = 0x08
MODE_PAGE_TIMED = 0x10
MODE_PAGE_VALUE_POLL = 0x20
MODE_PAGE_RDY_BSY = 0x40
MODE_WRITE_PAGE = 0x80

# Bit 31 of the address of CMD_LOAD_ADDRESS: issue "load extended address".
LOAD_EXTENDED_ADDRESS = 0x8000_0000
