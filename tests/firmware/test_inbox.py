"""Frames that arrive while the communication board waits (for the control
board's echo, for its reply slot) are kept in order and run afterwards; a
frame beyond the inbox's four is dropped and recorded, never run half."""

from __future__ import annotations

from fwsim import BUILD, Bench, scenario_file

from hexbot.protocol import frames, parser
from hexbot.protocol.codes import ErrorCode


def encoded(*commands: tuple) -> bytes:
    return b"".join(frames.encode_pc(frames.make(*c)) for c in commands)


def replies_to(bench: Bench, data: bytes, seconds: float) -> list[parser.Event]:
    """Send ``data`` at once, then the replies heard within ``seconds``."""
    bench.drain()
    bench.send(data)
    bench.run(seconds)
    return bench.replies()


def test_frames_arriving_while_the_control_echo_is_awaited_all_run_in_order(images, tmp_path):
    # No control board (the RF12 image never answers): JxOpen waits the full
    # 2.5 s for an echo. The three frames behind it (33 bytes, more than the
    # 31-byte IR ring holds) arrive during that wait.
    scenario = scenario_file(tmp_path, [(1, (0, 0), 0)], control=BUILD / "rf12.elf")
    bench = Bench.boot(scenario, boot_s=9.0)
    replies = replies_to(bench, encoded(("JxOpen", 2), ("LOn",), ("ClearError",), ("LOff",)), 5.0)
    assert [type(r) for r in replies] == [parser.Ack] * 4, replies
    assert replies[0].timed_out
    assert [r.code for r in replies[1:]] == [44, 72, 45]
    # ClearError ran after the time-out it clears.
    (sta,) = bench.command("Status")
    assert sta.error == ErrorCode.NONE


def selected_last(bench: Bench) -> None:
    """Select module 1 seventh: every reply waits six slots per reply slot."""
    replies = replies_to(bench, encoded(("Select", 2, 3, 4, 5, 6, 7, 1)), 5.0)
    assert [(r.code, r.module) for r in replies] == [(69, 1)]


def test_several_frames_are_kept_during_a_long_addressed_reply_wait(single: Bench):
    selected_last(single)
    # Status waits 6 x 2 slots = 7.2 s; three more frames arrive meanwhile.
    replies = replies_to(single, encoded(("Status",), ("LOn",), ("LOff",), ("ClearError",)),
                         7.2 + 3 * 3.6 + 2.0)
    assert [type(r) for r in replies] == [parser.StatusReport] + [parser.Ack] * 3, replies
    assert [(r.code, r.module) for r in replies[1:]] == [(44, 1), (45, 1), (72, 1)]


def test_a_frame_beyond_the_full_inbox_is_dropped_and_reported(single: Bench):
    selected_last(single)
    # Four frames wait behind Status; the fifth finds the inbox full.
    frames_sent = encoded(("Status",), ("LOn",), ("LOff",), ("LOn",), ("LOff",), ("LOn",))
    replies = replies_to(single, frames_sent, 7.2 + 4 * 3.6 + 2.0)
    assert [(r.code, r.module) for r in replies[1:]] == [(44, 1), (45, 1), (44, 1), (45, 1)]
    (sta,) = replies_to(single, encoded(("Status",)), 10.0)
    assert sta.error == ErrorCode.BUSY
    # The module still answers what comes next.
    assert [r.code for r in replies_to(single, encoded(("ClearError",)), 5.0)] == [72]
