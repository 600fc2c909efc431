"""The session's two logs, side by side in one folder.

- ``capture.hbcap``: byte-exact, both directions, millisecond time stamps
  (format in :mod:`hexbot.host.capture`); ``hexbot replay`` reads it.
- ``decoded.log``: the same session for people: one line per sent command
  and per parsed event, e.g. ``   12.345 ir  < M03 ACK 65 Ref``.
- ``session.tlog``: every MAVLink 2 frame of the IR port, both directions,
  in pymavlink's telemetry-log format (:mod:`hexbot.host.tlog`); print it
  with ``mavlogdump.py --dialect hexbot session.tlog`` (docs/protocol.md).

Both files are flushed on every line.
"""

from __future__ import annotations

import datetime as dt
import os
import threading
import time
from pathlib import Path
from typing import TextIO

from hexbot.host.capture import CaptureWriter
from hexbot.host.describe import describe_event, describe_tx
from hexbot.host.tlog import TlogWriter
from hexbot.protocol.parser import Event

CAPTURE_NAME = "capture.hbcap"
DECODED_NAME = "decoded.log"
TLOG_NAME = "session.tlog"


def default_log_root() -> Path:
    """``$HEXBOT_LOG_DIR`` or ``$XDG_STATE_HOME/hexbot/sessions``."""
    if os.environ.get("HEXBOT_LOG_DIR"):
        return Path(os.environ["HEXBOT_LOG_DIR"])
    state = os.environ.get("XDG_STATE_HOME") or str(Path.home() / ".local" / "state")
    return Path(state) / "hexbot" / "sessions"


def new_session_dir(root: Path | None = None) -> Path:
    """A fresh folder named by the UTC start time (suffixed if taken)."""
    root = Path(root) if root is not None else default_log_root()
    stamp = dt.datetime.now(dt.UTC).strftime("%Y%m%d-%H%M%S")
    for n in range(1000):
        path = root / (stamp if n == 0 else f"{stamp}-{n}")
        try:
            path.mkdir(parents=True, exist_ok=False)
            return path
        except FileExistsError:
            continue
    raise FileExistsError(f"no free session folder under {root}")


class SessionLog:
    def __init__(self, folder: Path) -> None:
        self.folder = Path(folder)
        self.capture = CaptureWriter(self.folder / CAPTURE_NAME)
        self._lock = threading.Lock()
        self._decoded: TextIO | None = (self.folder / DECODED_NAME).open(
            "w", encoding="utf-8", newline="\n")
        self.tlog = TlogWriter(self.folder / TLOG_NAME, time.time())  # the capture's start

    @property
    def capture_path(self) -> Path:
        return self.capture.path

    @property
    def decoded_path(self) -> Path:
        return self.folder / DECODED_NAME

    def port(self, name: str, description: str) -> None:
        self.capture.port(name, description)

    def sent(self, port: str, data: bytes) -> float:
        t = self.capture.record(port, "tx", data)
        self._line(t, port, ">", describe_tx(data))
        self.tlog.sent(t, data)
        return t

    def received(self, port: str, data: bytes) -> float:
        return self.capture.record(port, "rx", data)

    def cut(self, port: str, stamp: float) -> None:
        """Where the live decoder cut a half reply (:meth:`Host.cut`)."""
        self.capture.record(port, "cut", text=f"{stamp:.3f}")

    def event(self, t: float, port: str, ev: Event) -> None:
        self._line(t, port, "<", describe_event(ev))
        if getattr(ev, "mav", None) is not None:
            self.tlog.received(t, ev.raw)

    def state(self, port: str, text: str) -> float:
        t = self.capture.record(port, "state", text=text)
        self._line(t, port, "!", text)
        return t

    def note(self, port: str, text: str) -> None:
        t = self.capture.record(port, "note", text=text)
        self._line(t, port, "#", text)

    def _line(self, t: float, port: str, arrow: str, text: str) -> None:
        with self._lock:
            if self._decoded is not None:
                self._decoded.write(f"{t:9.3f} {port:<5} {arrow} {text}\n")
                self._decoded.flush()

    def close(self) -> None:
        self.capture.close()
        self.tlog.close()
        with self._lock:
            if self._decoded is not None:
                self._decoded.close()
                self._decoded = None
