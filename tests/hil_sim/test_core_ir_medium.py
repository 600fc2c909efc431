"""The IR medium routed in the core (hil_sim/core/ir_medium.c), on small AVR
programs (tests/hil_sim/avr/irnode.c): selector routes, delivery in the
middle of the stop bit, cut bytes (selector moved, reset), collisions at once
and bits apart, frame mismatch, bytes to and from the PC."""

from __future__ import annotations

import pytest
from test_core_uart import build

from hexbot.hil_sim._avr import Cluster
from hexbot.protocol.pins import SELECTOR_PINS

BIT = 16 * 208  # cycles per bit at UBRR 207 (300.5 baud)
FRAME = 10 * BIT
NONE = [("none",)] * 8


def selector_pins(y: int) -> int:
    """The PORTA value that selects index Y = 4C + 2B + A (Table 3-5)."""
    (_, a), (_, b), (_, c) = SELECTOR_PINS
    return (y & 1) << a | (y >> 1 & 1) << b | (y >> 2 & 1) << c


def node(c: Cluster, y: int, send: bytes = b"", ubrr: int = 0xFF, rxen: bool = True) -> int:
    m = c.add_mcu(build("irnode"), f"node{c.mcu_count}")
    c.write_eeprom(m, 0, (send + b"\xff\xff")[:2] + bytes([ubrr, int(rxen)]))
    c.set_input(m, "C", 0x07, selector_pins(y))
    c.ir_attach(m, 1, SELECTOR_PINS[0][0], tuple(bit for _, bit in SELECTOR_PINS))
    c.ir_routes(m, NONE)
    c.watch_uart(m, 0)  # the receiver's reports
    return m


def advance(c: Cluster, until: int) -> None:
    """run() returns after every watched byte (the reports): run on to ``until``."""
    while c.cycle < until:
        c.run(until)


def reports(c: Cluster, m: int) -> list[tuple[int, int, bool]]:
    """(cycle the report started, byte, framing error) per byte received."""
    taken = c.uart_take(m, 0)
    return [(start, data, bool(flag & 1))
            for (start, _, flag), (_, _, data) in zip(taken[::2], taken[1::2], strict=True)]


def sent(c: Cluster, m: int) -> list[tuple[int, int, int]]:
    c.watch_uart(m, 1)  # the sender's own log: start and end of each byte
    return c.uart_take(m, 1)


def route(c: Cluster, sender: int, y: int, receiver: int, need: int) -> None:
    routes = list(NONE)
    routes[y] = ("mcu", receiver, need)
    c.ir_routes(sender, routes)


def test_byte_reaches_the_facing_receiver_in_the_middle_of_its_stop_bit():
    c = Cluster(1000)
    a = node(c, 3, b"\x5a")
    b = node(c, 5)
    route(c, a, 3, b, 5)
    c.watch_uart(a, 1)
    advance(c, 3 * FRAME)
    [(start, end, value)] = c.uart_take(a, 1)
    [(seen, byte, fe)] = reports(c, b)
    assert (byte, fe) == (0x5A, False)
    mid_stop = start + 9 * BIT + BIT // 2
    # RXC rises at mid-stop; the polling loop reports within a few dozen cycles,
    # well before the stop bit ends (the Python medium: after the end)
    assert mid_stop <= seen < mid_stop + 100 < end
    assert c.ir_events() == []


def test_receiver_looking_elsewhere_hears_nothing():
    c = Cluster(1000)
    a = node(c, 3, b"\x5a")
    b = node(c, 4)  # not on 5, the index that faces a
    route(c, a, 3, b, 5)
    advance(c, 3 * FRAME)
    assert reports(c, b) == []
    # a sender on an index routed nowhere: lost in the air
    c2 = Cluster(1000)
    a2, b2 = node(c2, 1, b"\x5a"), node(c2, 5)
    route(c2, a2, 3, b2, 5)
    advance(c2, 3 * FRAME)
    assert reports(c2, b2) == []


def test_receiver_turned_away_mid_byte_reads_idle_ones_from_then_on():
    c = Cluster(1000)
    a = node(c, 3, b"\x5a")
    b = node(c, 5)
    route(c, a, 3, b, 5)
    c.watch_uart(a, 1)
    advance(c, 8 * BIT)  # data bit 7 on the air, its middle still to come
    c.set_input(b, "C", 0x07, selector_pins(6))
    advance(c, 3 * FRAME)
    # the UART had the start bit: it reads on, bit 7 and the stop bit high
    assert [(v, fe) for _, v, fe in reports(c, b)] == [(0xDA, False)]
    assert [(v, fe) for _, v, fe in python_medium(c, a, b)] == [(0xDA, False)]


