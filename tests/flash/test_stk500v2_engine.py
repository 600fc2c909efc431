"""The STK500v2 programmer and the ATmega162 ISP model, without any I/O."""

from __future__ import annotations

from hypothesis import given, settings
from hypothesis import strategies as st

from hexbot.hil_sim.isp import Atmega162Memory, standalone_programmer
from hexbot.hil_sim.isp.avr068 import ANSWER_CKSUM_ERROR, Cmd, Param, Status
from hexbot.hil_sim.isp.chip import Atmega162Isp, MemoryBackend
from hexbot.hil_sim.isp.framing import FrameDecoder, encode

# avrdude's opcodes for the m162 (avrdude.conf), as the host would send them
ENTER = bytes((Cmd.ENTER_PROGMODE_ISP, 200, 100, 25, 32, 0, 0x53, 3, 0xAC, 0x53, 0, 0))
ERASE = bytes((Cmd.CHIP_ERASE_ISP, 9, 0, 0xAC, 0x80, 0, 0))
READ_SIG = bytes((Cmd.READ_SIGNATURE_ISP, 4, 0x30, 0, 0, 0))
READ_HFUSE = bytes((Cmd.READ_FUSE_ISP, 4, 0x58, 0x08, 0, 0))
READ_LOCK = bytes((Cmd.READ_LOCK_ISP, 4, 0x58, 0x00, 0, 0))


def run(programmer, body: bytes, seq: int = 1) -> bytes:
    """Send one framed command; return the answer body (checks the frame)."""
    reply = programmer.feed(encode(seq, body))
    messages = list(FrameDecoder().feed(reply))
    assert len(messages) == 1 and messages[0].checksum_ok and messages[0].seq == seq
    return messages[0].body


def load_address(programmer, addr: int) -> None:
    assert run(programmer, bytes((Cmd.LOAD_ADDRESS,)) + addr.to_bytes(4, "big")) == b"\x06\x00"


def program_flash_page(programmer, word_addr: int, data: bytes) -> bytes:
    load_address(programmer, word_addr)
    head = bytes((Cmd.PROGRAM_FLASH_ISP, len(data) >> 8, len(data) & 0xFF, 0xC1, 10,
                  0x40, 0x4C, 0x20, 0xFF, 0xFF))
    return run(programmer, head + data)


def read_flash(programmer, word_addr: int, count: int) -> bytes:
    load_address(programmer, word_addr)
    answer = run(programmer, bytes((Cmd.READ_FLASH_ISP, count >> 8, count & 0xFF, 0x20)))
    assert answer[:2] == bytes((Cmd.READ_FLASH_ISP, Status.CMD_OK)) and answer[-1] == 0
    return answer[2:-1]


def test_frame_round_trip_in_any_chunking():
    frame = encode(7, b"\x01")
    assert frame == bytes((0x1B, 7, 0, 1, 0x0E, 1, 0x1B ^ 7 ^ 1 ^ 0x0E ^ 1))
    decoder = FrameDecoder()
    got = [m for byte in b"junk" + frame for m in decoder.feed(bytes((byte,)))]
    assert [(m.seq, m.body, m.checksum_ok) for m in got] == [(7, b"\x01", True)]
    assert decoder.dropped == 4


def test_sign_on_and_parameters():
    p = standalone_programmer()
    assert run(p, b"\x01") == b"\x01\x00\x08STK500_2"
    assert run(p, bytes((Cmd.GET_PARAMETER, Param.SW_MAJOR))) == b"\x03\x00\x02"
    assert run(p, bytes((Cmd.SET_PARAMETER, Param.SCK_DURATION, 5))) == b"\x02\x00"
    assert run(p, bytes((Cmd.GET_PARAMETER, Param.SCK_DURATION))) == b"\x03\x00\x05"
    # read-only and unknown parameters are refused
    assert run(p, bytes((Cmd.SET_PARAMETER, Param.HW_VER, 9))) == bytes((2, Status.CMD_FAILED))
    assert run(p, bytes((Cmd.GET_PARAMETER, 0x42))) == bytes((3, Status.CMD_FAILED))


def test_wrong_checksum_is_answered_with_answer_cksum_error_and_not_executed():
    p = standalone_programmer()
    frame = bytearray(encode(0x42, ERASE))
    frame[-1] ^= 0x55
    reply = list(FrameDecoder().feed(p.feed(bytes(frame))))
    assert [(m.seq, m.body) for m in reply] == [(0x42, bytes((ANSWER_CKSUM_ERROR,) * 2))]
    assert p.stats.checksum_errors == 1
    # the programmer is still in step: the next good frame works
    assert run(p, b"\x01", seq=0x43)[:2] == b"\x01\x00"


def test_malformed_commands_get_error_status():
    p = standalone_programmer()
    assert run(p, bytes((Cmd.LOAD_ADDRESS, 0))) == bytes((Cmd.LOAD_ADDRESS, Status.CMD_FAILED))
    assert run(p, b"\x7f") == bytes((0x7F, Status.CMD_UNKNOWN))
    # declared length 4 but 2 data bytes
    short = bytes((Cmd.PROGRAM_FLASH_ISP, 0, 4, 0xC1, 10, 0x40, 0x4C, 0x20, 0xFF, 0xFF, 1, 2))
    assert run(p, short) == bytes((Cmd.PROGRAM_FLASH_ISP, Status.CMD_FAILED))
    bad_retaddr = bytes((Cmd.READ_SIGNATURE_ISP, 9, 0x30, 0, 0, 0))
    assert run(p, bad_retaddr)[1] == Status.CMD_FAILED


