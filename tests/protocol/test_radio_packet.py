"""The RF12 packet of the listing and the link bytes the bridge puts in it."""

from __future__ import annotations

import pytest

from hexbot.protocol import radio
from hexbot.protocol.header import render


def receive(air: bytes, gap: int = 10, step: int = 1) -> tuple[bytes, radio.PacketReceiver]:
    rx = radio.PacketReceiver(gap)
    out = b"".join(rx.push(i * step, b) for i, b in enumerate(air))
    return out, rx


def test_a_packet_is_preamble_sync_payload_sum_trailer():
    payload = radio.payloads(b"*FNNNNNNNN#")[0]
    assert payload == b"\x0b*FNNNNNNNN#" + bytes(4)
    air = radio.packet(payload)
    assert air[:5] == b"\xaa\xaa\xaa\x2d\xd4"
    assert air[5:21] == payload and air[21] == sum(payload) & 0xFF
    assert air[22:] == b"\xaa\xaa\xaa"


def test_long_data_is_cut_into_packets_and_comes_back_whole():
    data = bytes(range(40))
    payloads = radio.payloads(data)
    assert [p[0] for p in payloads] == [15, 15, 10]
    out, rx = receive(b"".join(radio.packet(p) for p in payloads))
    assert out == data and (rx.good, rx.bad) == (3, 0)


def test_a_bad_sum_or_length_drops_the_packet():
    air = bytearray(radio.packet(radio.payloads(b"hello")[0]))
    air[7] ^= 0x01  # a flipped bit in the payload
    bad_length = bytes([16]) + bytes(15)
    ok = radio.packet(radio.payloads(b"ok")[0])
    out, rx = receive(bytes(air) + radio.packet(bad_length) + ok)
    assert out == b"ok" and (rx.good, rx.bad) == (1, 2)


def test_a_silence_mid_packet_restarts_the_sync_search():
    first = radio.packet(radio.payloads(b"lost")[0])[:12]  # cut after 7 payload bytes
    rx = radio.PacketReceiver(gap=5)
    for i, b in enumerate(first):
        rx.push(i, b)
    after = radio.packet(radio.payloads(b"next")[0])
    out = b"".join(rx.push(100 + i, b) for i, b in enumerate(after))
    assert out == b"next"


def test_channel_and_rate_of_the_listing_words():
    assert radio.channel() == (1, 0x640, 0x47)  # 433 MHz band, 434 MHz, R = 71
    assert radio.bit_rate() == pytest.approx(4789.3, abs=0.1)


def test_the_firmware_header_carries_the_radio_words():
    text = render()
    for name, value in (("CONFIG", radio.CMD_CONFIG), ("FREQ", radio.CMD_FREQUENCY),
                        ("RATE", radio.CMD_DATA_RATE), ("SYNC", radio.CMD_SYNC_LOW)):
        assert f"#define HB_RF12_CMD_{name:<7} 0x{value:04X}u" in text
    assert f"#define HB_RF12_LINK_BYTES  {radio.LINK_BYTES}u" in text
