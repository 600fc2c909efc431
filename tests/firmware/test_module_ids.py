"""Module ids 1..255 from all eight DIP switches: texts print them with two
digits, three from 100 (docs/protocol.md, "Module ids"); MAVLink addresses
every id; the legacy Select names 1..63 and reaches the others through
Select(0)."""

from __future__ import annotations

import pytest
from fwsim import QUIET_S, Bench, scenario_file

from hexbot.protocol import parser
from hexbot.protocol.mavlink_codec import Framing, MavAck, MavStatus

IDS = (1, 100, 255)  # boot slots 0, 3 and 6: none shares a slot


@pytest.fixture
def wide(images, tmp_path) -> Bench:
    modules = [(ident, (k, 0), 0) for k, ident in enumerate(IDS)]
    bench = Bench.boot(scenario_file(tmp_path, modules))
    return bench


def test_boot_texts_carry_three_digit_ids_and_two_digit_ones_unchanged(wide: Bench):
    found = [(e.phrase, e.tail) for e in parser.parse_all(wide.drain())
             if isinstance(e, parser.Text)]
    for ident in IDS:
        assert ("CTR. BOARD READY", f"ID={ident:02d}") in found
        assert ("COMM. LISTENING", f"ID={ident:02d} FW=0.1.0") in found
    assert ("COMM. LISTENING", "ID=01 FW=0.1.0") in found  # the thesis' bytes
    debug = wide.debug_read(255)
    assert b"CTR. BOARD READY ID=255 FW=0.1.0\n\r" in debug


def test_select_all_reaches_ids_above_63_with_three_digit_prefixes(wide: Bench):
    wide.drain()
    replies = wide.command("Select", 0, settle=QUIET_S)
    assert [(r.code, r.module) for r in replies] == [(69, i) for i in IDS]
    heard = bytes(wide.heard)
    assert b"\n\r\n\rM01: ACKE\n\r" in heard  # unchanged below 100
    assert b"\n\r\n\rM100: ACKE\n\r" in heard
    assert b"\n\r\n\rM255: ACKE\n\r" in heard


def test_mavlink_target_system_addresses_module_255(wide: Bench):
    wide.host.set_framing(Framing.MAVLINK)
    (ack,) = wide.command("JxOpen", 4, target=255, settle=QUIET_S)
    assert isinstance(ack, MavAck) and (ack.code, ack.module) == (1, 255)  # JxOpen
    (sta,) = wide.command("Status", target=255, settle=QUIET_S)
    assert isinstance(sta, MavStatus) and sta.module_id == 255 and sta.mav.sysid == 255
    joint_port = wide.sim.modules[255].control.port("A")[1]
    assert joint_port & (1 << 4)  # J4 is PA4 (Table 3-4)
