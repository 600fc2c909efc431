"""The results table: one Parquet row per finished task, written as they come.

A results folder holds the table as numbered part files
(``table/part-000001.parquet``, ...), one Arrow table to any reader
(``pyarrow.dataset.dataset(folder / "table")``, ``pandas.read_parquet``),
and whatever a kind writes beside it (``junit.xml``). Rows are buffered and
written as a new part every ``flush_rows`` rows or ``flush_seconds``
seconds, each part through a temporary file, flushed to disk, and a rename,
so an interrupt or a crash of this process (or of the machine) loses at
most the unflushed rows and never leaves a half-written part. A part that
cannot be read all the same (a disk error, a copy cut short) stops the
reading with its path: the user moves it aside. Closing the store merges
the parts into one. Reading keeps the last row of each task, so a merge
cut short by a crash only leaves duplicates that reading ignores.

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
    """Every stored row, the last one of each task; None when there are none.
    A part that cannot be read stops the reading (HexBotError naming it): a
    table without its rows would pass for the whole one (a report's counts,
    a --resume that runs them again and then merges the parts over it)."""
    folder = Path(folder)
    parts = [_read_part(p) for p in part_files(folder)]
    if not parts:
        return None
    try:
        table = pa.concat_tables(parts, promote_options="permissive")
    except (pa.ArrowInvalid, pa.ArrowTypeError, pa.ArrowNotImplementedError):
        # parts that disagree on a column's type: that column as text
        table = rows_table([row for part in parts for row in part.to_pylist()])
    last = {task: i for i, task in enumerate(table.column("task").to_pylist())}
    if len(last) < table.num_rows:
        table = table.take(sorted(last.values()))
    return table.replace_schema_metadata(parts[-1].schema.metadata)


DAMAGED_HINT = "move it aside; --resume then runs its tasks again"


def _read_part(path: Path) -> pa.Table:
    """One part file; HexBotError ``PATH: what is wrong; move it aside ...``."""
    try:
        part = pq.read_table(path)
    except (pa.ArrowException, OSError) as exc:
        # pyarrow's text repeats the path: "Could not open Parquet input source '...': "
        reason = re.sub(r"^Could not open Parquet input source '.*?': ", "", str(exc))
        reason = " ".join(reason.split()) or type(exc).__name__
        raise HexBotError(f"{path}: cannot read this part of the results table "
                          f"({reason}): {DAMAGED_HINT}") from None
    if META_KIND not in (part.schema.metadata or {}) or "task" not in part.column_names:
        raise HexBotError(f"{path}: a Parquet file, but not a part written by hexbot sweep "
                          f"(no kind in its metadata or no task column): {DAMAGED_HINT}")
    return part


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
        self._refused = False
        # what existing() read, until this store writes a part
        self._existing: tuple[pa.Table | None] | None = None
        self.written = 0
        # task id -> its place in the grid; closing sorts the table by it
        self.order: dict[str, int] = {}

    def __enter__(self) -> ResultStore:
        try:
            (self.folder / TABLE).mkdir(parents=True, exist_ok=True)
            self._lock = open(self.folder / ".lock", "w")  # noqa: SIM115 - held until close
        except OSError as exc:
            raise HexBotError(f"{self.folder}: cannot write the results there: "
                              f"{exc.strerror or exc}") from None
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
        """What is stored (read again only after this store wrote); refuses a
        folder of another kind or with a part it cannot read (and then writes
        nothing there, not even when closing)."""
        if self._existing is None:
            try:
                self._existing = (read_table(self.folder),)
            except HexBotError:
                self._refused = True
                raise
        table = self._existing[0]
        if table is not None:
            kind, _ = table_meta(table)
            if kind != self.kind:
                self._refused = True
                raise HexBotError(f"{self.folder} holds a {kind!r} sweep, not {self.kind!r}")
        return table

    def add(self, row: dict[str, Any]) -> None:
        if self._refused:
            raise HexBotError(f"{self.folder} holds another kind of sweep: no rows go there")
        self._rows.append(row)
        if (len(self._rows) >= self.flush_rows
                or time.monotonic() - self._last_flush >= self.flush_seconds):
            self.flush()

    def flush(self) -> None:
        self._last_flush = time.monotonic()
        if not self._rows:
            return
        self._write(rows_table(self._rows))
        self.written += len(self._rows)
        self._rows = []

    def close(self) -> None:
        """Write what is buffered, merge the parts into one in grid order,
        release the folder. A store that wrote no rows (or refused the folder)
        leaves the folder as it found it."""
        if self._lock is None:
            return
        try:
            self.flush()
            parts = part_files(self.folder)
            if self.written and not self._refused and parts:
                merged = read_table(self.folder)
                assert merged is not None
                ordered = self._grid_order(merged)
                if len(parts) > 1 or ordered is not None:
                    # the folder's own metadata (read_table keeps the last part's)
                    self._write(ordered if ordered is not None else merged,
                                merged.schema.metadata)
                    for p in parts:
                        p.unlink()
        finally:
            self._lock.close()
            self._lock = None

    def _grid_order(self, table: pa.Table) -> pa.Table | None:
        """The table sorted by grid order (rows not in this grid last, as they
        were); None when it is in that order already."""
        if not self.order:
            return None
        end = len(self.order)
        tasks = table.column("task").to_pylist()
        keys = [(self.order.get(t, end), i) for i, t in enumerate(tasks)]
        indices = [i for _, i in sorted(keys)]
        if indices == list(range(len(tasks))):
            return None
        return table.take(indices)

    def _write(self, table: pa.Table, meta: dict[bytes, bytes] | None = None) -> None:
        if meta is None:
            meta = {META_KIND: self.kind.encode(),
                    META_PARAMS: json.dumps(self.params).encode()}
        table = table.replace_schema_metadata(meta)
        parts = part_files(self.folder)
        number = int(PART.match(parts[-1].name).group(1)) + 1 if parts else 1
        final = self.folder / TABLE / f"part-{number:06d}.parquet"
        tmp = final.with_name(f".{final.name}.tmp")
        with open(tmp, "wb") as f:
            pq.write_table(table, f)
            f.flush()
            os.fsync(f.fileno())  # on disk before it has the part's name
        os.replace(tmp, final)
        _sync_folder(final.parent)  # the new name on disk before anything relies on it
        self._existing = None


def _sync_folder(folder: Path) -> None:
    fd = os.open(folder, os.O_RDONLY)
    try:
        os.fsync(fd)
    finally:
        os.close(fd)


_UNFIT = (pa.ArrowInvalid, pa.ArrowTypeError, pa.ArrowNotImplementedError)


def rows_table(rows: list[dict[str, Any]]) -> pa.Table:
    """The rows as an Arrow table; a column whose values Arrow cannot hold in
    one type (a figure that is a number for some tasks, text for others) is
    stored as text rather than losing every row."""
    try:
        return pa.Table.from_pylist(rows)
    except (*_UNFIT, OverflowError):
        pass
    names = list(dict.fromkeys(name for row in rows for name in row))
    columns = {}
    for name in names:
        values = [row.get(name) for row in rows]
        try:
            columns[name] = pa.array(values)
        except (*_UNFIT, OverflowError):  # OverflowError: an int beyond 64 bits
            columns[name] = pa.array([_as_text(v) for v in values], pa.string())
    return pa.table(columns)


def _as_text(value: Any) -> str | None:
    if value is None or isinstance(value, str):
        return value
    return json.dumps(value, default=str)