def test_signature_fuses_and_programming_enable_echo():
    memory = Atmega162Memory()
    chip = Atmega162Isp(MemoryBackend(memory))
    chip.set_reset(True)
    # Programming Enable: the 0x53 echoes back while the third byte goes out
    assert [chip.transfer(b) for b in (0xAC, 0x53, 0x00, 0x00)][2] == 0x53
    assert [chip.transfer(b) for b in (0x30, 0, 1, 0)][3] == 0x94
    p = standalone_programmer()
    assert run(p, ENTER) == b"\x10\x00"
    sig = [run(p, bytes((Cmd.READ_SIGNATURE_ISP, 4, 0x30, 0, i, 0)))[2] for i in range(3)]
    assert bytes(sig) == b"\x1e\x94\x04"
    assert run(p, READ_HFUSE) == bytes((Cmd.READ_FUSE_ISP, 0, 0xD9, 0))


def test_nothing_answers_before_reset_or_without_spien():
    p = standalone_programmer()
    # not in programming mode: MISO idles high
    assert run(p, READ_SIG)[2] == 0xFF
    dead = standalone_programmer(Atmega162Memory(hfuse=0xF9))  # SPIEN unprogrammed
    assert run(dead, ENTER) == bytes((Cmd.ENTER_PROGMODE_ISP, Status.CMD_FAILED))


def test_flash_page_write_only_clears_bits_until_chip_erase():
    p = standalone_programmer()
    run(p, ENTER)
    page = bytes(range(128))
    assert program_flash_page(p, 64, page) == b"\x13\x00"  # word 64 = byte 128
    assert read_flash(p, 64, 128) == page
    # a second write without erase ANDs into the cells, as real flash does
    program_flash_page(p, 64, b"\xf0" * 128)
    assert read_flash(p, 64, 4) == bytes(b & 0xF0 for b in page[:4])
    assert run(p, ERASE) == b"\x12\x00"
    assert read_flash(p, 64, 4) == b"\xff" * 4


def test_eeprom_page_write_touches_only_loaded_bytes():
    memory = Atmega162Memory()
    p = standalone_programmer(memory)
    run(p, ENTER)
    load_address(p, 8)
    head = bytes((Cmd.PROGRAM_EEPROM_ISP, 0, 2, 0xC1, 20, 0xC1, 0xC2, 0xA0, 0xFF, 0xFF))
    assert run(p, head + b"\x11\x22") == b"\x15\x00"
    assert memory.eeprom[6:12] == b"\xff\xff\x11\x22\xff\xff"


def test_lock_bits_spien_and_eesave_follow_the_chip():
    memory = Atmega162Memory()
    p = standalone_programmer(memory)
    run(p, ENTER)
    memory.eeprom[0] = 0x5A
    # SPIEN cannot be unprogrammed through SPI
    run(p, bytes((Cmd.PROGRAM_FUSE_ISP, 0xAC, 0xA8, 0, 0xF1)))
    assert memory.hfuse == 0xD1
    # lock mode 3: flash reads back as ones, fuses frozen
    run(p, bytes((Cmd.PROGRAM_LOCK_ISP, 0xAC, 0xE0, 0, 0xFC)))
    assert run(p, READ_LOCK)[2] == 0xFC
    run(p, bytes((Cmd.PROGRAM_FUSE_ISP, 0xAC, 0xA0, 0, 0x00)))
    assert memory.lfuse == 0x62
    assert read_flash(p, 0, 2) == b"\xff\xff"
    # chip erase clears the lock; EESAVE (now programmed: 0xD1) keeps the EEPROM
    run(p, ERASE)
    assert run(p, READ_LOCK)[2] == 0xFF and memory.eeprom[0] == 0x5A


def test_spi_multi_clocks_raw_bytes():
    p = standalone_programmer()
    run(p, ENTER)
    answer = run(p, bytes((Cmd.SPI_MULTI, 4, 4, 0, 0x30, 0x00, 0x02, 0x00)))
    assert answer == bytes((Cmd.SPI_MULTI, 0, 0x00, 0x30, 0x00, 0x04, 0))


@settings(max_examples=200, deadline=None)
@given(st.lists(st.binary(min_size=0, max_size=40), max_size=12))
def test_any_input_yields_only_well_formed_answers(chunks):
    p = standalone_programmer()
    p.feed(encode(0, ENTER))
    for chunk in chunks:
        reply = p.feed(chunk)
        decoder = FrameDecoder()
        messages = list(decoder.feed(reply))
        assert decoder.dropped == 0 and not decoder.in_frame
        assert all(m.checksum_ok and len(m.body) >= 2 for m in messages)


@settings(max_examples=200, deadline=None)
@given(st.integers(0, 255), st.binary(min_size=0, max_size=300))
def test_any_command_body_gets_a_status(cmd, rest):
    p = standalone_programmer()
    answer = p.execute(bytes((cmd,)) + rest)
    assert answer[0] == cmd and answer[1] in set(Status)


def test_word_mode_eeprom_write_with_value_polling():
    memory = Atmega162Memory()
    p = standalone_programmer(memory)
    run(p, ENTER)
    load_address(p, 0x1FE)
    # mode 0x04: word mode, value polling; cmd1 = Write EEPROM, cmd3 = Read EEPROM
    head = bytes((Cmd.PROGRAM_EEPROM_ISP, 0, 2, 0x04, 20, 0xC0, 0x00, 0xA0, 0xFF, 0xFF))
    assert run(p, head + b"\x33\xff") == b"\x15\x00"
    assert memory.eeprom[0x1FE:] == b"\x33\xff"


def test_half_sent_frame_is_dropped_on_receive_timeout():
    p = standalone_programmer()
    assert p.feed(encode(1, READ_SIG)[:5]) == b""
    p.receive_timeout()
    assert run(p, b"\x01", seq=2)[:2] == b"\x01\x00"
