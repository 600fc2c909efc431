"""Time budgets of the planners: every method gives up in time, and says why.

Restricted pivoting makes reachability PSPACE-complete in general, so a
search may run for ever on a hard pair. Each method checks a
:class:`Deadline` between journeys and raises :class:`PlanningFailure`
with the method's name and the budget when it is used up; the caller then
tries the next method or reports the reason (``hexbot plan`` exits 1).
"""

from __future__ import annotations

import copy
import time

#: Default time budget of one ``hexbot plan`` call, in seconds (10,000 modules fit in it).
DEFAULT_BUDGET = 300.0

#: The most moves a plan may have: a memory guard (a move costs about 140 bytes
#: with the schedule's share). The fixed module's spine route needs 11.5 million
#: at 10,000 modules (1.6 GiB at peak); the old ceiling of 10 million failed every
#: direction there, after a minute each, until the time budget was gone.
MAX_MOVES = 30_000_000


class PlanningFailure(Exception):
    """A planner cannot continue; the message says why."""


class BudgetExhausted(PlanningFailure):
    """A method used up its time budget (loops over alternatives stop at once)."""


class Deadline:
    """A point in time after which a method must give up: ``seconds`` of wall
    time, and optionally ``cpu_seconds`` of this process's CPU time (a method's
    own cap, see :meth:`capped`), whichever comes first."""

    def __init__(self, seconds: float | None = DEFAULT_BUDGET,
                 cpu_seconds: float | None = None, whole: float | None = None) -> None:
        self.seconds = seconds  # of wall time (None: no limit)
        self.cpu_seconds = cpu_seconds
        # the budget this one is a share of (the plan's ``--budget``): a method
        # that got a late share of a few ms says what it was a share of
        self.whole = seconds if whole is None else whole
        self._end = None if seconds is None else time.monotonic() + seconds
        self._cpu_end = None if cpu_seconds is None else time.process_time() + cpu_seconds

    def remaining(self) -> float:
        return float("inf") if self._end is None else self._end - time.monotonic()

    def _cpu_spent(self) -> bool:
        return self._cpu_end is not None and time.process_time() >= self._cpu_end

    def expired(self) -> bool:
        return self._cpu_spent() or self.remaining() <= 0

    def share(self, fraction: float, at_least: float = 0.0) -> Deadline:
        """A deadline for one method: ``fraction`` of what is left (at least
        ``at_least`` seconds, never past this deadline)."""
        left = self.remaining()
        if left == float("inf"):
            return Deadline(None)
        return Deadline(max(0.0, min(left, max(at_least, fraction * left))), whole=self.whole)

    def capped(self, seconds: float) -> Deadline:
        """This deadline, or once the planner has used ``seconds`` of CPU time
        from now if that comes first. A method's cap counts CPU time, not wall
        time: on a machine busy with other jobs a method gets as much work done
        before its cap, so the plans are the same (a blob of 100 lost its local
        plan to the strip's, 218 -> 6,396 moves, in a bench run beside other
        jobs when the caps were wall time)."""
        capped = copy.copy(self)  # the same end and the same words for it
        capped.cpu_seconds = seconds
        capped._cpu_end = time.process_time() + seconds
        return capped

    def check(self, what: str) -> None:
        """Raise :class:`PlanningFailure` when the budget is used up; the
        message names the limit that ran out, the CPU cap or the wall time."""
        if self._cpu_spent():
            raise BudgetExhausted(f"{what}: gave up, its cap of {self.cpu_seconds:.3g} s "
                                  "of CPU time is used up")
        if self.remaining() <= 0:
            raise BudgetExhausted(f"{what}: gave up, {self.describe()} is used up")

    def describe(self) -> str:
        """'its time budget of 2 s', or with a share: 'its share (0.001 s) of
        the time budget of 3 s' (a share alone read "0 s" when it came late)."""
        if self.whole is None or self.whole == self.seconds:
            return f"its time budget of {self.seconds:.3g} s"
        return f"its share ({self.seconds:.3g} s) of the time budget of {self.whole:.3g} s"


#: A deadline that never expires (library calls without a budget).
NO_DEADLINE = Deadline(None)
