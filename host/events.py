"""What the host tells its listeners (console, monitor, scripts): typed events.

Listeners are called from reader threads (or the simulating thread) and
must hand work over to their own thread. Every event carries the session
time ``t`` (seconds; simulated seconds on a simulated clock).
"""

from __future__ import annotations

import enum
from collections.abc import Callable
from dataclasses import dataclass

from hexbot.protocol.parser import Event
from hexbot.protocol.simulation import PlantVerdict


class TrafficDirection(enum.Enum):
    TX = "tx"  # PC -> module
    RX = "rx"  # module -> PC


@dataclass(frozen=True)
class Traffic:
    """Bytes sent or received on a port."""

    port: str
    direction: TrafficDirection
    t: float
    data: bytes


@dataclass(frozen=True)
class Observed:
    """One event of the reply parser, numbered in the session's journal."""

    seq: int
    t: float
    port: str
    event: Event


@dataclass(frozen=True)
class PortChanged:
    """A port connected, was lost or closed (``state`` is a LinkState)."""

    port: str
    state: object
    detail: str
    t: float


@dataclass(frozen=True)
class SimVerdict:
    """The embedded simulator's plant judged a rotation (simulated ports only)."""

    verdict: PlantVerdict


@dataclass(frozen=True)
class HostWarning:
    """Something the user must know that is no error of one command (a
    module's firmware speaks another protocol schema)."""

    t: float
    text: str


HostEvent = Traffic | Observed | PortChanged | SimVerdict | HostWarning
Listener = Callable[[HostEvent], None]
