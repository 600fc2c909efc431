"""Session capture: every byte in both directions, with millisecond times.

Format (``*.hbcap``, UTF-8 text, one record per line, flushed per line so
a killed console or a vanished port loses nothing already received)::

    # hexbot-capture 2
    # start 2026-11-22T00:45:01.123+00:00
    # port ir socket://localhost:7000 300 8N1
    0.000 ir state connected socket://localhost:7000 300 8N1
    1.234 ir tx 2a45004e4e4e4e4e4e4e23
    1.912 ir rx 0a0d0a0d4d30333a2041434b450a0d
    3.105 ir rx 0a0d0a0d53
    4.412 ir cut 4.105

Record fields: seconds since ``start`` with three decimals, the port name
(``ir`` or ``debug``; notes also ``host`` and ``sim``), the kind (``tx`` PC
to robot, ``rx`` robot to PC, ``state`` link state change: one of the link's
states, then detail, ``note`` free text, ``cut`` see below), then
lowercase hex bytes or text. Each ``rx`` record is one read from the port,
so the chunking of the original session is kept. Lines starting ``#`` are
comments. Times never go back from the first ``tx``, ``rx`` or ``cut`` on
(equal times are common: one millisecond holds many reads). The records
before it may: on the embedded simulator the set-up's notes (and, before
session 36, its ``connecting`` lines) carry wall-clock milliseconds, and the
simulation's clock starts at 0 when it connects.

A ``cut`` record (format 2) says that the live session gave up on the
half reply its parser held: a quiet second was seen on the line, and what
was held became garbage stamped at the record's text. A replay of a format
2 capture cuts there and nowhere else, so it decodes as the live session
did even where the live reader ran late (its read times then show gaps the
line never had). Format 1 captures have no such records, and a replay judges
the quiet second by their read times.
"""

from __future__ import annotations

import datetime as dt
import math
import threading
import time
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import TextIO

from hexbot import files
from hexbot.errors import ScenarioError
from hexbot.host.link import LinkState

#: The ports a record names: the session's two ports (``host.IR``,
#: ``host.DEBUG``) and the sources of notes (Host.warn and framing: host;
#: plant verdicts: sim). Another name is a malformed record.
PORTS = ("ir", "debug", "host", "sim")
#: What a ``state`` record's text starts with: the link states.
STATES = tuple(state.value for state in LinkState)
#: The records from which on times never go back (see the module docstring).
BYTE_KINDS = ("tx", "rx", "cut")

MAGIC = "# hexbot-capture 2"
#: first line -> format; format 1 (before session 33) has no ``cut`` records
FORMATS = {"# hexbot-capture 1": 1, MAGIC: 2}
KINDS = ("tx", "rx", "state", "note", "cut")


@dataclass(frozen=True)
class Record:
    t: float  # seconds since the capture started
    port: str
    kind: str  # one of KINDS
    data: bytes = b""  # tx / rx
    text: str = ""  # state / note / cut (the time stamp of what was cut)
    line: int = 0  # line number in the file it came from
    format: int = 1  # of the capture it came from (2: the live cuts are recorded)


class CaptureWriter:
    """Append-only writer; thread-safe; flushes every record."""

    def __init__(self, path: Path, clock=time.monotonic) -> None:
        self.path = Path(path)
        self.path.parent.mkdir(parents=True, exist_ok=True)
        self._clock = clock
        self._t0 = clock()
        self._lock = threading.Lock()
        self._file: TextIO | None = self.path.open("w", encoding="utf-8", newline="\n")
        started = dt.datetime.now(dt.UTC).isoformat(timespec="milliseconds")
        self._write(f"{MAGIC}\n# start {started}\n")

    def elapsed(self) -> float:
        return self._clock() - self._t0

    def use_clock(self, clock) -> None:
        """Stamp with ``clock``, which counts from the session's start (the
        session's clock: wall time, or a simulator's virtual time)."""
        with self._lock:
            self._t0 = 0.0
            self._clock = clock

    def port(self, name: str, description: str) -> None:
        self._write(f"# port {name} {description}\n")

    def record(self, port: str, kind: str, data: bytes = b"", text: str = "") -> float:
        """Write one record; returns its time stamp (seconds since start)."""
        if kind not in KINDS:
            raise ValueError(f"capture kind must be one of {KINDS}, got {kind!r}")
        body = data.hex() if kind in ("tx", "rx") else " ".join(text.split())
        # Stamp under the lock: the reader thread and the sender write
        # concurrently, and the file must stay in time order.
        with self._lock:
            t = self.elapsed()
            self._write_locked(f"{t:.3f} {port} {kind} {body}".rstrip() + "\n")
        return t

    def _write(self, text: str) -> None:
        with self._lock:
            self._write_locked(text)

    def _write_locked(self, text: str) -> None:
        if self._file is None:
            return
        self._file.write(text)
        self._file.flush()

    def close(self) -> None:
        with self._lock:
            if self._file is not None:
                self._file.close()
                self._file = None


