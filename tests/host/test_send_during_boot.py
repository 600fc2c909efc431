"""A command sent while the modules boot is lost; the outcome says so
instead of a bare "no reply" or "replies collided?" (session 36: `hexbot
send` to a `hexbot sim --pty` that was still booting read as a dead module
or a collision of replies)."""

from __future__ import annotations

from hexbot.host.session import OutcomeKind, select
from hexbot.protocol import frames, parser


def test_a_select_sent_during_the_boot_is_lost_and_the_reason_says_the_modules_were_booting(
        open_session):
    session = open_session("pair", boot=False)  # the modules are resetting right now
    out = session.exchange(select(2))
    assert out.kind in (OutcomeKind.TIMED_OUT, OutcomeKind.GARBLED), out.reason
    assert "modules were booting (heard " in out.reason, out.reason
    assert out.reason.endswith("send it again after 'COMM. LISTENING'")
    # once booted, the same command is answered
    session.wait_booted({1, 2})
    assert session.exchange(select(2)).ok


def test_no_boot_hint_when_no_module_was_booting(silent_responder):
    from hexbot.host.host import IR, Host
    from hexbot.host.link import PortSettings
    from hexbot.host.session import Session

    host = Host()
    host.add_port(IR, PortSettings(silent_responder.path))
    host.start(5.0)
    try:
        out = Session(host, [1]).exchange(frames.make("Status"), timeout=0.5)
    finally:
        host.close()
    assert out.kind is OutcomeKind.TIMED_OUT
    assert "booting" not in out.reason


def test_the_tail_of_a_boot_text_cut_by_the_command_counts_as_a_boot(pty_session, responder,
                                                                     monkeypatch):
    # the command's own frame collided with a boot text: only its tail
    # ("... FW=0.1.0") reads, as bytes that form no reply
    def cut_boot_text(frame):
        responder.write(b"1 FW=0.1.0\n\r")

    monkeypatch.setattr(responder, "_answer", cut_boot_text)
    out = pty_session.exchange(frames.make("Status"), count=1, timeout=1.0)
    assert out.kind is OutcomeKind.GARBLED, out.reason
    assert "modules were booting (heard a boot text's tail at " in out.reason
    assert any(isinstance(g.event, parser.Garbage) for g in out.garbage)
