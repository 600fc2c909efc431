"""Messages the console posts itself from the host's typed events
(:mod:`hexbot.host.events`; ``post_message`` is thread-safe)."""

from __future__ import annotations

import threading

from textual.message import Message

from hexbot.host.events import Observed
from hexbot.host.link import LinkState
from hexbot.protocol.simulation import PlantVerdict


class Traffic(Message):
    """Bytes sent (``tx``) or received (``rx``) on a port."""

    def __init__(self, port: str, direction: str, t: float, data: bytes,
                 wall: float | None = None) -> None:
        super().__init__()
        self.port, self.direction, self.t, self.data = port, direction, t, data
        self.wall = wall  # the PC's clock when the reader got the bytes


class Parsed(Message):
    """One event from the reply parser."""

    def __init__(self, port: str, observed: Observed) -> None:
        super().__init__()
        self.port, self.observed = port, observed


class PortState(Message):
    def __init__(self, port: str, state: LinkState, detail: str, t: float,
                 wall: float | None = None) -> None:
        super().__init__()
        self.port, self.state, self.detail, self.t = port, state, detail, t
        self.wall = wall


class SimEvent(Message):
    """The embedded simulator's plant judged a rotation: ``Moved`` or ``Refused``."""

    def __init__(self, verdict: PlantVerdict) -> None:
        super().__init__()
        self.verdict = verdict


class HostNote(Message):
    """A warning of the host's (``HostWarning``): a module that restarted, a
    module or an image built from another protocol, a Select said again."""

    def __init__(self, text: str, t: float, wall: float | None = None) -> None:
        super().__init__()
        self.text, self.t, self.wall = text, t, wall


class CaughtUp(Message):
    """Posted after a replayed record's messages: handled, every message
    before it was too (the app handles its messages in order)."""

    def __init__(self, done: threading.Event) -> None:
        super().__init__()
        self.done = done
