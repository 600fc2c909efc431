"""The comm <-> control board exchange on the paths no test reached
(firmware mutation audit, session 32): stops, late and wrong echoes, a
control board that restarts mid-command, frames sent while booting."""

from __future__ import annotations

import pytest
from fwsim import Bench, pc_frame, replies_to

from hexbot.protocol import frames, parser
from hexbot.protocol.codes import ErrorCode


def encoded(*commands: tuple) -> bytes:
    return b"".join(frames.encode_pc(frames.make(*c)) for c in commands)


def test_a_rotation_stopped_by_a_frame_for_another_module_lets_go_of_its_actuators(images):
    # The frame that stops module 1's rotation is meant for another module
    # (id 3, absent here, so that no ACK shares module 1's slot): module 1's
    # control board never sees it, so only the comm board's TurnOffAll ends
    # the rotation it just reported stopped.
    bench = Bench.boot("pair")
    (ack,) = bench.command("Select", 1)
    assert (ack.code, ack.module) == (69, 1)
    mark = bench.send(frames.encode_pc(frames.make("MCW", 1, 100, 100, 250)))
    bench.run(1.5)  # phase 2: joints open, magnets on
    assert not bench.all_off(1)
    bench.send(encoded(("Select", 3), ("JxOpen", 3)))
    (err,) = replies_to(bench, mark, 1, 6.0)
    assert isinstance(err.event, parser.ErrorReply), err.event
    assert (err.event.code, err.event.reason, err.event.module) == (21, ErrorCode.STOPPED, 1)
    bench.run(0.2)  # well before the rotation's own end (2.5 s of phase 3 left)
    assert bench.all_off(1), bench.actuators(1)


def test_a_control_restart_during_a_command_answers_it_timed_out_and_runs_the_next(single: Bench):
    # The control board restarts while the comm board forwards JxOpen(2): the
    # frame is lost in its boot, the comm board answers '~' after 2.5 s and
    # sends TurnOffAll without waiting. That TurnOffAll's echo arrives while
    # the next command (queued meanwhile) waits for its own: it must be
    # skipped, not taken for a wrong echo.
    mark = single.send(encoded(("JxOpen", 2), ("JxOpen", 3)))
    single.run(0.25)  # the first frame is still on the IR link
    control = single.sim.modules[1].control
    control.cluster.reset(control.index)
    first, second = replies_to(single, mark, 2, 8.0)
    assert isinstance(first.event, parser.Ack) and first.event.timed_out, first.event
    assert isinstance(second.event, parser.Ack) and second.event.code == 1, second.event
    joints, _magnets = single.actuators()
    assert joints == (False, False, True, False, False, False)
    # after a time-out the comm board switched everything off: what the
    # control board ran is unknown (the TurnOffAll shows on its debug port)
    assert b"ACK\x14" in single.debug_read(1)


def test_a_frame_sent_while_the_module_boots_is_not_run_after_boot(images):
    # "Nothing sent during boot is for us" (comm main.c): a frame that came
    # in during the handshake and the boot slot is dropped, not run later.
    bench = Bench.boot("single", boot_s=0.3)
    bench.send(frames.encode_pc(frames.make("LOn")))
    bench.run(7.0)
    heard = bench.drain()
    assert b"COMM. LISTENING" in heard, heard
    assert b"ACK" not in heard, heard  # LOn did not run once booted
    (sta,) = bench.command("Status")
    assert sta.module_id == 1


@pytest.mark.parametrize("name, joint, code", [("MCW", 4, 21), ("MCCW", 5, 22)])
def test_mobile_rotations_in_either_direction_forget_the_cell(images, name, joint, code):
    # MCW and MCCW move the mobile module: Status must not keep reporting
    # its old cell as localized.
    bench = Bench.boot("pair")
    bench.command("Select", 1)
    bench.command("Ref")
    bench.command("Select", 0)
    bench.command("Localize")
    bench.command("Select", 2)
    (sta,) = bench.command("Status")
    assert sta.localized
    (ack,) = bench.command(name, joint, 10, 10, 10)
    assert isinstance(ack, parser.Ack) and ack.code == code, ack
    (sta,) = bench.command("Status")
    assert not sta.localized, sta


MCW_3S = pc_frame(21, 1, 100, 100, 100)  # MCW about joint 1, 1 s per phase


def test_several_frames_that_do_not_drive_the_control_board_let_a_rotation_end(single: Bench):
    # Status and an LED function wait in the inbox, two of them as well as
    # one: neither stops the rotation.
    mark = single.send(MCW_3S)
    sent = single.session.now()
    single.run(1.5)
    single.send(encoded(("Status",), ("LOn",)))
    ack, sta, lon = replies_to(single, mark, 3, 10.0)
    assert isinstance(ack.event, parser.Ack) and ack.event.code == 21, ack.event
    assert ack.t - sent >= 3.0  # ran to its end
    assert isinstance(sta.event, parser.StatusReport) and sta.event.error == ErrorCode.NONE
    assert isinstance(lon.event, parser.Ack) and lon.event.code == 44


def test_a_combined_rotation_stops_a_running_rotation(single: Bench):
    # CW/CCW drive the control board too: like any control frame, they stop
    # the running rotation (ERR STOPPED), then run.
    mark = single.send(MCW_3S)
    single.run(1.5)
    single.send(encoded(("CW", 1, 10, 10, 10, 1, 10, 10, 10)))
    err, ack = replies_to(single, mark, 2, 10.0)
    assert isinstance(err.event, parser.ErrorReply), err.event
    assert (err.event.code, err.event.reason) == (21, ErrorCode.STOPPED)
    assert isinstance(ack.event, parser.Ack) and ack.event.code == 67, ack.event


def test_a_wrong_echo_is_refused_and_switches_the_control_board_off(single: Bench):
    # A byte corrupted on the board link (injected into the comm board's
    # UART0 while it waits for the echo of JxOpen(3)) is not the echo: the
    # command is refused (CONTROL_MISMATCH) and, since what the control board
    # runs is unknown, it is told TurnOffAll: no joint stays open after ERR.
    comm = single.sim.modules[1].comm
    mark = single.send(frames.encode_pc(frames.make("JxOpen", 3)))
    single.run(0.33)  # the frame is nearly in (11 bytes at 300 baud)
    for _ in range(60):  # a wrong byte every 2.5 ms for 150 ms
        comm.cluster.uart_put(comm.index, 0, 0x05)
        single.run(0.0025)
    (err,) = replies_to(single, mark, 1, 5.0)
    assert isinstance(err.event, parser.ErrorReply), err.event
    assert (err.event.code, err.event.reason) == (1, ErrorCode.CONTROL_MISMATCH)
    single.run(0.5)
    assert single.all_off(), single.actuators()
    (sta,) = single.command("Status")
    assert sta.error == ErrorCode.CONTROL_MISMATCH


def test_a_control_frame_behind_a_status_still_stops_the_rotation(single: Bench):
    # Every frame in the inbox is looked at, not only the first: a Status
    # waiting there does not hide the JxOpen behind it.
    mark = single.send(MCW_3S)
    single.run(1.5)
    single.send(encoded(("Status",), ("JxOpen", 2)))
    err, sta, ack = replies_to(single, mark, 3, 10.0)
    assert isinstance(err.event, parser.ErrorReply), err.event
    assert (err.event.code, err.event.reason) == (21, ErrorCode.STOPPED)
    assert isinstance(sta.event, parser.StatusReport)
    assert isinstance(ack.event, parser.Ack) and ack.event.code == 1
