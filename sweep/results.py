"""The results table: one Parquet row per finished task, written as they come.

A results folder holds the table as numbered part files
(``table/part-000001.parquet``, ...), one Arrow table to any reader
(``pyarrow.dataset.dataset(folder / "table")``, ``pandas.read_parquet``),
and whatever a kind writes beside it (``junit.xml``). Rows are buffered and
written as a new part every ``flush_rows`` rows or ``flush_seconds``
seconds, each part through a temporary file and a rename, so an interrupt
or a crash of this process loses at most the unflushed rows and never
leaves a half-written part. Closing the store merges the parts into one.
Reading keeps the last row of each task, so a merge cut short by a crash
only leaves duplicates that reading ignores.

The schema's metadata records the kind and its parameter names, which the
report needs to tell parameters from figures.
"""

from __future__ import annotations

import fcntl
import json
import os
import re
import time
from pathlib import Path
from typing import IO, Any

import pyarrow as pa
import pyarrow.parquet as pq

from hexbot.errors import HexBotError

TABLE = "table"
PART = re.compile(r"^part-(\d{6})\.parquet$")
META_KIND = b"hexbot.sweep.kind"
META_PARAMS = b"hexbot.sweep.params"


def part_files(folder: Path) -> list[Path]:
    table = folder / TABLE
    if not table.is_dir():
        return []
    return sorted(p for p in table.iterdir() if PART.match(p.name))


def read_table(folder: str | Path) -> pa.Table | None:
    """Every stored row, the last one of each task; None when there are none."""
    folder = Path(folder)
    parts = [pq.read_table(p) for p in part_files(folder)]
    if not parts:
        return None
    table = pa.concat_tables(parts, promote_options="permissive")
    last = {task: i for i, task in enumerate(table.column("task").to_pylist())}
    if len(last) < table.num_rows:
        table = table.take(sorted(last.values()))
    return table.replace_schema_metadata(parts[-1].schema.metadata)


def table_meta(table: pa.Table) -> tuple[str, list[str]]:
    """The kind and parameter names recorded with a table."""
    meta = table.schema.metadata or {}
    if META_KIND not in meta:
        raise HexBotError("this Parquet table was not written by hexbot sweep "
                          "(no kind in its metadata)")
    return meta[META_KIND].decode(), json.loads(meta[META_PARAMS])


class ResultStore:
    """Appends rows to a results folder; one writer at a time (a lock file says so)."""

    def __init__(self, folder: str | Path, kind: str, params: list[str],
                 flush_rows: int = 500, flush_seconds: float = 5.0) -> None:
        self.folder = Path(folder)
        self.kind = kind
        self.params = params
        self.flush_rows = flush_rows
        self.flush_seconds = flush_seconds
        self._rows: list[dict[str, Any]] = []
        self._last_flush = time.monotonic()
        self._lock: IO[str] | None = None
        self.written = 0

    def __enter__(self) -> ResultStore:
        (self.folder / TABLE).mkdir(parents=True, exist_ok=True)
        self._lock = open(self.folder / ".lock", "w")  # noqa: SIM115 - held until close
        try:
            fcntl.flock(self._lock, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            self._lock.close()
            self._lock = None
            raise HexBotError(f"{self.folder}: another sweep is writing there") from None
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    def existing(self) -> pa.Table | None:
        """What an earlier run stored; refuses a folder of another kind."""
        table = read_table(self.folder)
        if table is not None:
            kind, _ = table_meta(table)
            if kind != self.kind:
                raise HexBotError(f"{self.folder} holds a {kind!r} sweep, not {self.kind!r}")
        return table

    def add(self, row: dict[str, Any]) -> None:
        self._rows.append(row)
        if (len(self._rows) >= self.flush_rows
                or time.monotonic() - self._last_flush >= self.flush_seconds):
            self.flush()

    def flush(self) -> None:
        self._last_flush = time.monotonic()
        if not self._rows:
            return
        self._write(pa.Table.from_pylist(self._rows))
        self.written += len(self._rows)
        self._rows = []

    def close(self) -> None:
        """Write what is buffered, merge the parts into one, release the folder."""
        if self._lock is None:
            return
        try:
            self.flush()
            parts = part_files(self.folder)
            if len(parts) > 1:
                merged = read_table(self.folder)
                assert merged is not None
                self._write(merged)
                for p in parts:
                    p.unlink()
        finally:
            self._lock.close()
            self._lock = None

    def _write(self, table: pa.Table) -> None:
        meta = {META_KIND: self.kind.encode(), META_PARAMS: json.dumps(self.params).encode()}
        table = table.replace_schema_metadata(meta)
        parts = part_files(self.folder)
        number = int(PART.match(parts[-1].name).group(1)) + 1 if parts else 1
        final = self.folder / TABLE / f"part-{number:06d}.parquet"
        tmp = final.with_name(f".{final.name}.tmp")
        pq.write_table(table, tmp)
        os.replace(tmp, final)
