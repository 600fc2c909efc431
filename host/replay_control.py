"""Pacing of a capture replay: speed, pause and seek.

A replay has a *position* in capture seconds. While playing it advances
at ``speed`` times the wall clock; paused it stands still; a seek sets it.
The player plays every record whose time is at or before the position, so
a forward seek plays the records it skips at once (the parser and the
cluster model see every byte; the terminals show them with their recorded
times). The control is shared between the UI thread (keys) and the
replaying thread (``wait_until``), so every change wakes the waiter.
"""

from __future__ import annotations

import threading
import time
from collections.abc import Callable

SPEEDS = (0.125, 0.25, 0.5, 1.0, 2.0, 4.0, 8.0, 16.0, 32.0, 64.0)


class ReplayControl:
    def __init__(self, speed: float = 1.0, start: float = 0.0, *, end: float | None = None,
                 clock: Callable[[], float] = time.monotonic) -> None:
        if speed <= 0:
            raise ValueError(f"replay speed must be positive, got {speed:g}")
        self._clock = clock
        self._cond = threading.Condition()
        self._speed = speed
        self._paused = False
        self._base_pos = start
        self._base_wall = clock()
        self.end = end  # the capture's last time, for "12.0 s of 18.7 s"

    # --- what the UI reads -------------------------------------------------

    @property
    def speed(self) -> float:
        return self._speed

    @property
    def paused(self) -> bool:
        return self._paused

    def position(self) -> float:
        with self._cond:
            return self._position()

    def _position(self) -> float:
        if self._paused:
            return self._base_pos
        return self._base_pos + (self._clock() - self._base_wall) * self._speed

    def describe(self) -> str:
        """``12.0 s of 18.7 s, 2x`` (``, paused``)."""
        of = f" of {self.end:.1f} s" if self.end is not None else ""
        state = ", paused" if self._paused else ""
        return f"{self.position():.1f} s{of}, {self._speed:g}x{state}"

    # --- what the keys change ------------------------------------------------

    def _rebase(self, position: float) -> None:
        self._base_pos, self._base_wall = position, self._clock()
        self._cond.notify_all()

    def set_speed(self, speed: float) -> None:
        if speed <= 0:
            raise ValueError(f"replay speed must be positive, got {speed:g}")
        with self._cond:
            self._rebase(self._position())
            self._speed = speed

    def faster(self) -> float:
        """The next of SPEEDS above the current speed (the top stays)."""
        self.set_speed(next((s for s in SPEEDS if s > self._speed), self._speed))
        return self._speed

    def slower(self) -> float:
        self.set_speed(next((s for s in reversed(SPEEDS) if s < self._speed), self._speed))
        return self._speed

    def set_paused(self, paused: bool) -> None:
        with self._cond:
            self._rebase(self._position())
            self._paused = paused

    def toggle_pause(self) -> bool:
        self.set_paused(not self._paused)
        return self._paused

    def seek(self, position: float) -> None:
        """Move to ``position`` (capture seconds). Forward only: what was
        played stays played (a rewind would have to rebuild the model)."""
        with self._cond:
            self._rebase(max(self._position(), position))

    # --- what the player calls ------------------------------------------------

    def wait_until(self, t: float, cancel: threading.Event) -> bool:
        """Block until the position reaches ``t``; False when cancelled."""
        with self._cond:
            while not cancel.is_set():
                ahead = t - self._position()
                if ahead <= 0:
                    return True
                # paused: wait for a key (or a cancel, checked every 0.1 s)
                wait = 0.1 if self._paused else min(0.1, ahead / self._speed)
                self._cond.wait(wait)
            return False
