"""What the session's one send-and-wait must not take for an answer: a
reply from a module that was not asked, the ACK of another command, an
ACK 'N' (unused code), and replies beyond the count asked for. Over the
pty test double, so each case is a reply the firmware would not send."""

from __future__ import annotations

from hexbot.host.session import OutcomeKind, RefusalCause, select
from hexbot.protocol import frames, parser


def test_a_module_that_was_not_addressed_does_not_answer_for_a_missing_one(responder,
                                                                           pty_session):
    # Select(1, 2); module 2 is silent, module 3 (which missed the Select
    # and still takes itself for selected) answers: two STAs, but not the
    # two that were asked for
    pty_session.request(select(1, 2))
    responder.selected = [1, 3]
    out = pty_session.exchange(frames.make("Status"), timeout=1.0)
    assert out.kind is OutcomeKind.TIMED_OUT, out.reason
    assert out.missing == (2,)
    assert [o.event.module_id for o in out.replies] == [1]
    assert [o.event.module_id for o in out.extra] == [3]


def test_an_ack_of_another_code_is_not_this_commands_answer(responder, pty_session,
                                                           monkeypatch):
    # e.g. the late ACK of a command posted without waiting
    pty_session.request(select(1))
    real = responder._answer

    def other_code(frame):
        if frame[1] == 1:  # JxOpen: answered with LOn's ACK only
            responder.write(parser.reply_ack(44, "M", 1))
            return
        real(frame)

    monkeypatch.setattr(responder, "_answer", other_code)
    out = pty_session.exchange(frames.make("JxOpen", 3), timeout=1.0)
    assert out.kind is OutcomeKind.TIMED_OUT, out.reason
    assert out.replies == ()


def test_an_unused_code_is_a_refusal_not_an_acknowledgement(pty_session):
    pty_session.request(select(1))
    out = pty_session.exchange(frames.make(6, strict=False), strict=False)
    assert out.kind is OutcomeKind.REFUSED, out.reason
    assert [r.cause for r in out.refusals] == [RefusalCause.UNUSED_CODE]


def test_replies_beyond_the_count_asked_for_are_extra(pty_session):
    # legacy mode: all seven modules answer; one was asked for, the rest
    # are extra (heard while settling), not part of the outcome's replies
    out = pty_session.exchange(frames.make("LOn"), count=1, settle=0.5)
    assert out.ok, out.reason
    assert len(out.replies) == 1 and len(out.extra) == 6
