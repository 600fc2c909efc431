"""The paced simulator's clock: a wait ends at its deadline in simulated
time, unless the host's reader is still behind what the simulator sent
(on a loaded machine it can lag by more than the clock's latency)."""

from __future__ import annotations

import threading
import time

from hexbot.host import clock as clock_module
from hexbot.host.clock import PacedClock, WallClock


class RunAway:
    """A simulator that runs on while the host waits: 10 simulated seconds
    pass between two looks at its clock."""

    speed = 5.0
    stepped = False

    def __init__(self) -> None:
        self.t = 0.0

    def now(self) -> float:
        self.t += 10.0
        return self.t

    def on_advance(self, callback) -> None:
        pass


def answer_late(cond: threading.Condition, answered: threading.Event, after_s: float) -> None:
    """A reader thread that gets to the answer ``after_s`` of wall time late."""
    def reader() -> None:
        time.sleep(after_s)
        with cond:
            answered.set()
            cond.notify_all()

    threading.Thread(target=reader).start()


def test_a_wait_past_its_deadline_still_sees_what_the_reader_was_behind_on():
    sim, cond = RunAway(), threading.Condition()
    answered = threading.Event()
    clock = PacedClock(cond, sim, lambda: None, behind=lambda: not answered.is_set())

    answer_late(cond, answered, 0.3)
    assert clock.wait(answered.is_set, timeout=1.0)


def test_a_wait_past_its_deadline_with_nothing_unread_times_out():
    sim, cond = RunAway(), threading.Condition()
    clock = PacedClock(cond, sim, lambda: None, behind=lambda: False)
    assert not clock.wait(lambda: False, timeout=1.0)


def test_a_port_that_never_stops_talking_does_not_hold_a_wait_for_ever(monkeypatch):
    monkeypatch.setattr(clock_module, "BEHIND_MAX_S", 0.2)
    sim, cond = RunAway(), threading.Condition()
    clock = PacedClock(cond, sim, lambda: None, behind=lambda: True)
    assert not clock.wait(lambda: False, timeout=1.0)


def test_the_wall_clock_also_waits_for_a_reader_that_is_behind():
    # hardware: the reply is in the port's buffer at the deadline, the
    # reader thread has not run yet
    cond = threading.Condition()
    answered = threading.Event()
    clock = WallClock(cond, behind=lambda: not answered.is_set())

    answer_late(cond, answered, 0.3)
    assert clock.wait(answered.is_set, timeout=0.05)
    assert not WallClock(cond).wait(lambda: False, timeout=0.05)
