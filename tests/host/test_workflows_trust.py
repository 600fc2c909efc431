"""Session 28's console audit, below the console: what the workflows may
trust after a rotation was abandoned or sent by hand, one origin per
cluster, All off that sends every frame, the plant seen in the
localization's frame."""

from __future__ import annotations

from pathlib import Path

import pytest

from hexbot.errors import CancelledError, CommandRefusedError
from hexbot.host import workflows
from hexbot.host.cluster import ClusterModel
from hexbot.protocol import frames, parser

pytest.importorskip("hexbot.hil_sim._avr")
FIRMWARE = Path(__file__).resolve().parents[2] / "firmware" / "build"
pytestmark = pytest.mark.skipif(not (FIRMWARE / "comm.elf").exists(),
                                reason="firmware not built (make -C firmware)")


def test_a_mobile_modules_rotation_ack_makes_its_place_stale_however_it_was_sent():
    model = ClusterModel()
    model.apply("ir", parser.StatusReport(raw=b"", module_id=2, role="M", localized=True,
                                          x=-1, y=1, yref=0, error=0))
    assert model.module(2).localized
    model.apply("ir", parser.Ack(raw=b"", code=67, role="S", module=1))  # the substrate
    assert model.module(2).localized
    model.apply("ir", parser.Ack(raw=b"", code=67, role="M", module=2))  # e.g. the composer
    assert not model.module(2).localized


def test_an_abandoned_rotation_leaves_no_place_to_aim_the_next_one_from(open_session,
                                                                        monkeypatch):
    session = open_session("pair")
    workflows.localize(session, 1)
    real = session.request

    def escape_at_the_rotation(command, *args, **kwargs):
        if getattr(command, "code", None) in (67, 68):
            real(command, *args, **kwargs)  # it goes out, then the wait is abandoned
            raise CancelledError("cancelled")
        return real(command, *args, **kwargs)

    monkeypatch.setattr(session, "request", escape_at_the_rotation)
    with pytest.raises(CancelledError):
        workflows.rotate(session, "CW", 4, 2, 1, verify=workflows.Verify.PLANT)
    monkeypatch.undo()
    with pytest.raises(CommandRefusedError, match="orientation of module 2 is stale"):
        workflows.rotate(session, "CW", 4, 2, 1)


def test_a_cluster_has_one_origin_and_plans_default_to_it(open_session):
    from hexbot.planning.execute import default_reference

    session = open_session("pair")
    poses = workflows.localize(session, 2)
    assert poses[2].cell == (0, 0) and default_reference(session) == 2
    with pytest.raises(CommandRefusedError, match="module 2 is this cluster's origin"):
        workflows.localize(session, 1)  # refused before anything is sent
    # the plant, seen from the localization: module 2 at (0, 0), as the replies say
    truth = workflows.plant_placements(session)
    assert {i: p.cell for i, p in truth.items()} == {i: p.cell for i, p in poses.items()}


def test_all_off_sends_every_frame_whatever_the_replies(open_session, monkeypatch):
    session = open_session("pair")
    sent = []
    real = session.exchange

    def first_unanswered(command, *args, **kwargs):
        sent.append(str(command))
        outcome = real(command, *args, **kwargs)
        if len(sent) == 1:  # as during a rotation: a garbled or missing answer
            return type(outcome)(command, type(outcome.kind).TIMED_OUT, (), (),
                                 missing=(1,), waited=1.0)
        return outcome

    monkeypatch.setattr(session, "exchange", first_unanswered)
    with pytest.raises(CommandRefusedError, match="all frames sent"):
        workflows.all_off(session)
    assert sent == [str(frames.make("TurnOffAll")), "Select(0)", str(frames.make("TurnOffAll"))]


def test_a_status_check_assumes_the_place_but_does_not_call_it_localized(open_session):
    # (review) the status path marked the module localized at the planned
    # cell right after its own Status said it was not
    session = open_session("pair")
    workflows.localize(session, 1)
    result = workflows.rotate(session, "CW", 4, 2, 1, verify=workflows.Verify.STATUS)
    row = session.host.model.module(2)
    assert result.got is None  # nothing saw the place
    assert (row.localized, row.assumed, row.position) == (False, True, (0, 1))
    assert workflows.known_pose(session, 2).cell == (0, 1)  # the next move may aim from it
    poses = workflows.localize(session, 1)  # a localization judges it
    assert poses[2].cell == (0, 1) and session.host.model.module(2).localized
    assert not session.host.model.module(2).assumed


# --- what a rotation must not report as done ---------------------------------


def test_a_status_check_refuses_a_module_that_still_says_localized(responder, pty_session,
                                                                   monkeypatch):
    # the rotation is acknowledged, but the mobile module's Status says it is
    # still localized where it was: it did not move
    workflows.localize(pty_session, 1)
    real = responder._answer

    def stays(frame):
        real(frame)
        if frame[1] in (67, 68):
            for m in responder.modules:
                m.localized = True

    monkeypatch.setattr(responder, "_answer", stays)
    with pytest.raises(CommandRefusedError, match="module 3 does not report a move"):
        workflows.rotate(pty_session, "CW", 5, 3, 1, verify=workflows.Verify.STATUS)


def test_a_rotation_the_modules_refuse_fails_with_their_refusal(responder, pty_session,
                                                              monkeypatch):
    # the rotation frame itself is refused (ERR STOPPED): the failure must
    # say so, not leave it to a later check to notice that nothing moved
    from hexbot.protocol.codes import ErrorCode

    workflows.localize(pty_session, 1)
    real = responder._answer

    def refuse(frame):
        if frame[1] in (67, 68):
            for m in responder._targets():
                responder._reply(m, b"ERR" + bytes([frame[1], ErrorCode.STOPPED]))
            return
        real(frame)

    monkeypatch.setattr(responder, "_answer", refuse)
    with pytest.raises(CommandRefusedError, match="ERR STOPPED"):
        workflows.rotate(pty_session, "CW", 5, 3, 1, verify=workflows.Verify.STATUS)


def test_a_rotation_that_leaves_a_module_alone_is_not_a_success(open_session, tmp_path):
    from hexbot.hil_sim.geometry import Rotation, distance, neighbor, to_global

    # the pair rig plus module 3 touching only the mobile module 2
    rot = Rotation(to_global(4, 0), "CW")
    taken = {rot.goal_cell((-1, 1)), *rot.swept_cells((-1, 1)), (0, 0)}
    third = next(c for c in (neighbor((-1, 1), s) for s in range(1, 7))
                 if c not in taken and all(distance(c, o) > 1
                                           for o in [(0, 0), rot.goal_cell((-1, 1))]))
    scenario = tmp_path / "tail.toml"
    scenario.write_text('name = "tail"\nseed = 1\nbase = 1\n' + "".join(
        f"[[module]]\nid = {i}\nposition = [{x}, {y}]\norientation = 0\n"
        for i, (x, y) in ((1, (0, 0)), (2, (-1, 1)), (3, third))))
    session = open_session(scenario)
    workflows.localize(session, 1)
    with pytest.raises(CommandRefusedError, match="the cluster split"):
        workflows.rotate(session, "CW", 4, 2, 1, verify=workflows.Verify.PLANT)
