"""Session 36's mutation audit of host/workflows.py, each test failing on
its mutant: what a localization or a rotation must refuse, and what
"verified" must mean (localize waves, crowded cells, unlocalized modules,
a lost port in All off, abandoned rotations, plant refusals and silence,
a wrong facing, a status with an error, a module missing from the check)."""

from __future__ import annotations

import pytest

from hexbot.errors import CommandRefusedError, LinkUnavailableError
from hexbot.host import workflows
from hexbot.protocol.codes import ErrorCode


def test_two_modules_reporting_one_cell_fail_the_localization(pty_session, responder):
    # e.g. two modules took Ref: the poses have two origins
    responder.modules[2].position = responder.modules[1].position
    with pytest.raises(CommandRefusedError, match="modules 2, 3 all report"):
        workflows.localize(pty_session, 1)


def test_a_module_not_localized_after_localize_fails_it(pty_session, responder, monkeypatch):
    real = responder._answer

    def module_4_unheard(frame):
        real(frame)
        responder.modules[3].localized = False  # its report never came

    monkeypatch.setattr(responder, "_answer", module_4_unheard)
    with pytest.raises(CommandRefusedError, match=r"not localized after Localize: module\(s\) 4"):
        workflows.localize(pty_session, 1)


def test_verify_plant_on_hardware_is_refused_before_anything_moves(pty_session, responder):
    workflows.localize(pty_session, 1)
    sent = len(responder.received)
    with pytest.raises(CommandRefusedError, match="verify=plant needs the embedded simulator"):
        workflows.rotate(pty_session, "CW", 5, 3, 1, verify=workflows.Verify.PLANT)
    assert responder.received[sent:] == []


def test_a_localize_refused_for_another_reason_than_not_heard_is_not_sent_again(
        pty_session, responder, monkeypatch):
    # another wave helps a module that heard nobody (NOT_HEARD), nothing else
    real = responder._answer

    def module_2_stopped(frame):
        if frame[1] != 66:
            return real(frame)
        for m in responder._targets():
            if m.ident == 2:
                responder._reply(m, b"ERR" + bytes([66, ErrorCode.STOPPED]))
            else:
                responder._reply(m, b"ACK" + bytes([66]))

    monkeypatch.setattr(responder, "_answer", module_2_stopped)
    with pytest.raises(CommandRefusedError, match="module 2: ERR STOPPED"):
        workflows.localize(pty_session, 1)
    assert [f[1] for f in responder.received].count(66) == 1


def test_all_off_on_a_lost_port_says_the_port_is_lost(pty_session, responder):
    responder.close()  # unplugged
    assert pty_session.wait_for(lambda o: False, 0, 10.0) is None  # ends once lost
    with pytest.raises(LinkUnavailableError, match="port lost"):
        workflows.all_off(pty_session)


def test_a_rotation_abandoned_before_any_answer_leaves_no_place_to_aim_from(
        pty_session, responder, monkeypatch):
    # Escape while the rotation's ACKs have not come (they never will): the
    # module may have moved, so the next rotation must not aim from the old place
    from hexbot.errors import CancelledError

    workflows.localize(pty_session, 1)
    real = responder._answer
    monkeypatch.setattr(responder, "_answer", lambda frame: pty_session.wake()
                        if frame[1] in (67, 68) else real(frame))
    with pytest.raises(CancelledError):
        workflows.rotate(pty_session, "CW", 5, 3, 1, verify=workflows.Verify.STATUS)
    with pytest.raises(CommandRefusedError, match="orientation of module 3 is stale"):
        workflows.rotate(pty_session, "CW", 5, 3, 1, verify=workflows.Verify.STATUS)


def test_a_rotation_the_plant_refuses_is_not_done(open_session):
    # flower7: module 2 turning CW about joint 4 on the centre would go to
    # (0, 1), where module 3 is
    session = open_session("flower7")
    workflows.localize(session, 1)
    with pytest.raises(CommandRefusedError, match="the plant refused: module 2"):
        workflows.rotate(session, "CW", 4, 2, 1, verify=workflows.Verify.PLANT)


