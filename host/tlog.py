"""The session's MAVLink frames as a ``.tlog``: pymavlink's telemetry-log
format, which ``mavutil.mavlink_connection(path)``, ``mavlogdump.py`` and
MAVProxy read: per frame an 8-byte big-endian time stamp in microseconds
since the Unix epoch, then the frame's bytes as they were on the wire.

Frames the PC sent are logged whole from the bytes written; received ones
once the parser has checked them (a frame with a bad CRC is not a
message and stays in the byte capture only).
"""

from __future__ import annotations

import struct
import threading
from pathlib import Path

from hexbot.protocol.mavlink_codec import STX

_STAMP = struct.Struct(">Q")


class TlogWriter:
    """Append-only, thread-safe, flushed per frame. ``started`` is the Unix
    time of the session's t = 0."""

    def __init__(self, path: Path, started: float) -> None:
        self.path = Path(path)
        self._started = started
        self._lock = threading.Lock()
        self._file = self.path.open("ab")  # every session has one, empty without MAVLink

    def sent(self, t: float, data: bytes) -> None:
        if data[:1] == bytes([STX]):
            self._write(t, data)

    def received(self, t: float, frame: bytes) -> None:
        self._write(t, frame)

    def _write(self, t: float, frame: bytes) -> None:
        with self._lock:
            if self._file is None:
                self._file = self.path.open("ab")
            self._file.write(_STAMP.pack(round((self._started + t) * 1e6)) + frame)
            self._file.flush()

    def close(self) -> None:
        with self._lock:
            if self._file is not None:
                self._file.close()
                self._file = None
