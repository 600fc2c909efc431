"""The IR medium: selector routing, the PC, collisions, baud mismatch, faults, drops."""

from dataclasses import dataclass, field

from hexbot.hil_sim.geometry import CENTRE
from hexbot.hil_sim.ir_bus import AirByte, Frame, IrMedium
from hexbot.hil_sim.module import receiver_on_since
from hexbot.hil_sim.scenario import Faults

IR = Frame(300.0)
BYTE = 33_333  # cycles of one 300-baud 8N1 byte at 1 MHz


@dataclass
class Air:
    """Modules at fixed cells with scripted selector channels."""

    cells: dict[int, tuple[int, int]]
    channels: dict[int, list[tuple[int, int | None]]]  # module -> [(from cycle, channel)]
    rx: dict[int, Frame] = field(default_factory=dict)
    rxen: dict[int, bool] = field(default_factory=dict)
    got: list[tuple[int, int, bool]] = field(default_factory=list)
    reset_at: dict[int, list[int]] = field(default_factory=dict)  # module -> reset cycles
    #: module -> (cycle, on) of its receiver's changes (RXEN, resets); on from 0 before
    rx_log: dict[int, list[tuple[int, bool]]] = field(default_factory=dict)
    #: the cycle the medium hands bytes over (the simulator's boundary after
    #: the byte's end); None: at the horizon, as the core
    now: float | None = None
    dropped: dict[int, int] = field(default_factory=dict)  # module -> bytes counted lost

    def channel_at(self, module, cycle):
        current = None
        for since, channel in self.channels[module]:
            if since <= cycle:
                current = channel
        return current

    def channel_changes(self, module, after, until):
        return [(since, channel) for since, channel in self.channels[module]
                if after < since <= until]

    def resets(self, module, after, until):
        return [c for c in self.reset_at.get(module, []) if after < c <= until]

    def position(self, module):
        return self.cells[module]

    def module_at(self, cell):
        return next((m for m, c in self.cells.items() if c == cell), None)

    def listeners(self):
        return sorted(self.cells)

    def rx_frame(self, module):
        return self.rx.get(module, IR)

    def rx_since(self, module, before):
        return receiver_on_since(self.rx_log.get(module, []), before, on=True)

    def rx_went_off(self, module, after):
        until = after if self.now is None else self.now
        return any(not on and after <= cycle < until
                   for cycle, on in self.rx_log.get(module, []))

    def drop(self, module):
        self.dropped[module] = self.dropped.get(module, 0) + 1

    def deliver(self, module, value, framing_error):
        if not self.rxen.get(module, True):
            return False
        self.got.append((module, value, framing_error))
        return True


def medium(air, **kw):
    events = []
    m = IrMedium(air, emit=lambda cycle, e: events.append({"cycle": cycle, **e}), **kw)
    return m, events


def pair_air(**channels):
    # module 1 at the origin, module 2 on its side 3 (so 1 hears 2 on side 3, 2 hears 1 on 6)
    return Air({1: (0, 0), 2: (1, 0)}, {1: [(0, channels.get("a", 3))],
                                        2: [(0, channels.get("b", 6))]})


def test_side_byte_reaches_the_neighbour_listening_on_the_facing_side():
    air = pair_air()
    m, _ = medium(air)
    m.transmit(AirByte(1, 0, BYTE, 0x2A, IR))
    assert air.got == [(2, 0x2A, False)]


def test_neighbour_listening_elsewhere_hears_nothing():
    air = pair_air(b=CENTRE)
    m, _ = medium(air)
    m.transmit(AirByte(1, 0, BYTE, 0x2A, IR))
    assert air.got == []


def test_sender_channel_taken_at_start_and_selector_moves_after_the_byte_do_not_matter():
    air = pair_air()
    air.channels[1] = [(0, 3), (BYTE, 5)]  # the sender moves on as the stop bit ends
    air.channels[2] = [(0, 6), (BYTE + 1, 1)]  # the receiver right after
    m, _ = medium(air)
    m.transmit(AirByte(1, 0, BYTE, 0x55, IR))
    assert air.got == [(2, 0x55, False)]


BIT = BYTE / 10  # one bit time of IR


