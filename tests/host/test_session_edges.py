"""Session 36's mutation audit of the send-and-wait (host/session.py), each
test failing on its mutant: legacy replies of a cluster of unknown size,
debts of cancelled commands, a failed re-Select after a restart, roll
calls, the boot wait (modules that never booted, ID=00, a garbled answer
asked again, a port lost), a port closed or down, the time-out's wording.
Over the pty test double unless the firmware or slot timing matters."""

from __future__ import annotations

import pytest

from hexbot.errors import CommandRefusedError, LinkUnavailableError
from hexbot.host.events import Traffic, TrafficDirection
from hexbot.host.host import IR, Host
from hexbot.host.link import PortSettings
from hexbot.host.session import Outcome, OutcomeKind, Session, listening_id, select
from hexbot.protocol import frames, wire
from hexbot.protocol.codes import ErrorCode


def boot_text(ident: int) -> bytes:
    return wire.PREAMBLE + f"COMM. LISTENING ID={ident:02d} FW=0.1.0".encode() + wire.EOL


def test_in_legacy_mode_a_cluster_of_unknown_size_is_heard_to_the_end(unknown_cluster):
    # before any Select every module answers without an id: one reply
    # cannot tell how many will come, so each of the seven is judged
    out = unknown_cluster.exchange(frames.make("LOn"))
    assert out.ok, out.reason
    assert len(out.replies) == 7


def test_a_command_nobody_would_answer_is_refused_not_acknowledged(pty_session):
    with pytest.raises(CommandRefusedError, match="no module would answer"):
        pty_session.exchange(frames.make("Status"), modules=())


def test_a_late_reply_to_a_cancelled_command_is_not_the_next_ones_answer(responder,
                                                                         pty_session,
                                                                         monkeypatch):
    # Escape during JxOpen: its ERR STOPPED comes after the next JxOpen went
    # out, just before that one's ACK (as the firmware does after a stop)
    pty_session.request(select(1))
    real = responder._answer
    jx_open = []

    def answer(frame):
        if frame[1] != 1:  # not JxOpen
            return real(frame)
        jx_open.append(frame)
        if len(jx_open) == 1:
            pty_session.wake()  # the user's Escape, while the first waits
            return
        responder._reply(responder.modules[0], b"ERR" + bytes([1, ErrorCode.STOPPED]))
        real(frame)

    monkeypatch.setattr(responder, "_answer", answer)
    first = pty_session.exchange(frames.make("JxOpen", 3))
    assert first.kind is OutcomeKind.CANCELLED, first.reason
    second = pty_session.exchange(frames.make("JxOpen", 3), settle=0.3)
    assert second.ok, second.reason  # not "refused: ERR STOPPED", the first one's
    assert len(second.extra) == 1


def test_a_failed_select_again_after_a_restart_stops_the_command(responder, pty_session,
                                                                monkeypatch):
    # module 2 restarted (its boot text): the session says Select(1, 2)
    # again first; if that is not answered, the command must not go out to
    # a module that would run whatever it hears
    pty_session.request(select(1, 2))
    mark = pty_session.host.mark()
    responder.write(boot_text(2))
    assert pty_session.wait_for(lambda o: listening_id(o.event) == 2, mark, 5.0)
    real = responder._answer
    monkeypatch.setattr(responder, "_answer",
                        lambda frame: None if frame[1] == 69 else real(frame))
    sent = len(responder.received)
    out = pty_session.exchange(frames.make("JxOpen", 3))
    assert out.kind is OutcomeKind.TIMED_OUT and str(out.command) == "Select(1, 2)", out.reason
    assert [f[1] for f in responder.received[sent:]] == [69]  # JxOpen never sent


def test_a_roll_call_waits_for_every_module_it_knows_of(tmp_path, open_session):
    # ids 3 and 11 share a boot slot: their texts collide, the session
    # knows only 1 and 12. Select(0) must wait for 12 (rank 11), not stop
    # at two replies (1 and 3) and the quiet after them.
    session = open_session(scenario(tmp_path, [1, 3, 11, 12]))
    assert session.known == {1, 12} and not session.cluster
    out = session.exchange(select(0))
    assert out.ok, out.reason
    assert [o.event.module for o in out.replies] == [1, 3, 11, 12]
    assert session.selection == (1, 3, 11, 12)


def restarted_reference(open_session):
    """A pair localized from module 1, whose comm board then restarted and
    forgot its Ref (its boot text is in, nothing sent since)."""
    from hexbot.host import workflows

    session = open_session("pair")
    workflows.localize(session, 1)
    comm = session.host.simulator.simulator.modules[1].comm
    comm.cluster.reset(comm.index)
    session.sleep(4.0)
    return session


def test_a_reference_that_restarted_is_no_origin_any_more(open_session):
    from hexbot.host import workflows

    # the next localization may take module 2 as origin instead of being refused
    session = restarted_reference(open_session)
    session.request(frames.make("Status"))  # the session hears of the restart
    poses = workflows.localize(session, 2)
    assert poses[2].cell == (0, 0) and session.reference == 2


