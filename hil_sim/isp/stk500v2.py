"""An STK500 in STK500v2 mode (Atmel AVR068), as a pure protocol object.

``Stk500v2Programmer.feed(bytes) -> bytes`` takes what the host sends and
returns what the programmer answers; nothing here does I/O or keeps time, so
the whole protocol is tested without a port. Like the real programmer it
turns each ISP command into SPI instructions whose opcodes come in the
command itself (the host knows the part; the programmer does not), and it
drives them into an :class:`~hexbot.hil_sim.isp.chip.IspTarget`.

Bad input never raises: a frame with a wrong checksum is answered with
ANSWER_CKSUM_ERROR, a command too short for its fields or with impossible
values with STATUS_CMD_FAILED, an unknown command with STATUS_CMD_UNKNOWN.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

from hexbot.hil_sim.isp.avr068 import (
    ANSWER_CKSUM_ERROR,
    LOAD_EXTENDED_ADDRESS,
    MODE_PAGE,
    MODE_WRITE_PAGE,
    SIGN_ON_NAME,
    Cmd,
    Param,
    Status,
)
from hexbot.hil_sim.isp.chip import IspTarget
from hexbot.hil_sim.isp.framing import FrameDecoder, Message, encode

OK, FAILED = Status.CMD_OK, Status.CMD_FAILED
MAX_DATA = 256  # data bytes one read/program command may carry (STK500 buffer)
POLL_LIMIT = 32  # RDY/BSY or value polls before giving up
# How to wait for a write: the three bits of the mode byte for word mode
# (bits 1..3) or page mode (bits 4..6), shifted down.
WAIT_VALUE_POLL = 0x02
WAIT_RDY_BSY = 0x04

# Values an STK500 with firmware 2.10 reports; the read-only ones refuse writes.
DEFAULT_PARAMS: dict[int, int] = {
    Param.BUILD_NUMBER_LOW: 0x00,
    Param.BUILD_NUMBER_HIGH: 0x00,
    Param.HW_VER: 0x02,
    Param.SW_MAJOR: 0x02,
    Param.SW_MINOR: 0x0A,
    Param.VTARGET: 50,  # 5.0 V, in tenths of a volt
    Param.VADJUST: 50,
    Param.OSC_PSCALE: 0x02,
    Param.OSC_CMATCH: 0x01,
    Param.SCK_DURATION: 0x02,
    Param.TOPCARD_DETECT: 0xFF,  # no top card
    Param.STATUS: 0x00,
    Param.DATA: 0x00,
    Param.RESET_POLARITY: 0x01,
    Param.CONTROLLER_INIT: 0x00,
}
READ_ONLY = {
    Param.BUILD_NUMBER_LOW, Param.BUILD_NUMBER_HIGH, Param.HW_VER,
    Param.SW_MAJOR, Param.SW_MINOR, Param.TOPCARD_DETECT,
}

# Minimum body length of each command (command byte included).
MIN_LENGTH: dict[int, int] = {
    Cmd.SIGN_ON: 1, Cmd.SET_PARAMETER: 3, Cmd.GET_PARAMETER: 2,
    Cmd.SET_DEVICE_PARAMETERS: 1, Cmd.OSCCAL: 1, Cmd.LOAD_ADDRESS: 5,
    Cmd.FIRMWARE_UPGRADE: 1, Cmd.ENTER_PROGMODE_ISP: 12, Cmd.LEAVE_PROGMODE_ISP: 3,
    Cmd.CHIP_ERASE_ISP: 7, Cmd.PROGRAM_FLASH_ISP: 10, Cmd.READ_FLASH_ISP: 4,
    Cmd.PROGRAM_EEPROM_ISP: 10, Cmd.READ_EEPROM_ISP: 4, Cmd.PROGRAM_FUSE_ISP: 5,
    Cmd.READ_FUSE_ISP: 6, Cmd.PROGRAM_LOCK_ISP: 5, Cmd.READ_LOCK_ISP: 6,
    Cmd.READ_SIGNATURE_ISP: 6, Cmd.READ_OSCCAL_ISP: 6, Cmd.SPI_MULTI: 4,
}


@dataclass
class ProgrammerStats:
    frames: int = 0
    checksum_errors: int = 0
    failed: int = 0
    unknown: int = 0
    spi_bytes: int = 0


@dataclass
class Stk500v2Programmer:
    target: IspTarget
    params: dict[int, int] = field(default_factory=lambda: dict(DEFAULT_PARAMS))
    stats: ProgrammerStats = field(default_factory=ProgrammerStats)

    def __post_init__(self) -> None:
        self.decoder = FrameDecoder()
        self.address = 0  # word address for flash, byte address for EEPROM
        self.extended = False
        self.progmode = False
        self._handlers: dict[int, Callable[[bytes], bytes]] = {
            Cmd.SIGN_ON: self._sign_on,
            Cmd.SET_PARAMETER: self._set_parameter,
            Cmd.GET_PARAMETER: self._get_parameter,
            Cmd.SET_DEVICE_PARAMETERS: lambda b: bytes((b[0], OK)),  # obsolete, accepted
            Cmd.OSCCAL: lambda b: bytes((b[0], FAILED)),  # no oscillator to calibrate
            Cmd.LOAD_ADDRESS: self._load_address,
            Cmd.FIRMWARE_UPGRADE: lambda b: bytes((b[0], FAILED)),  # never leaves ISP
            Cmd.ENTER_PROGMODE_ISP: self._enter_progmode,
            Cmd.LEAVE_PROGMODE_ISP: self._leave_progmode,
            Cmd.CHIP_ERASE_ISP: self._chip_erase,
            Cmd.PROGRAM_FLASH_ISP: lambda b: self._program_memory(b, flash=True),
            Cmd.READ_FLASH_ISP: lambda b: self._read_memory(b, flash=True),
            Cmd.PROGRAM_EEPROM_ISP: lambda b: self._program_memory(b, flash=False),
            Cmd.READ_EEPROM_ISP: lambda b: self._read_memory(b, flash=False),
            Cmd.PROGRAM_FUSE_ISP: self._program_byte,
            Cmd.PROGRAM_LOCK_ISP: self._program_byte,
            Cmd.READ_FUSE_ISP: self._read_byte,
            Cmd.READ_LOCK_ISP: self._read_byte,
            Cmd.READ_SIGNATURE_ISP: self._read_byte,
            Cmd.READ_OSCCAL_ISP: self._read_byte,
            Cmd.SPI_MULTI: self._spi_multi,
        }

    # -- transport ----------------------------------------------------------
    def feed(self, data: bytes) -> bytes:
        """Bytes from the host in, the programmer's answer bytes out."""
        out = bytearray()
        for message in self.decoder.feed(data):
            out += encode(message.seq, self.answer(message))
        return bytes(out)

    def receive_timeout(self) -> None:
        """The host went quiet in the middle of a frame: drop it, as the
        programmer's receive time-out does."""
        self.decoder.reset()

    def answer(self, message: Message) -> bytes:
        self.stats.frames += 1
        if not message.checksum_ok:
            self.stats.checksum_errors += 1
            # AVR068 5.5.1: answer id and status are both ANSWER_CKSUM_ERROR.
            return bytes((ANSWER_CKSUM_ERROR, ANSWER_CKSUM_ERROR))
        return self.execute(message.body)

    def execute(self, body: bytes) -> bytes:
        """Run one command body; return the answer body."""
        cmd = body[0]
        handler = self._handlers.get(cmd)
        if handler is None:
            self.stats.unknown += 1
            return bytes((cmd, Status.CMD_UNKNOWN))
        if len(body) < MIN_LENGTH[cmd]:
            self.stats.failed += 1
            return bytes((cmd, FAILED))
        answer = handler(body)
        if answer[1] != OK:
            self.stats.failed += 1
        return answer

    # -- SPI helpers --------------------------------------------------------
    def _spi(self, data: bytes | list[int]) -> bytes:
        self.stats.spi_bytes += len(data)
        return bytes(self.target.transfer(b) for b in data)

    def _wait_ready(self) -> bool:
        for _ in range(POLL_LIMIT):
            if not self._spi((0xF0, 0x00, 0x00, 0x00))[3] & 0x01:
                return True
        return False

    # -- general commands ---------------------------------------------------
    def _sign_on(self, body: bytes) -> bytes:
        return bytes((body[0], OK, len(SIGN_ON_NAME))) + SIGN_ON_NAME

    def _set_parameter(self, body: bytes) -> bytes:
        param, value = body[1], body[2]
        if param not in self.params or param in READ_ONLY:
            return bytes((body[0], FAILED))
        self.params[param] = value
        return bytes((body[0], OK))

    def _get_parameter(self, body: bytes) -> bytes:
        param = body[1]
        if param not in self.params:
            return bytes((body[0], FAILED))
        return bytes((body[0], OK, self.params[param]))

    def _load_address(self, body: bytes) -> bytes:
        value = int.from_bytes(body[1:5], "big")
        self.extended = bool(value & LOAD_EXTENDED_ADDRESS)
        self.address = value & ~LOAD_EXTENDED_ADDRESS
        if self.extended:  # "Load Extended Address" for parts above 64 K words
            self._spi((0x4D, 0x00, (self.address >> 16) & 0xFF, 0x00))
        return bytes((body[0], OK))

    # -- ISP commands -------------------------------------------------------
    def _enter_progmode(self, body: bytes) -> bytes:
        synch_loops, poll_value, poll_index = body[4], body[6], body[7]
        instruction = body[8:12]
        if poll_index > 4:
            return bytes((body[0], FAILED))
        self.target.set_reset(True)
        for _ in range(max(1, synch_loops)):
            reply = self._spi(instruction)
            if poll_index == 0 or reply[poll_index - 1] == poll_value:
                self.progmode = True
                return bytes((body[0], OK))
            # Out of step (or nobody there): pulse RESET and try again.
            self.target.set_reset(False)
            self.target.set_reset(True)
        self.target.set_reset(False)
        self.progmode = False
        return bytes((body[0], FAILED))

    def _leave_progmode(self, body: bytes) -> bytes:
        self.target.set_reset(False)
        self.progmode = False
        return bytes((body[0], OK))

    def _chip_erase(self, body: bytes) -> bytes:
        poll_method = body[2]
        self._spi(body[3:7])
        if poll_method == 1 and not self._wait_ready():
            return bytes((body[0], Status.RDY_BSY_TOUT))
        return bytes((body[0], OK))

    def _program_memory(self, body: bytes, *, flash: bool) -> bytes:
        count = int.from_bytes(body[1:3], "big")
        mode, cmd1, cmd2, cmd3, poll1 = body[3], body[5], body[6], body[7], body[8]
        data = body[10:]
        if count > MAX_DATA or len(data) != count:
            return bytes((body[0], FAILED))
        start = self.address
        paged = bool(mode & MODE_PAGE)
        poll_ok = True
        for i, value in enumerate(data):
            high = flash and i % 2 == 1
            addr = self.address
            self._spi((cmd1 | (0x08 if high else 0), (addr >> 8) & 0xFF, addr & 0xFF, value))
            if not paged:  # word mode: each write completes on its own
                poll_ok &= self._wait_write((mode >> 1) & 7, cmd3 | (0x08 if high else 0),
                                            addr, value, poll1)
            if not flash or high:
                self.address += 1
        if paged and mode & MODE_WRITE_PAGE:
            self._spi((cmd2, (start >> 8) & 0xFF, start & 0xFF, 0x00))
            poll_ok &= self._wait_write((mode >> 4) & 7, cmd3, start, data[0] if data else 0, poll1)
        if not poll_ok:
            return bytes((body[0], Status.RDY_BSY_TOUT))
        return bytes((body[0], OK))

    def _wait_write(self, kind: int, read_cmd: int, addr: int, value: int, poll1: int) -> bool:
        """Wait for a write as the mode bits ask: timed delay (nothing to do
        in simulated time), data polling, or RDY/BSY polling."""
        if kind & WAIT_RDY_BSY:
            return self._wait_ready()
        if kind & WAIT_VALUE_POLL:
            if value == poll1:
                return True  # this value cannot be told from "busy": timed wait
            for _ in range(POLL_LIMIT):
                if self._spi((read_cmd, (addr >> 8) & 0xFF, addr & 0xFF, 0))[3] != poll1:
                    return True
            return False
        return True

    def _read_memory(self, body: bytes, *, flash: bool) -> bytes:
        count = int.from_bytes(body[1:3], "big")
        cmd1 = body[3]
        if count > MAX_DATA:
            return bytes((body[0], FAILED))
        data = bytearray()
        for i in range(count):
            high = flash and i % 2 == 1
            addr = self.address
            data.append(self._spi((cmd1 | (0x08 if high else 0), (addr >> 8) & 0xFF,
                                   addr & 0xFF, 0x00))[3])
            if not flash or high:
                self.address += 1
        return bytes((body[0], OK)) + bytes(data) + bytes((OK,))

    def _program_byte(self, body: bytes) -> bytes:
        self._spi(body[1:5])
        return bytes((body[0], OK, OK))

    def _read_byte(self, body: bytes) -> bytes:
        ret_addr = body[1]
        if not 1 <= ret_addr <= 4:
            return bytes((body[0], FAILED))
        reply = self._spi(body[2:6])
        return bytes((body[0], OK, reply[ret_addr - 1], OK))

    def _spi_multi(self, body: bytes) -> bytes:
        num_tx, num_rx, rx_start = body[1], body[2], body[3]
        tx = body[4:]
        if len(tx) != num_tx:
            return bytes((body[0], FAILED))
        # Clock out the bytes given, then zeros while more answer is wanted.
        extra = max(0, rx_start + num_rx - num_tx)
        reply = self._spi(bytes(tx) + bytes(extra))
        return bytes((body[0], OK)) + reply[rx_start:rx_start + num_rx] + bytes((OK,))
