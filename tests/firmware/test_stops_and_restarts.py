"""What the PC is told when a control sequence does not run to its end, or
when one board of a module restarts on its own: never "done", never a
module that lost its id, never an actuator left on that nobody asked for."""

from __future__ import annotations

from fwsim import Bench, pc_frame, replies_to

from hexbot.hil_sim.plant import OFF
from hexbot.protocol import frames, parser
from hexbot.protocol.codes import ErrorCode
from hexbot.protocol.timing import LOCALIZE_WINDOW_S

BOOT_TEXT = b"COMM. BOARD READY"
MCW_3S = pc_frame(21, 1, 100, 100, 100)  # MCW about joint 1, 1 s per phase








def test_a_zero_tick_led_pattern_does_not_starve_the_watchdog(single: Bench):
    # LCircle(170, 0): 6,120 waits of no time at all, about 2.5 s of LED
    # writes; the comm board used to reboot (watchdog) before its ACK.
    replies = single.frame(pc_frame(46, 170, 0), timeout=10.0)
    assert [type(r).__name__ for r in replies] == ["Ack"] and replies[0].code == 46
    assert BOOT_TEXT not in single.drain()
    (sta,) = single.command("Status")
    assert sta.module_id == 1 and sta.error == ErrorCode.NONE


def test_a_rotation_stopped_by_a_new_control_command_is_reported_stopped(single: Bench):
    mark = single.send(MCW_3S)
    single.run(1.5)  # phase 2 of 3: joints open, magnets on
    assert not single.all_off()
    single.send(frames.encode_pc(frames.make("JxOpen", 2)))
    first, second = replies_to(single, mark, 2, 8.0)
    assert isinstance(first.event, parser.ErrorReply), first.event
    assert first.event.code == 21 and first.event.reason == ErrorCode.STOPPED
    assert isinstance(second.event, parser.Ack) and second.event.code == 1
    # the rotation is over, only what the new command asked for is on
    joints, magnets = single.actuators()
    assert joints == (False, True, False, False, False, False)
    assert all(m == OFF for m in magnets)


def test_a_status_during_a_rotation_waits_for_its_end(single: Bench):
    mark = single.send(MCW_3S)
    sent = single.session.now()
    single.run(1.5)
    single.send(frames.encode_pc(frames.make("Status")))
    ack, sta = replies_to(single, mark, 2, 8.0)
    assert isinstance(ack.event, parser.Ack) and ack.event.code == 21
    assert ack.t - sent >= 3.0  # the ACK says the rotation ran to its end
    assert isinstance(sta.event, parser.StatusReport)
    assert single.all_off()


def test_an_unannounced_comm_restart_keeps_the_id_and_drops_the_actuators(single: Bench):
    single.command("SxP", 1)
    single.command("JxOpen", 2)
    assert not single.all_off()
    comm = single.sim.modules[1].comm
    comm.cluster.reset(comm.index)  # the comm board alone restarts
    single.run(4.0)
    heard = single.drain()
    assert BOOT_TEXT in heard and b"ID=01" in heard, heard
    assert single.all_off()  # the control board let go of what nobody runs any more
    (sta,) = single.command("Status")
    assert sta.module_id == 1


def test_a_control_restart_is_reported_in_status(single: Bench):
    single.command("SxP", 1)
    control = single.sim.modules[1].control
    control.cluster.reset(control.index)
    single.run(2.0)
    assert single.all_off()
    (sta,) = single.command("Status")
    assert sta.module_id == 1 and sta.error == ErrorCode.CONTROL_RESTARTED
    (ack,) = single.command("JxOpen", 3)  # and it listens again (code 1)
    assert isinstance(ack, parser.Ack) and ack.code == 1


def test_a_localize_that_waited_for_a_rotation_keeps_the_clusters_window(single: Bench):
    # Every module times the hops of a localization from the frame's arrival;
    # one that was busy must not start its window late (and miss its hops).
    mark = single.send(MCW_3S)
    single.run(1.5)
    sent = single.session.now()
    single.send(frames.encode_pc(frames.make("Localize")))
    ack, err = replies_to(single, mark, 2, LOCALIZE_WINDOW_S + 10.0)
    assert isinstance(ack.event, parser.Ack) and ack.event.code == 21
    assert isinstance(err.event, parser.ErrorReply) and err.event.reason == ErrorCode.NOT_HEARD
    frame_s = 11 * 10 / 300  # the Localize frame itself at 300 baud
    assert err.t - sent - frame_s < LOCALIZE_WINDOW_S + 0.5, (err.t - sent, LOCALIZE_WINDOW_S)


def test_zero_delay_walks_are_answered_within_their_protocol_time_out(single: Bench):
    # The steps of a walk cost time of their own: with t = 0 the walk is all
    # steps, and the PC's time-out (protocol/timing.py) must still cover it.
    for name in ("LCircle", "LFlash2", "SPTest"):
        out = single.session.exchange(frames.make(name, 255, 0))
        assert out.ok, out.reason


def test_all_off_stops_a_running_rotation_and_every_actuator(images, tmp_path):
    from fwsim import scenario_file

    from hexbot.host import workflows
    from hexbot.host.session import select

    bench = Bench.boot(scenario_file(tmp_path, [(1, (0, 0), 0), (2, (-1, 1), 0)]))
    bench.session.request(select(2))
    bench.session.request(frames.make("SxP", 3))  # module 2: a magnet left on
    bench.session.request(select(1))
    bench.send(frames.encode_pc(frames.make("MCW", 1, 250, 250, 250)))  # 7.5 s on module 1
    bench.run(1.0)
    assert not bench.all_off(1) and not bench.all_off(2)
    started = bench.session.now()
    workflows.all_off(bench.session)  # raises unless every step was acknowledged
    assert bench.session.now() - started < 5.0  # did not wait for the rotation's end
    assert bench.all_off(1) and bench.all_off(2)


