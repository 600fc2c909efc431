"""MAVLink addressing (firmware mutation audit, session 32): target_system
overrides the last Select and answers at once; a half MAVLink frame
expires; a control time-out is reported as one."""

from __future__ import annotations

from fwsim import QUIET_S, Bench, pc_frame

from hexbot.protocol import frames
from hexbot.protocol.mavlink_codec import Framing, MavAck, MavlinkEncoder


def test_target_system_reaches_a_module_the_last_select_left_out(images):
    # docs/protocol.md: "target_system = a module id: that module runs the
    # command and answers at once, whatever the last Select said (the Select
    # state is left as it was)".
    bench = Bench.boot("pair")
    bench.drain()
    [(code, module)] = [(r.code, r.module) for r in bench.command("Select", 1)]
    assert (code, module) == (69, 1)
    bench.host.set_framing(Framing.MAVLINK)
    (ack,) = bench.command("JxOpen", 4, target=2, settle=QUIET_S)
    assert (ack.code, ack.module) == (1, 2)
    assert bench.actuators(2)[0][3] and not any(bench.actuators(1)[0])
    # and the selection is unchanged: a broadcast still reaches module 1 only
    bench.host.set_framing(Framing.LEGACY)
    assert [(r.code, r.module) for r in bench.command("LOn", settle=QUIET_S)] == [(44, 1)]


def test_target_system_answers_at_once_whatever_its_select_rank(images):
    # Module 1 is seventh in the last Select (its ACK slot 3.6 s away): a
    # frame that names it by target_system is answered without that wait.
    bench = Bench.boot("single")
    bench.drain()
    bench.send(pc_frame(69, 2, 3, 4, 5, 6, 7, 1))
    bench.run(5.0)
    assert [(r.code, r.module) for r in bench.replies()] == [(69, 1)]
    bench.host.set_framing(Framing.MAVLINK)
    mark = bench.send(MavlinkEncoder().encode(frames.make("LOn"), target=1))
    sent = bench.session.now()
    got = bench.session.wait_for(lambda o: isinstance(o.event, MavAck), mark, 6.0)
    assert got is not None and got.event.code == 44
    frame_s = 14 * 10 / 300  # the command itself at 300 baud
    assert got.t - sent - frame_s < 1.0, got.t - sent


def test_a_control_time_out_is_a_control_timeout_result(images, tmp_path):
    # No control board (the RF12 image never echoes): the MAVLink answer must
    # say CONTROL_TIMEOUT, never DONE, as the legacy one says '~'.
    from fwsim import BUILD, scenario_file

    bench = Bench.boot(scenario_file(tmp_path, [(1, (0, 0), 0)], control=BUILD / "rf12.elf"),
                       boot_s=9.0)
    bench.host.set_framing(Framing.MAVLINK)
    bench.drain()
    # without its control board the module has no id (0): target 0, every module
    mark = bench.send(MavlinkEncoder().encode(frames.make("JxOpen", 2), target=0))
    got = bench.session.wait_for(lambda o: isinstance(o.event, MavAck), mark, 6.0)
    assert got is not None
    fields = dict(got.event.mav.fields)
    assert fields["code"] == 1
    assert fields["result"] != 0  # not DONE
    assert got.event.timed_out, fields


def test_a_half_mavlink_frame_is_abandoned_after_the_byte_time_out(single: Bench):
    # docs/protocol.md: "A half MAVLink frame is abandoned after the same
    # inter-byte time-out as a legacy one": the legacy frame after the pause
    # is a frame, not the rest of the MAVLink one.
    half = MavlinkEncoder().encode(frames.make("JxOpen", 2), target=1)[:6]
    single.send(half)
    single.run(1.0)
    replies = single.frame(frames.encode_pc(frames.make("LOn")))
    assert [(type(r).__name__, r.code) for r in replies] == [("Ack", 44)]
