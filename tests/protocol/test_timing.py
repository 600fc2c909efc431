"""The protocol's timing against the thesis' numbers, and the bounds the
host derives from it (their hold on the real firmware is checked in
tests/firmware/test_timing_bounds.py)."""

import math

import pytest

from hexbot.protocol import timing, wire
from hexbot.protocol.codes import CODES


def test_thesis_clock_tick_and_links():
    # 1 MHz (internal RC / 8); Timer0 /64 reloaded with 0x64 ticks "10 ms".
    assert timing.F_CPU == 1_000_000
    assert timing.TICK_TRUE_S == pytest.approx(0.009984)
    assert timing.TICK_TRUE_S <= timing.TICK_S == 0.010  # bounds in nominal ticks stay bounds
    assert (timing.BAUD_IR, timing.BAUD_BOARD, timing.BAUD_DEBUG) == (300, 4800, 4800)
    # The control board's echo is awaited 2.5 s; the substrate answers after 1 s.
    assert timing.CONTROL_ACK_TIMEOUT_TICKS * timing.TICK_S == 2.5
    assert timing.SUBSTRATE_ACK_DELAY_TICKS * timing.TICK_S == 1.0


def test_an_ir_byte_is_counted_no_shorter_than_it_lasts():
    byte_s = timing.wire_seconds(1, timing.BAUD_IR)
    assert timing.IR_BYTE_TICKS_X10 / 10 * timing.TICK_TRUE_S >= byte_s
    for n in (1, 11, 16, 61, 80):
        assert timing.ir_ticks(n) * timing.TICK_TRUE_S >= timing.wire_seconds(n, timing.BAUD_IR)


def test_each_reply_fits_its_slots():
    for nbytes, slots in ((timing.REPLY_BYTES_ACK, timing.SLOTS_ACK),
                          (timing.REPLY_BYTES_ERR, timing.SLOTS_ACK),
                          (timing.REPLY_BYTES_STATUS, timing.SLOTS_STATUS),
                          (timing.REPLY_BYTES_LOCALIZE, timing.SLOTS_LOCALIZE)):
        air = timing.wire_seconds(nbytes, timing.BAUD_IR)
        assert air <= slots * timing.ACK_SLOT_S, nbytes
        assert air > (slots - 1) * timing.ACK_SLOT_S, f"{nbytes} bytes waste a slot"


def test_reply_sizes_are_those_of_the_replies():
    from hexbot.protocol import parser

    longest_err = parser.reply_error(255, 255, "M", 255)  # a three-digit id
    status = parser.reply_status(255, "S", True, -99, 99, 5, 7, prefix_role="S", schema=0)
    assert timing.REPLY_BYTES_ERR == len(longest_err)
    assert timing.REPLY_BYTES_ACK == len(parser.reply_ack(255, "M", 255))
    # Ids 1..99 keep the thesis' two digits: one byte less.
    assert len(parser.reply_ack(255, "M", 63)) == timing.REPLY_BYTES_ACK - 1
    assert timing.REPLY_BYTES_STATUS == len(status)


def test_boot_slot_holds_the_slot_text_of_a_three_digit_id():
    ident = 200
    text = (wire.PREAMBLE + f"{wire.TEXT_CTR_READY} ID={ident}".encode() + wire.EOL
            + wire.TEXT_CTR_LISTENING.encode() + wire.EOL
            + f"{wire.TEXT_COMM_LISTENING} ID={ident} FW=0.1.0".encode() + wire.EOL)
    assert timing.BOOT_TEXT_FIXED_BYTES + len("0.1.0") == len(text)
    assert timing.boot_slot_ticks("0.1.0") == 392  # docs/firmware.md: 3.92 s
    guard = timing.BOOT_GUARD_TICKS
    assert timing.boot_slot_ticks("0.1.10") == timing.ir_ticks(len(text) + 1) + guard
    two_digit = text.replace(b"ID=200", b"ID=12")
    assert len(two_digit) == len(text) - 2  # ends earlier in the same slot