def test_a_sender_that_switches_its_selector_mid_byte_delivers_a_cut_byte():
    # UDR written, then the mux switched before TXC: data bits 4..7 leave by
    # side 5, the receiver on side 6 reads them as the idle line's ones
    air = pair_air()
    air.channels[1] = [(0, 3), (round(5 * BIT), 5)]  # while data bit 4 goes out
    m, events = medium(air)
    m.transmit(AirByte(1, 0, BYTE, 0x00, IR))
    assert air.got == [(2, 0xF0, False)]  # not 0x00: a wrong byte, stop bit high
    assert events == []


def test_a_sender_that_resets_mid_byte_stops_the_byte():
    air = pair_air()
    air.reset_at[1] = [round(5 * BIT)]
    m, _ = medium(air)
    m.transmit(AirByte(1, 0, BYTE, 0x00, IR))
    assert air.got == [(2, 0xF0, False)]


def test_a_byte_cut_in_its_start_bit_is_a_glitch_and_reaches_nobody():
    air = pair_air()
    air.channels[1] = [(0, 3), (10, 5)]  # the start bit's first 10 cycles only
    air.channels[2] = [(0, 1), (BYTE - 5, 6)]  # switched in as the stop bit ends: sees nothing
    m, events = medium(air)
    m.transmit(AirByte(1, 0, BYTE, 0x55, IR))
    m.transmit(AirByte(1, 2 * BYTE, 3 * BYTE, 0x55, IR))
    assert air.got == []
    assert events == []


def test_a_receiver_that_looks_away_mid_byte_reads_idle_ones_from_then_on():
    air = pair_air()
    air.channels[2] = [(0, 6), (round(8 * BIT), 1)]  # as data bit 7 begins
    m, _ = medium(air)
    m.transmit(AirByte(1, 0, BYTE, 0x5A, IR))
    assert air.got == [(2, 0xDA, False)]  # bit 7 reads 1, the stop bit too


def test_a_sender_that_switches_back_sends_the_rest_of_its_byte():
    air = pair_air()
    air.channels[1] = [(0, 3), (round(3 * BIT), 5), (round(5 * BIT), 3)]  # away for bits 2, 3
    m, _ = medium(air)
    m.transmit(AirByte(1, 0, BYTE, 0x00, IR))
    assert air.got == [(2, 0x0C, False)]


def test_a_receiver_off_for_part_of_a_byte_reads_from_a_falling_edge_after():
    # 0x5A: data bits 0, 2, 5, 7 low. Off in bit 0, on again in bit 1 (high):
    # bit 2's falling edge is a start bit, and bits 3..7, the stop bit and
    # the idle line read 0xEB. On again in bit 2 (low): that is no start
    # bit; bit 5's edge is, and reads 0xFD.
    dropped = []

    def got(rx_log, value=0x5A, now=None):
        air = pair_air()
        air.rx_log[2] = rx_log
        air.now = now
        m, events = medium(air)
        m.transmit(AirByte(1, 0, BYTE, value, IR))
        dropped.append(air.dropped.get(2, 0))
        return [(v, fe) for _, v, fe in air.got], [e["event"] for e in events]

    assert got([(round(1.5 * BIT), False), (round(2.2 * BIT), True)]) == ([(0xEB, False)], [])
    assert got([(round(1.5 * BIT), False), (round(3.2 * BIT), True)]) == ([(0xFD, False)], [])
    # 0xF0 on again in data bit 1: the line is low, then only high: nothing
    assert got([(round(1.5 * BIT), False), (round(2.2 * BIT), True)], 0xF0) == ([], [])
    # off before the byte and on again as its start bit begins: the whole byte
    assert got([(-5, False), (0, True)]) == ([(0x5A, False)], [])
    # off at the middle of the stop bit (9.5 bits): not delivered; on again
    # after it: the byte is lost all the same
    assert got([(round(4 * BIT), False)]) == ([], ["ir-dropped"])
    assert got([(round(9.4 * BIT), False), (round(9.6 * BIT), True)]) == ([], ["ir-dropped"])
    assert dropped[-2:] == [1, 1]  # counted as the USART counts one (Air.drop)
    # changes after that middle do not change what it reads: handed over
    # there (the core), the byte is in its receive buffer
    assert got([(round(9.6 * BIT), False)]) == ([(0x5A, False)], [])
    # handed over later (the simulator: the boundary after the byte's end),
    # it went with the buffer if the receiver went off in between, even if
    # on again by then: no event, not counted
    assert got([(round(9.6 * BIT), False)], now=BYTE + 500) == ([], [])
    assert got([(round(9.6 * BIT), False), (BYTE, True)], now=BYTE + 500) == ([], [])
    assert got([(BYTE + 500, False)], now=BYTE + 500) == ([(0x5A, False)], [])
    assert dropped[-3:] == [0, 0, 0]