# The same bytes through the Python medium (hil_sim/ir_bus.py), on the
# cycles the core logged: the twins must read the same. Sender on "3",
# receiver facing it on "6" (test_ir_bus.pair_air); any other index is away.

def python_medium(c: Cluster, a: int, b: int, others: tuple[int, ...] = ()) -> list:
    from test_ir_bus import Air, medium

    from hexbot.hil_sim.ir_bus import AirByte, Frame

    line = Frame(1e6 / BIT)
    cells = {a: (0, 0), b: (1, 0), **{o: (0, 0) for o in others}}

    def history(m: int, on: int, y_on: int) -> list[tuple[int, int]]:
        (_, pin_a), (_, pin_b), (_, pin_c) = SELECTOR_PINS
        out = [(0, on)]
        for cycle, port, value in c.pin_log(m):
            if port == SELECTOR_PINS[0][0]:
                y = (value >> pin_a & 1) | (value >> pin_b & 1) << 1 | (value >> pin_c & 1) << 2
                out.append((cycle, on if y == y_on else 0))
        return out

    air = Air(cells, {m: history(m, 3, 3) for m in (a, *others)} | {b: history(b, 6, 5)},
              rx={b: line}, reset_at={m: c.resets(m)[1:] for m in (a, *others)})
    m, _ = medium(air)
    sent = sorted((start, end, value, m) for m in (a, *others) for start, end, value in
                  c.uart_take(m, 1))
    for start, end, value, sender in sent:  # one sender per cell: route each alone
        air.cells = {sender: (0, 0), b: (1, 0)}
        m.transmit(AirByte(sender, start, end, value, line))
    return air.got


def test_sender_switching_its_selector_mid_byte_delivers_a_cut_byte():
    # UDR written, then the mux switched before TXC: the tail leaves by
    # another transceiver; the receiver reads idle ones for data bits 4..7
    c = Cluster(1000)
    a = node(c, 3, b"\x00")
    b = node(c, 5)
    route(c, a, 3, b, 5)
    c.watch_uart(a, 1)
    advance(c, 94 + 5 * BIT)  # the byte started at cycle 94: data bit 4 goes out
    c.set_input(a, "C", 0x07, selector_pins(1))
    advance(c, 3 * FRAME)
    assert [(v, fe) for _, v, fe in reports(c, b)] == [(0xF0, False)]
    assert [(v, fe) for _, v, fe in python_medium(c, a, b)] == [(0xF0, False)]


def test_sender_reset_mid_byte_cuts_its_byte():
    c = Cluster(1000)
    a = node(c, 3, b"\x00")
    b = node(c, 5)
    route(c, a, 3, b, 5)
    c.watch_uart(a, 1)
    advance(c, 94 + 5 * BIT)
    c.reset(a)  # its USART stops; after boot it sends its byte again, whole
    advance(c, 4 * FRAME)
    assert [(v, fe) for _, v, fe in reports(c, b)] == [(0xF0, False), (0x00, False)]
    assert [(v, fe) for _, v, fe in python_medium(c, a, b)] == [(0xF0, False), (0x00, False)]


def test_bytes_colliding_three_bits_apart_read_the_and_of_the_shifted_lines():
    c = Cluster(1000)
    a = node(c, 3, b"\xf0")
    d = node(c, 3)  # sends nothing at boot
    b = node(c, 5)
    route(c, a, 3, b, 5)
    route(c, d, 3, b, 5)
    c.watch_uart(a, 1)
    c.watch_uart(d, 1)
    advance(c, 3 * BIT)
    c.write_eeprom(d, 0, b"\x3c\xff")
    c.reset(d)  # boots in 94 cycles, as a did: its byte starts 3 bits after a's
    advance(c, 3 * FRAME)
    # 0x3C's start bit and bits 0, 1 fall on 0xF0's bits 2..4, its bits 2..5
    # (high) on 5..7 and the stop bit: 0xE0, not 0xF0 & 0x3C = 0x30
    got = [(v, fe) for _, v, fe in reports(c, b)]
    assert got == [(0xF0, False), (0xE0, True)]
    assert [(v, fe) for _, v, fe in python_medium(c, a, b, others=(d,))] == got
    assert [e[0] for e in c.ir_events()] == ["ir-collision"]