def test_a_late_reply_to_an_abandoned_command_is_not_the_next_ones_answer(single: Bench):
    # The PC gives up on a 3 s rotation after 1 s and sends another: the
    # module answers the first with ERR STOPPED, then runs the second.
    first = single.session.exchange(frames.make("MCW", 1, 100, 100, 100), timeout=1.0)
    assert first.kind.value == "timed out"
    second = single.session.exchange(frames.make("MCW", 1, 10, 10, 10))
    assert second.ok, second.reason  # was: "refused: ERR STOPPED", the first one's
    (late,) = [o.event for o in second.extra]
    assert isinstance(late, parser.ErrorReply) and late.reason == ErrorCode.STOPPED
    # and the first one's ACK that never came is not waited for forever
    assert single.session.exchange(frames.make("Status")).ok


def test_after_a_module_restarts_the_session_selects_again_and_forgets_its_role(
        images, tmp_path):
    from fwsim import scenario_file

    from hexbot.host import workflows
    from hexbot.host.session import select

    bench = Bench.boot(scenario_file(tmp_path, [(1, (0, 0), 0), (2, (-1, 1), 0)]))
    workflows.localize(bench.session, 1)
    workflows.set_role(bench.session, 1, workflows.Role.SUBSTRATE)
    assert bench.host.model.module(1).role == "S"
    bench.session.request(select(2))
    comm = bench.sim.modules[1].comm
    comm.cluster.reset(comm.index)  # module 1's comm board restarts alone
    bench.run(4.0)
    # it forgot the Select: without a new one it would open its joint 3 too
    out = bench.session.request(frames.make("JxOpen", 3))
    assert [o.event.module for o in out.replies] == [2]
    assert not bench.actuators(1)[0][2] and bench.actuators(2)[0][2]
    assert any("module(s) 1 restarted" in w for w in bench.host.warnings)
    row = bench.host.model.module(1)  # the model forgot its role and place
    assert row.role == "M" and not row.localized


def test_in_legacy_mode_every_modules_answer_is_judged(images, tmp_path):
    # Before any Select every module answers, without an id. Module 2 has
    # no working control board (an RF12 image in its place): it answers
    # '~' 2.5 s after module 1's ACK, and that must fail the command.
    from fwsim import BUILD

    from hexbot.host.session import OutcomeKind, RefusalCause

    scenario = tmp_path / "deadctl.toml"
    scenario.write_text(
        'name = "deadctl"\nseed = 1\nbase = 1\n'
        "[[module]]\nid = 1\nposition = [0, 0]\norientation = 0\n"
        "[[module]]\nid = 2\nposition = [-1, 1]\norientation = 0\n"
        f'firmware = {{ control = "{BUILD / "rf12.elf"}" }}\n')
    bench = Bench.boot(scenario)
    out = bench.session.exchange(frames.make("JxOpen", 3))
    assert out.kind is OutcomeKind.REFUSED, out.reason
    assert [r.cause for r in out.refusals] == [RefusalCause.CONTROL_TIMEOUT]
    assert len(out.replies) == 2  # module 1's ACK 1 is there too


def test_select_all_waits_for_the_slot_of_every_id_it_has_heard_of(images, tmp_path):
    # On hardware the session is not told the cluster: it knows ids from
    # the boot texts. Module 12 answers Select(0) in slot 11, 6.6 s after
    # module 2; silence in between must not end the roll call.
    from fwsim import scenario_file

    from hexbot.host.session import Session, select

    bench = Bench.boot(scenario_file(tmp_path, [(2, (0, 0), 0), (12, (-1, 1), 0)]))
    session = Session(bench.host)  # no ids given
    out = session.request(select(0))
    assert sorted(o.event.module for o in out.replies) == [2, 12]
    assert session.selection == (2, 12)
    out = session.request(frames.make("Status"))
    assert sorted(o.event.module_id for o in out.replies) == [2, 12]


def test_a_select_that_one_module_missed_still_switches_the_others(images, tmp_path):
    from fwsim import scenario_file

    from hexbot.host.session import select

    bench = Bench.boot(scenario_file(tmp_path, [(1, (0, 0), 0), (2, (-1, 1), 0)]))
    bench.session.request(select(2))
    assert not bench.session.exchange(select(1, 9)).ok  # there is no module 9
    # module 1 heard it and is selected now: the session must expect it too
    out = bench.session.exchange(frames.make("Status"))
    assert [o.event.module_id for o in out.replies] == [1]
    assert out.missing == (9,)


def test_a_select_sent_without_waiting_still_decides_who_answers_next(images, tmp_path):
    from fwsim import scenario_file

    from hexbot.host.session import select

    bench = Bench.boot(scenario_file(tmp_path, [(1, (0, 0), 0), (2, (-1, 1), 0)]))
    bench.session.request(select(1, 2))
    bench.session.send(select(2))  # the console composer's Send
    bench.run(1.0)
    out = bench.session.request(frames.make("Status"))
    assert [o.event.module_id for o in out.replies] == [2]


def test_a_time_out_says_which_module_may_still_be_busy(images, tmp_path):
    from fwsim import scenario_file

    from hexbot.host.session import select

    bench = Bench.boot(scenario_file(tmp_path, [(1, (0, 0), 0), (2, (-1, 1), 0)]))
    bench.session.request(select(1))
    abandoned = bench.session.exchange(frames.make("JTest", 200, 2), timeout=1.0)
    assert not abandoned.ok
    out = bench.session.exchange(frames.make("LOn"), timeout=2.0)  # JTest still runs
    assert not out.ok
    assert "module 1 may still be running JTest" in out.reason, out.reason