def test_a_reference_that_restarted_is_no_origin_even_before_the_next_exchange(open_session):
    from hexbot.host import workflows

    # the boot text alone says it (localize refused "module 1 is this
    # cluster's origin" until an exchange had looked at the restarts)
    session = restarted_reference(open_session)
    assert session.reference is None
    poses = workflows.localize(session, 2)
    assert poses[2].cell == (0, 0) and session.reference == 2


def scenario(tmp_path, ids):
    """Modules ``ids`` in a row (the first is the base)."""
    path = tmp_path / "row.toml"
    path.write_text(f'name = "row"\nseed = 1\nbase = {ids[0]}\n' + "".join(
        f"[[module]]\nid = {i}\nposition = [{n}, 0]\norientation = 0\n"
        for n, i in enumerate(ids)))
    return path


def test_a_module_that_never_booted_is_not_waited_for_by_select_all(tmp_path, open_session):
    # modules 1 and 2 were expected, only 1 is there: the session does not
    # take {1, 2} for the cluster, so Select(0) hears who answers
    session = open_session(scenario(tmp_path, [1]), boot=False)
    assert session.wait_booted({1, 2}, timeout=10.0) == {1}
    out = session.exchange(select(0))
    assert out.ok, out.reason
    assert session.selection == (1,)


def test_a_module_whose_status_came_garbled_is_asked_once_more(open_session, monkeypatch):
    session = open_session("pair")
    real = session.exchange
    calls = []

    def first_garbled(command, **kwargs):
        calls.append(command)
        out = real(command, **kwargs)
        if len(calls) == 1:  # as when two answers collided on the IR link
            return type(out)(command, OutcomeKind.GARBLED, waited=out.waited)
        return out

    monkeypatch.setattr(session, "exchange", first_garbled)
    assert session.confirm_booted([2]) == {2}
    assert len(calls) == 2


def test_a_port_closed_during_the_wait_ends_it_as_port_lost(silent_responder):
    # e.g. the console's port closed while a command waits: the verdict
    # comes at once and says why, not as a time-out much later
    host = Host()
    host.add_port(IR, PortSettings(silent_responder.path))
    host.start(5.0)
    session = Session(host, [1])
    host.add_listener(lambda e: host.channels[IR].link.close()
                      if isinstance(e, Traffic) and e.direction is TrafficDirection.TX else None)
    out = session.exchange(frames.make("Status"), timeout=10.0)
    assert out.kind is OutcomeKind.PORT_LOST, out.reason
    assert session.port_lost() == "closed"
    host.close()


def test_a_time_out_names_one_missing_module_in_the_singular():
    out = Outcome(frames.make("Status"), OutcomeKind.TIMED_OUT, missing=(2,), waited=1.0)
    assert out.reason == "Status (70): no reply from module 2 within 1.0 s (0 received)"
    two = Outcome(frames.make("Status"), OutcomeKind.TIMED_OUT, missing=(2, 3), waited=1.0)
    assert "no reply from modules 2, 3 within" in two.reason


def test_a_comm_board_without_an_id_is_not_reported_as_module_0(responder, unknown_cluster):
    # "ID=00": a comm board that got no id from its control board
    responder.write(boot_text(0) + boot_text(1))
    assert unknown_cluster.wait_booted({1}, timeout=5.0) == {1}


def test_a_comm_board_without_an_id_answers_with_id_0_and_that_is_its_answer(
        tmp_path, open_session, built_images):
    # its control board never answers the handshake (an RF12 image in its
    # place): it boots as ID=00 and its STA carries id 0, which is no
    # collision when no two expected ids share a boot slot
    path = tmp_path / "lone.toml"
    path.write_text('name = "lone"\nseed = 1\nbase = 1\n[[module]]\nid = 1\n'
                    'position = [0, 0]\norientation = 0\n'
                    f'firmware = {{ control = "{built_images / "rf12.elf"}" }}\n')
    session = open_session(path)
    out = session.exchange(frames.make("Status"))
    assert out.ok, out.reason
    assert [o.event.module_id for o in out.replies] == [0]


def test_a_port_lost_while_the_modules_boot_is_an_error_not_an_empty_boot(responder,
                                                                           unknown_cluster):
    responder.close()  # unplugged
    assert unknown_cluster.wait_for(lambda o: False, 0, 10.0) is None  # ends once lost
    assert unknown_cluster.port_lost() is not None
    with pytest.raises(LinkUnavailableError, match="ir port lost while the modules booted"):
        unknown_cluster.wait_booted({1}, timeout=10.0)


def test_a_command_to_a_port_that_is_down_is_a_port_lost_outcome(responder, pty_session):
    responder.close()  # unplugged
    assert pty_session.wait_for(lambda o: False, 0, 10.0) is None  # ends once lost
    out = pty_session.exchange(frames.make("Status"))
    assert out.kind is OutcomeKind.PORT_LOST, out.reason
    assert "is not connected" in out.detail
