"""Replay pacing (speed, pause, seek) on a fake clock, and `hexbot replay`'s
--from/--to/--speed on the recorded flower7 session."""

from __future__ import annotations

import json
import threading
from pathlib import Path

import pytest

from hexbot.cli import main
from hexbot.host.replay_control import ReplayControl

CAPTURE = Path(__file__).parent / "data" / "flower7_session.hbcap"


class FakeClock:
    def __init__(self) -> None:
        self.now = 100.0

    def __call__(self) -> float:
        return self.now


def test_position_runs_at_speed_stands_still_paused_and_seeks_forward():
    clock = FakeClock()
    control = ReplayControl(2.0, start=1.0, end=18.7, clock=clock)
    clock.now += 3
    assert control.position() == 7.0
    control.set_paused(True)
    clock.now += 5
    assert control.position() == 7.0
    assert control.describe() == "7.0 s of 18.7 s, 2x, paused"
    control.seek(12.0)
    assert control.position() == 12.0
    control.seek(3.0)  # no rewind: what was played stays played
    assert control.position() == 12.0
    control.set_paused(False)
    assert control.faster() == 4.0
    clock.now += 1
    assert control.position() == 16.0
    assert control.slower() == 2.0 and control.slower() == 1.0


def test_speed_steps_stop_at_the_ends_and_must_be_positive():
    control = ReplayControl(64.0, clock=FakeClock())
    assert control.faster() == 64.0
    control.set_speed(0.125)
    assert control.slower() == 0.125
    with pytest.raises(ValueError):
        control.set_speed(0)


def test_wait_until_returns_at_once_after_a_seek_and_false_when_cancelled():
    control = ReplayControl(1.0, clock=FakeClock())  # a clock that never moves
    control.set_paused(True)
    cancel = threading.Event()
    done: list[bool] = []
    waiter = threading.Thread(target=lambda: done.append(control.wait_until(5.0, cancel)))
    waiter.start()
    control.seek(5.0)  # wakes the waiter although paused
    waiter.join(timeout=30)
    assert done == [True]
    cancel.set()
    assert control.wait_until(9.0, cancel) is False


def test_cli_from_and_to_print_only_that_window(capsys):
    assert main(["replay", str(CAPTURE), "--from", "5.7", "--to", "5.9", "--port", "ir"]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert [line.split()[0] for line in lines] == ["5.736", "5.781", "5.781", "5.856", "5.857"]
    assert lines[3].endswith("< S01 ACK 65 Ref")


def test_cli_paced_replay_prints_the_same_records(capsys):
    assert main(["replay", str(CAPTURE), "--from", "18", "--json"]) == 0
    fast = capsys.readouterr().out
    assert main(["replay", str(CAPTURE), "--from", "18", "--speed", "64", "--json"]) == 0
    assert capsys.readouterr().out == fast and fast


def test_cli_rejects_a_window_that_ends_before_it_starts(capsys):
    assert main(["replay", str(CAPTURE), "--from", "7", "--to", "6"]) == 2
    assert "--to 6 is before --from 7" in capsys.readouterr().err


def test_a_reply_split_by_a_quiet_second_is_garbage_in_replays_as_it_was_live(tmp_path, capsys):
    """Live, the parser gives up a half reply after a quiet second; the two
    replays (the CLI's and the console's) must not join it to the next bytes
    and invent an acknowledgement from module 2."""
    from hexbot.host.capture import read_capture
    from hexbot.host.host import Host
    from hexbot.protocol.parser import Ack, Garbage

    capture = tmp_path / "split.hbcap"
    capture.write_text("# hexbot-capture 1\n"
                       f"1.000 ir rx {b'M01: ACKE'.hex()}0a0d\n"
                       f"2.500 ir rx {b'M0'.hex()}\n"
                       f"4.500 ir rx {b'2: ACKE'.hex()}0a0d\n")
    assert main(["replay", str(capture), "--json"]) == 0
    rows = [json.loads(line) for line in capsys.readouterr().out.splitlines()]
    assert [(r["t"], r["kind"]) for r in rows] == [
        (1.0, "ack"), (3.5, "garbage"), (4.5, "garbage"), (4.5, "ack")]
    assert rows[0]["module"] == 1 and rows[3].get("module") is None

    seen = []
    host = Host()
    host.add_listener(lambda ev: seen.append(ev))
    host.replay(read_capture(capture))
    events = [(o.t, type(o.event)) for o in seen if hasattr(o, "event")]
    assert events == [(1.0, Ack), (3.5, Garbage), (4.5, Garbage), (4.5, Ack)]