def test_a_module_found_at_its_goal_facing_the_wrong_way_is_not_verified(
        pty_session, responder, monkeypatch):
    from hexbot.protocol.rotation import direction_of
    from hexbot.protocol.rotation_geometry import Rotation

    workflows.localize(pty_session, 1)
    rotation = Rotation(5, direction_of("CW"))
    goal, facing = rotation.goal_cell((0, 1)), (2 + rotation.turn) % 6  # module 3
    real = responder._answer

    def moved_but_turned_wrong(frame):
        real(frame)
        if frame[1] in (67, 68):
            responder.modules[2].position, responder.modules[2].yref = goal, (facing + 1) % 6
            responder.modules[3].position = (5, 5)  # module 4 was there (no plant here)

    monkeypatch.setattr(responder, "_answer", moved_but_turned_wrong)
    with pytest.raises(CommandRefusedError, match=f"facing {facing} .* facing {(facing + 1) % 6}"):
        workflows.rotate(pty_session, "CW", 5, 3, 1, verify=workflows.Verify.LOCALIZE)


def test_a_status_check_refuses_a_module_that_reports_an_error(pty_session, responder,
                                                               monkeypatch):
    from hexbot.protocol import parser

    workflows.localize(pty_session, 1)
    real = responder._answer

    def status_with_error(frame):
        if frame[1] != 70 or responder.selected != [3]:
            return real(frame)
        responder.write(parser.reply_status(3, "M", False, 0, 1, 2, ErrorCode.STOPPED,
                                            prefix_role="M", schema=responder.schema))

    monkeypatch.setattr(responder, "_answer", status_with_error)
    with pytest.raises(CommandRefusedError, match="module 3 does not report a move"):
        workflows.rotate(pty_session, "CW", 5, 3, 1, verify=workflows.Verify.STATUS)


def test_a_module_missing_from_the_check_localization_is_not_verified(unknown_cluster,
                                                                      responder, monkeypatch):
    # module 3 is not heard after its rotation (it fell off): the
    # localization that checks it finds the others, not it
    workflows.localize(unknown_cluster, 1)
    real = responder._answer

    def module_3_gone(frame):
        real(frame)
        if frame[1] in (67, 68):
            responder.modules = [m for m in responder.modules if m.ident != 3]

    monkeypatch.setattr(responder, "_answer", module_3_gone)
    with pytest.raises(CommandRefusedError, match="module 3 reported no place after CW"):
        workflows.rotate(unknown_cluster, "CW", 5, 3, 1, verify=workflows.Verify.LOCALIZE)


def test_a_plant_that_saw_no_motion_is_a_time_out(open_session, monkeypatch):
    from hexbot.errors import HexBotTimeoutError

    session = open_session("pair")
    workflows.localize(session, 1)
    monkeypatch.setattr(session.host.simulator, "verdicts", lambda since=0: [])
    with pytest.raises(HexBotTimeoutError, match="the plant reported no motion of module 2"):
        workflows.rotate(session, "CW", 4, 2, 1, verify=workflows.Verify.PLANT)


def test_localize_sends_waves_while_each_reaches_more_modules(pty_session, responder,
                                                              monkeypatch):
    # one Localize reaches 4 hops: modules out of reach answer NOT_HEARD;
    # while a wave localizes more of them, another one is sent
    real = responder._answer
    unheard = [{5, 6, 7}, {7}, set()]  # per wave

    def waves(frame):
        if frame[1] != 66:
            return real(frame)
        out = unheard.pop(0)
        everyone = responder.selected
        responder.selected = [i for i in everyone if i not in out]
        real(frame)
        responder.selected = everyone
        for m in responder.modules:
            if m.ident in out:
                responder._reply(m, b"ERR" + bytes([66, ErrorCode.NOT_HEARD]))

    monkeypatch.setattr(responder, "_answer", waves)
    poses = workflows.localize(pty_session, 1)
    assert sorted(poses) == [1, 2, 3, 4, 5, 6, 7] and unheard == []
