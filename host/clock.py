"""The session's time: the wall clock, or a simulator's virtual time.

Every wait in the host is "until this condition holds, at most T seconds",
and the clock decides what a second is:

- :class:`WallClock` (hardware, ptys, a paced simulator): reader threads
  append to the journal and notify a condition; the waiter sleeps on it.
  A paced simulator's time-outs are scaled by its speed, so "5 s" means
  five simulated seconds there too.
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
    """Real time; waits sleep on ``condition`` (the host's journal condition).
    ``now`` may come from elsewhere (a paced simulator) and ``scale`` turns
    a time-out in session seconds into wall seconds."""

    def __init__(self, condition: threading.Condition,
                 now: Callable[[], float] | None = None, scale: float = 1.0) -> None:
        self._condition = condition
        t0 = time.monotonic()
        self._now = now or (lambda: time.monotonic() - t0)
        self.scale = scale

    def now(self) -> float:
        return self._now()

    def wait(self, ready: Callable[[], bool], timeout: float) -> bool:
        with self._condition:
            return self._condition.wait_for(ready, max(0.0, timeout) * self.scale)

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
            left = end - self.simulator.now()
            if left <= 1e-9:
                return False
            self.simulator.advance(min(STEP_S, left))
            self._pump()
        return True

    def wake(self) -> None:
        pass  # the waiter is the only thread that moves time