def test_boot_guard_covers_the_clock_spread_at_the_last_slot():
    """A slow module's text in slot 6 ends before a fast module's slot 7 starts."""
    s, slot = timing.CLOCK_SPREAD, timing.boot_slot_ticks("0.1.0-rc1+build")  # 15 characters
    last_start = timing.BOOT_FIRST_SLOT_TICKS + (timing.BOOT_SLOTS - 1) * slot
    previous_text_end = last_start - timing.BOOT_GUARD_TICKS
    assert previous_text_end * (1 + s) <= last_start * (1 - s)


def test_boot_seconds_is_the_end_of_the_last_slot_used():
    slot = timing.boot_slot_ticks() * timing.TICK_S
    assert timing.boot_seconds([1]) == pytest.approx(2.0 + slot)
    assert timing.boot_seconds([1, 7]) == pytest.approx(2.0 + 7 * slot)
    assert timing.boot_seconds([9]) == timing.boot_seconds([1])  # slots wrap after eight ids
    assert timing.boot_seconds([1], "0.1.0-rc1") > timing.boot_seconds([1])
    with pytest.raises(ValueError):
        timing.boot_seconds([])


def test_localization_window_allows_its_hops():
    per_hop = timing.LOC_SWEEP_TICKS + 6 * timing.LOC_LISTEN_TICKS
    assert timing.LOC_WINDOW_TICKS >= timing.LOC_HOPS * per_hop
    assert timing.LOCALIZE_WINDOW_S == timing.LOC_WINDOW_TICKS * timing.TICK_S


def test_reply_timeout_grows_with_replies_and_run_time():
    for code in (1, 21, 44, 66, 69, 70):
        bounds = [timing.reply_timeout_s(code, n) for n in range(1, 9)]
        assert bounds == sorted(bounds) and bounds[0] < bounds[-1], code
    assert timing.reply_timeout_s(70, 0) == 0.0
    with pytest.raises(ValueError):
        timing.reply_timeout_s(70, -1)
    # JTest(2, 5): 2 rounds x 6 joints x (5 on + 5 off) ticks before the ACK,
    # plus what each of its 24 steps costs beyond its delay.
    assert timing.run_ticks(5, [2, 5]) == math.ceil(24 * (5 + timing.WALK_STEP_TICKS))
    # with no delay at all the steps still take time (LCircle(255, 0): 4.6 s)
    assert timing.run_ticks(46, [255, 0]) * timing.TICK_S > 4.6
    assert timing.reply_timeout_s(5, 1, [2, 5]) < timing.reply_timeout_s(5, 1)  # worst case
    # A control function waits up to 2.5 s for the echo, a comm function not.
    assert timing.reply_timeout_s(1, 1) - timing.reply_timeout_s(44, 1) >= 2.5
    # Localize: the whole window, then one report slot per module.
    one, two = timing.reply_timeout_s(66, 2), timing.reply_timeout_s(66, 3)
    assert one > timing.LOCALIZE_WINDOW_S
    assert two - one == pytest.approx(
        timing.SLOTS_LOCALIZE * timing.ACK_SLOT_S * (1 + timing.CLOCK_TOLERANCE))


def test_without_arguments_the_bound_holds_for_any():
    for fn in CODES.values():
        top = [a.hi for a in fn.args]
        assert timing.reply_timeout_s(fn.code, 1) == timing.reply_timeout_s(fn.code, 1, top) > 0


def test_a_bit_is_what_the_usart_makes_of_the_baud_rate():
    # UBRR rounded to nearest, 16 cycles a count (firmware/common/uart.c)
    assert timing.bit_cycles(4800) == 208  # 4807.7 baud at 1 MHz
    assert timing.bit_cycles(300) == 3328
    from hexbot.hil_sim.simulator import lookahead_cycles

    # start bit to mid-stop of a board byte on the fastest clock allowed
    assert lookahead_cycles() == int(9.5 * 208 / (1 + timing.CLOCK_TOLERANCE)) == 1881
