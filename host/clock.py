"""The session's time: the wall clock, or a simulator's virtual time.

Every wait in the host is "until this condition holds, at most T seconds",
and the clock decides what a second is:

- :class:`WallClock` (hardware, ptys): reader threads append to the
  journal and notify a condition; the waiter sleeps on it.
- :class:`PacedClock` (a simulator on its own thread, ``speed`` > 0): the
  same condition, also notified as the simulator's time advances, so "5 s"
  means five simulated seconds whatever the load.
- :class:`SteppedClock` (a stepped simulator, ``speed=0``): nothing happens
  unless the waiter makes it happen, so waiting *is* running the simulator
  in slices and pumping the ports between them. The same calls give the
  same trace.
"""

from __future__ import annotations

import threading
import time
from collections.abc import Callable
from typing import Protocol

from hexbot.protocol.simulation import SimulatorAccess

STEP_S = 0.01  # simulated time between two looks: a third of a 300-baud byte


class Clock(Protocol):
    def now(self) -> float:
        """Seconds since the session started (simulated on a simulator)."""

    def wait(self, ready: Callable[[], bool], timeout: float) -> bool:
        """Until ``ready()`` (True) or ``timeout`` seconds passed (False)."""

    def wake(self) -> None:
        """Something a waiter may be waiting for changed (cancel, port state)."""


class WallClock:
    """Real time; waits sleep on ``condition`` (the host's journal condition)."""

    def __init__(self, condition: threading.Condition) -> None:
        self._condition = condition
        self._t0 = time.monotonic()

    def now(self) -> float:
        return time.monotonic() - self._t0

    def wait(self, ready: Callable[[], bool], timeout: float) -> bool:
        with self._condition:
            return self._condition.wait_for(ready, max(0.0, timeout))

    def wake(self) -> None:
        with self._condition:
            self._condition.notify_all()


class PacedClock:
    """Virtual time of a simulator that runs on its own thread (speed > 0).
    Waits sleep on the host's condition, which the simulator notifies each
    time its clock advances; the deadline is in simulated seconds, plus
    ``LATENCY_S`` of wall time for the host to read what the simulator
    produced (at 50x, 0.25 s of reading is 12 simulated seconds)."""

    LATENCY_S = 0.25

    def __init__(self, condition: threading.Condition, simulator: SimulatorAccess) -> None:
        self._condition = condition
        self.simulator = simulator
        self._t0 = simulator.now()
        simulator.on_advance(self.wake)

    def now(self) -> float:
        return self.simulator.now() - self._t0

    def wait(self, ready: Callable[[], bool], timeout: float) -> bool:
        end = self.now() + max(0.0, timeout) + self.LATENCY_S * self.simulator.speed
        with self._condition:
            while not ready():
                if self.now() >= end:
                    return False
                self._condition.wait(1.0)  # notified at every simulated step
            return True

    def wake(self) -> None:
        with self._condition:
            self._condition.notify_all()


class SteppedClock:
    """Virtual time of a stepped simulator; ``pump`` moves what the ports
    received into the session after each step."""

    def __init__(self, simulator: SimulatorAccess, pump: Callable[[], None]) -> None:
        self.simulator = simulator
        self._pump = pump
        self._t0 = simulator.now()

    def now(self) -> float:
        return self.simulator.now() - self._t0

    def wait(self, ready: Callable[[], bool], timeout: float) -> bool:
        end = self.simulator.now() + max(0.0, timeout)
        self._pump()
        while not ready():
            before = self.simulator.now()
            left = end - before
            if left <= 1e-9:
                return False
            self.simulator.advance(min(STEP_S, left))
            self._pump()
            if self.simulator.now() <= before:
                return ready()  # less than one cycle was left: the deadline is here
        return True

    def wake(self) -> None:
        pass  # the waiter is the only thread that moves time
