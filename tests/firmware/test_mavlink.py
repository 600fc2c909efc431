"""MAVLink 2 framing on the IR link, on the same comm image that speaks the
legacy frames: commands as HEXBOT_COMMAND (told apart by their first byte
0xFD), answers in the request's framing, target_system addressing, frames
with a bad checksum dropped and counted, numbered replies."""

from __future__ import annotations

import pytest
from fwsim import QUIET_S, Bench, pc_frame

from hexbot.protocol import frames, parser
from hexbot.protocol.mavlink_codec import (
    Framing,
    MavAck,
    MavErrorReply,
    MavlinkEncoder,
    MavStatus,
)


@pytest.fixture
def single(images) -> Bench:
    bench = Bench.boot("single")
    bench.drain()
    bench.debug_read(1)
    return bench


@pytest.fixture
def pair(images) -> Bench:
    bench = Bench.boot("pair")
    bench.drain()
    bench.sim.events.clear()
    return bench



def mavlink(bench: Bench) -> Bench:
    bench.host.set_framing(Framing.MAVLINK)
    return bench


def test_both_framings_on_one_image_each_answered_in_its_own(single: Bench):
    (legacy,) = single.command("JxOpen", 2)
    assert type(legacy) is parser.Ack and legacy.code == 1
    (mav,) = mavlink(single).command("JxOpen", 5)
    assert isinstance(mav, MavAck) and (mav.code, mav.module, mav.role) == (1, 1, "M")
    assert mav.mav.name == "HEXBOT_ACK"
    assert single.actuators()[0] == (False, True, False, False, True, False)
    single.host.set_framing(Framing.LEGACY)
    (again,) = single.command("JxClose", 2)
    assert type(again) is parser.Ack and again.code == 2
    # The control board got the same board frame from both: unused args 'N'.
    log = parser.parse_all(single.debug_read(1))
    msgs = [(e.code, e.args) for e in log if isinstance(e, parser.ControlMessage)]
    assert msgs == [(1, (2, 78, 78, 78)), (1, (5, 78, 78, 78)), (2, (2, 78, 78, 78))]


def test_refusals_come_back_as_hexbot_ack_results(single: Bench):
    mavlink(single)
    (err,) = single.command(1, 9, strict=False)
    assert isinstance(err, MavErrorReply) and (err.code, err.reason) == (1, 1)  # ARG_RANGE
    (unused,) = single.command(6, strict=False)
    assert isinstance(unused, MavAck) and unused.did_nothing
    assert dict(unused.mav.fields)["code"] == 6  # the code itself, not 'N'


def test_status_reports_schema_and_dropped_frames(single: Bench):
    mavlink(single)
    (status,) = single.command("Status")
    assert isinstance(status, MavStatus)
    assert (status.module_id, status.role, status.crc_errors) == (1, "M", 0)
    assert status.schema is not None and not single.host.warnings  # same schema


def test_a_frame_with_a_bad_checksum_is_dropped_counted_never_executed(single: Bench):
    frame = bytearray(MavlinkEncoder().encode(frames.make("JxOpen", 3), target=1))
    frame[11] ^= 0x04  # the code byte: JxOpen (1) would become SxP(5)... if it ran
    single.drain()
    single.send(bytes(frame))
    single.run(3.0)
    assert single.replies() == []
    assert single.actuators()[0] == (False,) * 6
    assert not [e for e in parser.parse_all(single.debug_read(1))
                if isinstance(e, parser.ControlMessage)]  # the control board got nothing
    (status,) = mavlink(single).command("Status")
    assert status.crc_errors == 1 and status.error == 5  # BAD_FRAME


def test_target_system_addresses_one_module_without_select(pair: Bench):
    mavlink(pair)
    (ack,) = pair.command("JxOpen", 4, target=2, settle=QUIET_S)
    assert (ack.code, ack.module) == (1, 2)
    assert pair.actuators(2)[0][3] and not any(pair.actuators(1)[0])


def test_a_frame_for_another_module_is_ignored(pair: Bench):
    pair.send(MavlinkEncoder().encode(frames.make("JxOpenAll"), target=9))
    pair.run(4.0)
    assert pair.replies() == []
    assert not any(pair.actuators(1)[0]) and not any(pair.actuators(2)[0])


def test_broadcast_replies_keep_their_ack_slots(pair: Bench):
    mavlink(pair)
    assert [(r.code, r.module) for r in pair.command("Select", 0)] == [(69, 1), (69, 2)]
    replies = pair.command("Status", settle=QUIET_S)
    assert [(type(r), r.module_id) for r in replies] == [(MavStatus, 1), (MavStatus, 2)]
    assert [e for e in pair.sim.events if e["event"] == "ir-collision"] == []


def test_replies_are_numbered_one_after_another(single: Bench):
    mavlink(single)
    seqs = [single.command("LOn")[0].mav.seq for _ in range(3)]
    single.host.set_framing(Framing.LEGACY)
    single.command("LOff")  # a legacy reply takes no MAVLink number
    mavlink(single)
    seqs.append(single.command("LOff")[0].mav.seq)
    assert seqs == [seqs[0] + i for i in range(4)]
    assert all(r.mav.missed == 0 for r in single.replies() if hasattr(r, "mav"))


def test_a_stray_mavlink_start_byte_does_not_eat_the_next_legacy_frame(single: Bench):
    replies = single.frame(b"\xfd" + pc_frame(44))
    assert [(type(r), r.code) for r in replies] == [(parser.Ack, 44)]
