"""Edges of the IR medium that a user of the fault injection or of the
selector sees: a byte lost is not delivered, a flipped bit is a data bit,
back-to-back bytes of two senders do not collide, Y7 is no transceiver, a
burst reaches every data bit, a selector may leave and come back three
times within one byte (the C twin's IR_MAX_SPANS)."""

from test_ir_bus import BIT, BYTE, IR, Air, medium, pair_air

from hexbot.hil_sim.geometry import CENTRE
from hexbot.hil_sim.ir_bus import AirByte
from hexbot.hil_sim.scenario import Faults


def _send(faults: Faults, values, seed: int = 3):
    """Module 1 sends ``values`` to module 2, one byte every three byte times."""
    air = pair_air()
    m, events = medium(air, seed=seed, faults_for=lambda s, r: faults)
    for i, value in enumerate(values):
        m.transmit(AirByte(1, 3 * i * BYTE, (3 * i + 1) * BYTE, value, IR))
    return air.got, events


def test_a_byte_the_link_loses_is_not_delivered():
    # byte_loss = 1: every byte vanishes; the event alone is not enough, the
    # receiver must not get it (a lossy link that loses nothing)
    got, events = _send(Faults(byte_loss=1.0), [0x55] * 5)
    assert got == []
    assert [e["event"] for e in events] == ["ir-lost"] * 5


def test_a_bit_error_flips_data_bits_only():
    # bit_error_rate = 1: each of the 8 data bits flips, the byte arrives
    # inverted, still a byte (0..255), and the event names the 8 bits
    got, events = _send(Faults(bit_error_rate=1.0), [0x55, 0x00, 0xF0])
    assert [value for _, value, _ in got] == [0xAA, 0xFF, 0x0F]
    assert [e["mask"] for e in events] == [0xFF] * 3


def test_bytes_of_two_senders_back_to_back_reach_the_pc_both():
    # the second start bit begins as the first stop bit ends: no overlap on
    # the line, so no collision; the PC reads the two bytes
    air = Air({1: (0, 0), 2: (9, 9)}, {1: [(0, CENTRE)], 2: [(0, CENTRE)]})
    m, events = medium(air)
    m.transmit(AirByte(1, 0, BYTE, ord("A"), IR))
    m.transmit(AirByte(2, BYTE, 2 * BYTE, ord("B"), IR))
    m.settle(6 * BYTE)
    assert m.pc_take() == b"AB"
    assert events == []


def test_a_sender_on_y7_reaches_nobody():
    # Y7 (channel None) drives no transceiver: neither the PC nor a
    # neighbour hears the byte
    air = Air({1: (0, 0), 2: (1, 0)}, {1: [(0, None)], 2: [(0, CENTRE)]})
    m, events = medium(air)
    m.transmit(AirByte(1, 0, BYTE, ord("M"), IR))
    m.settle(10 * BYTE)
    assert m.pc_take() == b""
    assert air.got == [] and events == []


def test_a_burst_can_hit_every_data_bit_and_a_start_bit():
    # burst_rate = 1: a burst of 12 bit times starts on every other byte
    # (10 bit times of its own, the next byte's start bit and data bit 0);
    # over many bytes each data bit is read wrong somewhere, and a start bit
    # read wrong breaks the frame of a byte whose data bits 1..7 are right
    got, _ = _send(Faults(burst_rate=1.0), [0x00] * 200, seed=5)
    hit = 0
    for _, value, _ in got:
        hit |= value
    assert hit == 0xFF  # bit 7 included
    tails = got[1::2]  # the bytes a burst only runs into
    assert any(fe and value & 0xFE == 0 for _, value, fe in tails)


def test_a_selector_that_leaves_and_returns_three_times_shows_four_parts():
    # 0x00 sent; the sender's selector is away during data bits 1, 3 and 5
    # and back for bits 2, 4 and 6..7: the receiver sees four spans, reads
    # the low bits there and the idle line's ones in between
    air = pair_air()
    air.channels[1] = [(0, 3)] + [(round(k * BIT), 5 if k % 2 == 0 else 3)
                                  for k in (2, 3, 4, 5, 6, 7)]
    m, _ = medium(air)
    m.transmit(AirByte(1, 0, BYTE, 0x00, IR))
    assert air.got == [(2, 0b00101010, False)]