def test_overlapping_bytes_of_two_senders_collide_as_and_with_framing_error():
    c = Cluster(1000)
    a = node(c, 3, b"\x5a")
    d = node(c, 3, b"\x3c")
    b = node(c, 5)
    route(c, a, 3, b, 5)
    route(c, d, 3, b, 5)
    advance(c, 3 * FRAME)
    got = reports(c, b)
    # the first intact, then the AND of both, broken (as hil_sim/ir_bus.py)
    assert [(v, fe) for _, v, fe in got] == [(0x5A, False), (0x5A & 0x3C, True)]
    [event] = c.ir_events()
    assert event == ("ir-collision", event[1], d, b, 0x3C, (a,))
    assert c.ir_events() == []  # taken


def test_bytes_one_after_another_do_not_collide():
    c = Cluster(1000)
    a = node(c, 3, b"\x5a\x11")
    b = node(c, 5)
    route(c, a, 3, b, 5)
    advance(c, 4 * FRAME)
    assert [(v, fe) for _, v, fe in reports(c, b)] == [(0x5A, False), (0x11, False)]
    assert c.ir_events() == []


@pytest.mark.parametrize("ubrr", [103, 254, 12])  # 600, 245 and 4,800 baud
def test_receiver_at_another_baud_rate_reads_what_its_uart_samples(ubrr):
    # not a random byte: the sender's levels at the receiver's sampling
    # times, as the Python medium (uart_line.first_byte) reads them
    from hexbot.hil_sim.uart_line import LineSettings, first_byte

    c = Cluster(1000)
    a = node(c, 3, b"\x5a")
    b = node(c, 5, ubrr=ubrr)
    route(c, a, 3, b, 5)
    advance(c, 3 * FRAME)
    expected = first_byte(0x5A, LineSettings(1e6 / BIT), LineSettings(1e6 / (16 * (ubrr + 1))))
    assert [(v, fe) for _, v, fe in reports(c, b)] == ([expected] if expected else [])
    [(name, _, sender, receiver, byte, _)] = c.ir_events()
    assert (name, sender, receiver, byte) == ("ir-garbled", a, b, 0x5A)
    if ubrr == 103:  # twice as fast: 0x5A reads 0x98, and no framing error says so
        assert expected == (0x98, False)


def test_centre_channel_bytes_go_to_the_pc_and_the_pcs_bytes_come_back():
    c = Cluster(1000)
    a = node(c, 2, b"\x41")
    b = node(c, 2)
    to_pc = list(NONE)
    to_pc[2] = ("pc",)
    c.ir_routes(a, to_pc)
    c.ir_routes(b, to_pc)
    reached = c.run(3 * FRAME)
    assert reached < 3 * FRAME  # returned for the PC's byte
    [(mcu, start, end, byte)] = c.ir_take_pc()
    assert (mcu, byte) == (a, 0x41) and end - start == FRAME and end <= reached
    assert reports(c, b) == []  # modules do not hear each other on the centre
    now = c.cycle
    c.ir_send_from_pc(now, now + FRAME, 0x7E)
    advance(c, now + 2 * FRAME)
    got = {m: reports(c, m) for m in (a, b)}
    for m in (a, b):
        [(seen, byte, fe)] = got[m]
        assert (byte, fe) == (0x7E, False)
        assert now + 9 * BIT + BIT // 2 <= seen < now + FRAME


def test_dropped_byte_is_reported_when_the_receiver_is_off():
    c = Cluster(1000)
    a = node(c, 3, b"\x5a")
    b = node(c, 5, rxen=False)
    route(c, a, 3, b, 5)
    advance(c, 3 * FRAME)
    assert reports(c, b) == []
    [(name, end, sender, receiver, byte, _)] = c.ir_events()
    assert (name, sender, receiver, byte) == ("ir-dropped", a, b, 0x5A)
    assert c.uart_config(b, 1)["rx_dropped"] == 1


def test_routes_are_checked():
    c = Cluster(1000)
    a = node(c, 3)
    with pytest.raises(ValueError, match="8 in all"):
        c.ir_routes(a, NONE[:7])
    with pytest.raises(ValueError, match="route 0"):
        c.ir_routes(a, [("mcu", 99, 5)] + NONE[1:])
    with pytest.raises(ValueError, match="not on the IR medium"):
        c.ir_state(c.add_mcu(build("irnode"), "plain"))
