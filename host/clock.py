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

On the wall clock and the paced one, a wait whose deadline passed while the
reader thread is behind (bytes unread at the port, half a reply parsed)
waits for it, at most :data:`BEHIND_MAX_S` more: on a loaded machine what
the reader has not read yet may be the answer, which came in time.

On a simulator's clock time is the simulator's: when it stops (a fault of
its core, and its port is lost for good), no deadline will ever come. A
lost port wakes every waiter at once: one whose ``ready()`` accepts a lost
port returns and judges it (the session's exchange: a "port lost"
outcome); any other gets :class:`~hexbot.errors.LinkUnavailableError`
with the reason, instead of waiting for ever.
"""

from __future__ import annotations

import threading
import time
from collections.abc import Callable
from typing import Protocol

from serial import SerialException

from hexbot.errors import LinkUnavailableError
from hexbot.protocol.simulation import SimulatorAccess

STEP_S = 0.01  # simulated time between two looks: a third of a 300-baud byte
#: Why the simulator behind the clock stopped (its port lost), or None while it runs.
Stopped = Callable[[], str | None]


class Clock(Protocol):
    def now(self) -> float:
        """Seconds since the session started (simulated on a simulator)."""

    def wait(self, ready: Callable[[], bool], timeout: float) -> bool:
        """Until ``ready()`` (True) or ``timeout`` seconds passed (False);
        LinkUnavailableError if time stopped first (a simulator that stopped)."""

    def wake(self) -> None:
        """Something a waiter may be waiting for changed (cancel, port state)."""


#: Wall seconds a wait stays past its deadline while the reader is behind
#: (bytes unread at the port, half a reply parsed): a loaded machine's
#: reader thread can lag the line, and what it has not read yet may be the
#: answer. Bounded: a port that never stops talking.
BEHIND_MAX_S = 5.0
Behind = Callable[[], bool]


def _nothing_behind() -> bool:
    return False


def _grace(condition: threading.Condition, ready: Callable[[], bool],
           behind: Behind) -> bool:
    """Past a deadline, with ``condition`` held: wait while the reader is
    behind, until ``ready()`` or :data:`BEHIND_MAX_S`."""
    late = time.monotonic()
    while behind() and time.monotonic() - late <= BEHIND_MAX_S:
        if condition.wait_for(ready, 0.02):  # the reader's events notify it
            return True
    return ready()


class WallClock:
    """Real time; waits sleep on ``condition`` (the host's journal condition)."""

    def __init__(self, condition: threading.Condition, behind: Behind = _nothing_behind) -> None:
        self._condition = condition
        self._behind = behind
        self._t0 = time.monotonic()

    def now(self) -> float:
        return time.monotonic() - self._t0

    def wait(self, ready: Callable[[], bool], timeout: float) -> bool:
        with self._condition:
            return (self._condition.wait_for(ready, max(0.0, timeout))
                    or _grace(self._condition, ready, self._behind))

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

    def __init__(self, condition: threading.Condition, simulator: SimulatorAccess,
                 stopped: Stopped, behind: Behind = _nothing_behind) -> None:
        self._condition = condition
        self.simulator = simulator
        self._stopped = stopped  # notified on the condition too (the port's state)
        self._behind = behind
        self._t0 = simulator.now()
        simulator.on_advance(self.wake)

    def now(self) -> float:
        return self.simulator.now() - self._t0

    def wait(self, ready: Callable[[], bool], timeout: float) -> bool:
        # a reader that lags more than LATENCY_S (a loaded machine): _grace
        end = self.now() + max(0.0, timeout) + self.LATENCY_S * self.simulator.speed
        with self._condition:
            while not ready():
                why = self._stopped()
                if why is not None:  # its time will not move again
                    raise LinkUnavailableError(why)
                if self.now() >= end:
                    return _grace(self._condition, ready, self._behind)
                self._condition.wait(1.0)  # notified at every simulated step
            return True

    def wake(self) -> None:
        with self._condition:
            self._condition.notify_all()


class SteppedClock:
    """Virtual time of a stepped simulator; ``pump`` moves what the ports
    received into the session after each step."""

    def __init__(self, simulator: SimulatorAccess, pump: Callable[[], None],
                 stopped: Stopped) -> None:
        self.simulator = simulator
        self._pump = pump
        self._stopped = stopped
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
            try:
                self.simulator.advance(min(STEP_S, left))
            except SerialException as exc:  # it stopped: its ports fail from now on
                self._pump()  # ... and the pump finds them lost, with the reason
                if ready():
                    return True
                raise LinkUnavailableError(self._stopped() or str(exc)) from exc
            self._pump()
            if self.simulator.now() <= before:
                return ready()  # less than one cycle was left: the deadline is here
        return True

    def wake(self) -> None:
        pass  # the waiter is the only thread that moves time