def test_centre_goes_to_pc_and_pc_goes_to_every_centre_listener():
    air = Air({1: (0, 0), 2: (1, 0), 3: (5, 5)}, {1: [(0, CENTRE)], 2: [(0, CENTRE)], 3: [(0, 2)]})
    m, _ = medium(air)
    m.transmit(AirByte(1, 0, BYTE, ord("M"), IR))
    m.settle(10 * BYTE)
    assert m.pc_take() == b"M"
    m.transmit(AirByte("pc", 10 * BYTE, 11 * BYTE, ord("*"), IR))
    assert air.got == [(1, ord("*"), False), (2, ord("*"), False)]


def test_overlapping_bytes_at_the_pc_become_one_broken_byte():
    air = Air({1: (0, 0), 2: (9, 9)}, {1: [(0, CENTRE)], 2: [(0, CENTRE)]})
    m, events = medium(air)
    m.transmit(AirByte(1, 0, BYTE, 0xF0, IR))
    m.transmit(AirByte(2, BYTE // 2, BYTE + BYTE // 2, 0x3C, IR))
    m.settle(BYTE + BYTE // 2)
    assert m.pc_take() == b""  # not settled: a third byte could still overlap
    m.settle(4 * BYTE)
    # 0x3C starts 5 bits later: its start bit and bits 0, 1 (low) land on
    # 0xF0's bits 4..6, its bit 2 (high) on bit 7: 0x80, not 0xF0 & 0x3C
    assert m.pc_take() == bytes([0x80])
    assert [e["event"] for e in events] == ["ir-collision"]


def test_a_collision_reads_the_and_of_the_lines_at_their_real_offset():
    # 0xFF is a lone start bit: shifted by k bits it clears data bit k - 1
    for k in (1, 3, 8):
        air = Air({1: (0, 0), 2: (9, 9)}, {1: [(0, CENTRE)], 2: [(0, CENTRE)]})
        m, _ = medium(air)
        m.transmit(AirByte(1, 0, BYTE, 0xFF, IR))
        m.transmit(AirByte(2, round(k * BIT), round(k * BIT) + BYTE, 0xFF, IR))
        m.settle(5 * BYTE)
        assert m.pc_take() == bytes([0xFF & ~(1 << (k - 1))])
    # started together: the AND of the values, as before
    air = Air({1: (0, 0), 2: (9, 9)}, {1: [(0, CENTRE)], 2: [(0, CENTRE)]})
    m, _ = medium(air)
    m.transmit(AirByte(1, 0, BYTE, 0xF0, IR))
    m.transmit(AirByte(2, 0, BYTE, 0x3C, IR))
    m.settle(5 * BYTE)
    assert m.pc_take() == bytes([0x30])


def test_baud_mismatch_gives_what_the_receivers_uart_samples():
    air = pair_air()
    air.rx[2] = Frame(4800.0)  # samples the start bit's low level: 0, framing error
    m, events = medium(air, seed=3)
    m.transmit(AirByte(1, 0, BYTE, 0x41, IR))
    assert [(value, fe) for _, value, fe in air.got] == [(0x00, True)]
    assert events[0]["event"] == "ir-garbled"
    air = pair_air()
    air.rx[2] = Frame(600.0)  # twice as fast: a wrong byte that looks fine
    m, events = medium(air, seed=3)
    m.transmit(AirByte(1, 0, BYTE, 0x5A, IR))
    assert [(value, fe) for _, value, fe in air.got] == [(0x98, False)]


def test_moves_in_the_stop_bit_and_the_baud_rule_depend_only_on_samples():
    # Receiver 5 % fast: its samples all fall before the sender's stop bit
    # is over, and 0x5A still reads right (with a framing error: outside the
    # baud range nothing is promised). Moves from the stop bit on change no
    # sample and so nothing; a cut that changes no sample keeps the rule.
    def got(sender, receiver):
        air = pair_air()
        air.rx[2] = Frame(315.0)
        air.channels[1] = [(0, 3), *sender]
        air.channels[2] = [(0, 6), *receiver]
        m, _ = medium(air)
        m.transmit(AirByte(1, 0, BYTE, 0x5A, IR))
        return [(value, fe) for _, value, fe in air.got]

    assert got([], []) == [(0x5A, True)]
    assert got([(round(9.2 * BIT), 5)], []) == [(0x5A, True)]  # sender, in the stop bit
    assert got([], [(round(9.7 * BIT), 1)]) == [(0x5A, True)]  # receiver, after it sampled
    assert got([(round(8.9 * BIT), 5)], []) == [(0x5A, True)]  # bit 7 (low) is cut after the
    # receiver sampled it (8.1 bit times): the same samples, the same byte
    assert got([(round(7.9 * BIT), 5)], []) == [(0xDA, False)]  # before: bit 7 reads high


def test_a_word_format_mismatch_gives_seeded_garbage_with_framing_error():
    air = pair_air()
    air.rx[2] = Frame(300.0, data_bits=7)
    m, events = medium(air, seed=3)
    m.transmit(AirByte(1, 0, BYTE, 0x41, IR))
    assert len(air.got) == 1 and air.got[0][2] is True
    assert events[0]["event"] == "ir-garbled"


def test_receiver_with_rxen_off_drops_and_the_bus_says_so():
    air = pair_air()
    air.rxen[2] = False
    m, events = medium(air)
    m.transmit(AirByte(1, 0, BYTE, 0x41, IR))
    assert air.got == []
    assert events[0]["event"] == "ir-dropped" and events[0]["to"] == 2


def _lossy_run(seed):
    air = pair_air()
    m, events = medium(air, seed=seed, faults_for=lambda s, r: Faults(0.05, 0.3))
    for i in range(200):
        m.transmit(AirByte(1, i * BYTE, (i + 1) * BYTE, i % 256, IR))
    return air.got, events


def test_fault_injection_is_seeded_and_deterministic():
    got, events = _lossy_run(5)
    assert (got, events) == _lossy_run(5)
    assert got != _lossy_run(6)[0]
    lost = sum(e["event"] == "ir-lost" for e in events)
    assert 30 < lost < 90  # 30 % of 200
    assert any(value != sent for (_, value, _), sent in zip(got, range(200), strict=False))


def test_three_senders_at_once_give_the_pc_one_broken_byte():
    cells = {1: (0, 0), 2: (5, 5), 3: (9, 9)}
    air = Air(cells, {m: [(0, CENTRE)] for m in cells})
    m, events = medium(air)
    for sender, value in ((1, 0xFE), (2, 0xFD), (3, 0xFB)):
        m.transmit(AirByte(sender, 100, 100 + BYTE, value, IR))
    m.settle(5 * BYTE)
    assert m.pc_take() == bytes([0xF8])
    assert len(events) == 2


def _run(faults: Faults, seed: int = 3, n: int = 200):
    air = pair_air()
    m, events = medium(air, seed=seed, faults_for=lambda s, r: faults)
    for i in range(n):
        m.transmit(AirByte(1, 3 * i * BYTE, (3 * i + 1) * BYTE, 0x55, IR))
    return air.got, events


def test_framing_errors_reach_the_receiver_flagged():
    got, events = _run(Faults(framing_error_rate=1.0), n=5)
    assert [(value, fe) for _, value, fe in got] == [(0x55, True)] * 5
    assert [e["event"] for e in events] == ["ir-framing-error"] * 5


def test_a_spurious_start_bit_on_the_idle_line_adds_a_byte():
    got, events = _run(Faults(spurious_byte_rate=1.0), n=3)
    values = [value for _, value, _ in got]
    assert values[0::2] == [0x55] * 3
    assert all(bin(v).count("1") == 7 for v in values[1::2])  # idle ones, the pulse's zero
    assert sum(e["event"] == "ir-spurious-byte" for e in events) == 3


def test_a_burst_spans_byte_boundaries_and_breaks_stop_bits():
    got, events = _run(Faults(burst_rate=0.05), seed=11)
    bursts = sum(e["event"] == "ir-burst" for e in events)
    assert 3 <= bursts <= 25
    hit = [i for i, (_, value, fe) in enumerate(got) if value != 0x55 or fe]
    # each burst covers BURST_BITS = 12 bit times: its byte and the next one
    assert any(b == a + 1 for a, b in zip(hit, hit[1:], strict=False))
    assert any(fe for _, _, fe in got)
    assert _run(Faults(burst_rate=0.05), seed=11) == (got, events)  # seeded
