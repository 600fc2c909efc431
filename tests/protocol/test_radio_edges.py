"""The RF12 packet receiver's time-out at its edge."""

from hexbot.protocol import radio


def test_a_byte_exactly_gap_cycles_after_the_last_continues_the_packet():
    air = radio.packet(radio.payloads(b"edge")[0])
    rx = radio.PacketReceiver(gap=10)
    assert b"".join(rx.push(10 * i, b) for i, b in enumerate(air)) == b"edge"
    assert (rx.good, rx.bad) == (1, 0)
    late = radio.PacketReceiver(gap=9)  # one cycle longer than it waits: every byte starts afresh
    assert b"".join(late.push(10 * i, b) for i, b in enumerate(air)) == b""