def read_capture(path: Path) -> Iterator[Record]:
    """Records of a capture file; ScenarioError naming file and line on a
    malformed record. A truncated last line (the writer was killed
    mid-write) is skipped, since everything before it is intact."""
    path = Path(path)
    raw_lines = files.read_bytes(path, "capture").split(b"\n")
    # line by line: a writer killed in the middle of a character (a note
    # naming a non-ASCII path) leaves a half last line, not a broken file
    lines = []
    for number, raw in enumerate(raw_lines, start=1):
        try:
            lines.append(raw.decode("utf-8"))
        except UnicodeDecodeError as exc:
            if number != len(raw_lines) or number == 1:
                raise ScenarioError(f"{path}: not a hexbot capture (not UTF-8 text)") from exc
            lines.append("")  # the half last line, skipped as any other
    version = FORMATS.get(lines[0].strip()) if lines else None
    if version is None:
        raise ScenarioError(f"{path}:1: not a hexbot capture (first line must be {MAGIC!r})")
    last = len(lines) - 1  # text after the final newline: possibly half-written
    latest: Record | None = None  # the record before, from the first byte record on
    for number, raw in enumerate(lines, start=1):
        line = raw.strip()
        if not line or line.startswith("#"):
            continue
        where = f"{path}:{number}"
        try:
            rec = _parse(line, where, number, version)
            if latest is not None and rec.t < latest.t:
                raise ScenarioError(f"{where}: time {rec.t:.3f} is before {latest.t:.3f} on "
                                    f"line {latest.line}: records must not go back in time")
        except ScenarioError:
            if number - 1 == last:
                return
            raise
        if latest is not None or rec.kind in BYTE_KINDS:
            latest = rec
        yield rec


def _parse(line: str, where: str, number: int, version: int) -> Record:
    parts = line.split(" ", 3)
    if len(parts) < 3:
        raise ScenarioError(f"{where}: expected 'TIME PORT KIND DATA', got {line!r}")
    t_text, port, kind = parts[:3]
    body = parts[3] if len(parts) > 3 else ""
    t = _stamp(t_text)
    if t is None:
        raise ScenarioError(f"{where}: bad time stamp {t_text!r}")
    if port not in PORTS:
        raise ScenarioError(f"{where}: unknown port {port!r} (a capture's ports are "
                            f"{', '.join(PORTS)})")
    kinds = KINDS if version >= 2 else KINDS[:4]
    if kind not in kinds:
        raise ScenarioError(f"{where}: unknown record kind {kind!r} (expected {kinds})")
    if kind == "state" and body.split(" ", 1)[0] not in STATES:
        raise ScenarioError(f"{where}: unknown link state {body.split(' ', 1)[0]!r} "
                            f"(expected {', '.join(STATES)})")
    if kind in ("tx", "rx"):
        try:
            return Record(t, port, kind, data=bytes.fromhex(body), line=number, format=version)
        except ValueError as exc:
            raise ScenarioError(f"{where}: bad hex data {body[:40]!r}") from exc
    if kind == "cut" and _stamp(body) is None:
        raise ScenarioError(f"{where}: a cut needs the time stamp of what it cut, got {body!r}")
    return Record(t, port, kind, text=body, line=number, format=version)


def _stamp(text: str) -> float | None:
    """Seconds since the start, or None: not a finite, non-negative number
    (a paced replay would wait for ever on nan)."""
    try:
        t = float(text)
    except ValueError:
        return None
    return t if math.isfinite(t) and t >= 0 else None
