"""Reading configurations from files.

Two formats:

* **grid text** (``*.txt`` and anything not ``*.toml``): rows of 0/1 exactly
  as the thesis writes its matrices, row 1 on top; the cell in row ``r``,
  column ``c`` of an ``R``-row grid is the axial cell ``(c - 1, R - r)``.
  MATLAB decorations are tolerated (one ``I = [`` before the first row,
  ``]``, ``;``, ``,``, ``...``), and ``#`` or ``%`` start a comment; any
  other token is an error, a bracket inside a bracket too (a TOML
  configuration in a file not named ``.toml`` fails there instead of being
  read as a grid). One pair of brackets, if any, holds all the rows: a
  ``[`` never closed, a ``[`` after the first row or after the ``]``, and
  a row after the ``]`` are errors. Modules are numbered 1..n in reading
  order.
* **TOML**: ``cells = [[x, y], ...]`` (numbered in reading order), or
  ``[[module]]`` tables with ``id``, ``cell = [x, y]`` and optional
  ``orientation`` (0..5, the module's Yref). Any other key, at the top or
  in a ``[[module]]`` table, is an error naming it and its line (and the
  known key it is close to): a misspelt ``orientaton`` left orientation 0.

The format follows the suffix, never the content. Both formats keep their
cells within ``hexlattice.COORD_LIMIT`` (one check, :func:`_check_cell`).
Every error names the file, the line (of a ``[[module]]`` table: its
header) and the problem; a file with neither ``cells`` nor ``[[module]]``
has no line to name.
"""

from __future__ import annotations

import re
from collections import Counter
from pathlib import Path

from hexbot.errors import ScenarioError
from hexbot.files import load_toml, read_text
from hexbot.planning.configuration import Configuration, Module
from hexbot.planning.hexlattice import COORD_LIMIT, Cell
from hexbot.toml_lines import TomlLines, unknown_key

_ASSIGN = re.compile(r"^\s*[A-Za-z_]\w*\s*=(?=\s*\[)")
#: a grid line's tokens: brackets, separators, and anything else (a cell or an error)
_GRID_TOKEN = re.compile(r"[][;,]|[^\s\][;,]+")
#: the keys of a TOML configuration, at the top and in a [[module]] table
TOP_KEYS = ("cells", "module")
MODULE_KEYS = ("id", "cell", "orientation")


def parse_grid(text: str, source: str = "<grid>") -> Configuration:
    """Parse 0/1 grid rows (see the module docstring)."""
    rows: list[list[int]] = []
    lines: list[int] = []
    opened = 0  # the line of the '[' open, 0: none is
    closed = 0  # the line of the ']' that closed the grid, 0: none did

    def end_row(row: list[int], lineno: int) -> None:
        if not row:
            return
        if rows and len(row) != len(rows[0]):
            raise ScenarioError(
                f"{source}:{lineno}: row has {len(row)} columns, "
                f"row 1 (line {lines[0]}) has {len(rows[0])}"
            )
        rows.append(row)
        lines.append(lineno)

    lineno = 0
    for lineno, raw in enumerate(text.splitlines(), start=1):
        line = re.split(r"[#%]", raw, maxsplit=1)[0]
        if not rows and not opened and not closed:
            line = _ASSIGN.sub("", line, count=1)  # MATLAB's `I = [`, before the first row
        line = line.replace("...", " ")
        if not closed and "[" not in line and "]" not in line and ";" not in line:
            end_row(_cells(line.replace(",", " ").split(), source, lineno), lineno)
            continue  # a plain row (most lines of a big grid): no brackets to follow
        row: list[int] = []
        for token in _GRID_TOKEN.findall(line):
            if token == "[":
                if opened:
                    raise ScenarioError(f"{source}:{lineno}: a bracket inside a bracket: not a "
                                        "0/1 grid (a TOML configuration must be named .toml)")
                if closed:
                    raise ScenarioError(f"{source}:{lineno}: a second '[' after the grid's ']' "
                                        f"on line {closed}: a file holds one grid")
                if rows or row:
                    raise ScenarioError(f"{source}:{lineno}: '[' after the first row (line "
                                        f"{lines[0] if rows else lineno}): it opens the grid, "
                                        "before its rows")
                opened = lineno
            elif token == "]":
                if not opened:
                    raise ScenarioError(f"{source}:{lineno}: ']' closes no bracket")
                end_row(row, lineno)
                row, opened, closed = [], 0, lineno
            elif token == ";":
                end_row(row, lineno)
                row = []
            elif token != ",":
                _cells([token], source, lineno)
                if closed:
                    raise ScenarioError(f"{source}:{lineno}: a row after the grid's closing "
                                        f"']' on line {closed}")
                row.append(int(token))
        end_row(row, lineno)
    if opened:
        raise ScenarioError(f"{source}:{lineno}: ']' missing: the '[' on line {opened} is "
                            "never closed")
    if not rows:
        raise ScenarioError(f"{source}: no grid rows found")
    height = len(rows)
    filled = [r for r, row in enumerate(rows) if 1 in row]
    if not filled:
        raise ScenarioError(f"{source}: the grid holds no module (all zeros)")
    # the farthest cells: the top row's first module, the last column's
    top = filled[0]
    _check_cell((rows[top].index(1), height - 1 - top), f"{source}:{lines[top]}")
    right = max(filled, key=lambda r: len(rows[r]) - rows[r][::-1].index(1))
    _check_cell((len(rows[right]) - 1 - rows[right][::-1].index(1), height - 1 - right),
                f"{source}:{lines[right]}")
    cells = {(c, height - 1 - r) for r, row in enumerate(rows) for c, v in enumerate(row) if v}
    return Configuration.from_cells(cells)


def _cells(tokens: list[str], source: str, lineno: int) -> list[int]:
    """A grid row's tokens as 0/1 cells."""
    for token in tokens:
        if token not in ("0", "1"):
            raise ScenarioError(f"{source}:{lineno}: expected 0 or 1, found {token!r}")
    return [int(t) for t in tokens]


def _check_cell(cell: Cell, where: str) -> Cell:
    """``cell`` if it is within the planner's coordinate range (both formats)."""
    if max(abs(cell[0]), abs(cell[1])) > COORD_LIMIT:  # keeps the int32 arithmetic exact
        raise ScenarioError(f"{where}: cell {list(cell)} is outside the planner's coordinate "
                            f"range (-{COORD_LIMIT:,}..{COORD_LIMIT:,})")
    return cell


def _toml_line(text: str, needle: str) -> int:
    """The line that sets the key ``needle`` (else the first that names it, else 1):
    a comment naming the key before it is not the line."""
    lines = text.splitlines()
    sets = re.compile(rf"^\s*{re.escape(needle)}\s*=")
    for lineno, line in enumerate(lines, start=1):
        if sets.match(line):
            return lineno
    for lineno, line in enumerate(lines, start=1):
        if needle in line:
            return lineno
    return 1


def _module_lines(text: str) -> list[int]:
    """The line of each ``[[module]]`` header, in order (inline tables: none)."""
    header = re.compile(r"^\s*\[\[\s*module\s*\]\]")
    return [n for n, line in enumerate(text.splitlines(), start=1) if header.match(line)]


def _as_cell(value: object, where: str) -> Cell:
    if (
        not isinstance(value, list)
        or len(value) != 2
        or not all(_is_int(v) for v in value)
    ):
        raise ScenarioError(f"{where}: a cell must be [x, y] with two integers, got {value!r}")
    return _check_cell((value[0], value[1]), where)


def _is_int(value: object) -> bool:
    """A TOML integer (``true`` is an int to Python, not to a configuration)."""
    return isinstance(value, int) and not isinstance(value, bool)


def parse_toml(text: str, source: str = "<toml>") -> Configuration:
    """Parse a TOML cell list (see the module docstring)."""
    data = load_toml(text, source)
    lines = TomlLines(text)
    for key in sorted(set(data) - set(TOP_KEYS)):
        raise ScenarioError(f"{source}:{lines.find('', -1, key)}: {unknown_key(key, TOP_KEYS)}")
    if "cells" in data and "module" in data:
        raise ScenarioError(f"{source}:{_toml_line(text, 'cells')}: give either 'cells' or "
                            "[[module]] tables, not both")
    if "cells" in data:
        cells = data["cells"]
        where = f"{source}:{_toml_line(text, 'cells')}"
        if not isinstance(cells, list) or not cells:
            raise ScenarioError(f"{where}: 'cells' must be a non-empty list of [x, y]")
        parsed = [_as_cell(c, where) for c in cells]
        dup = [c for c, times in Counter(parsed).items() if times > 1]
        if dup:  # (one count: list.count per cell took 2.4 s for 10,000 cells)
            raise ScenarioError(f"{where}: cell {min(dup)} listed twice")
        return Configuration.from_cells(parsed)
    modules = data.get("module")
    if not isinstance(modules, list) or not modules:
        raise ScenarioError(f"{source}: expected 'cells = [...]' or [[module]] tables")
    out: dict[Cell, Module] = {}
    ids: set[int] = set()
    headers = _module_lines(text)
    for k, entry in enumerate(modules, start=1):
        line = headers[k - 1] if len(headers) == len(modules) else _toml_line(text, "module")
        where = f"{source}:{line}: [[module]] #{k}"
        for key in sorted(set(entry) - set(MODULE_KEYS) if isinstance(entry, dict) else ()):
            # the key's own line; an inline table has only the line that sets 'module'
            at = lines.find("module", k - 1, key) if len(headers) == len(modules) else line
            raise ScenarioError(f"{source}:{at}: [[module]] #{k}: "
                                f"{unknown_key(key, MODULE_KEYS)}")
        if not isinstance(entry, dict) or "id" not in entry or "cell" not in entry:
            raise ScenarioError(f"{where}: needs 'id' and 'cell'")
        mid, orientation = entry["id"], entry.get("orientation", 0)
        if not _is_int(mid) or not 1 <= mid <= 63:
            raise ScenarioError(f"{where}: id must be an integer 1..63 (DIP switches), got {mid!r}")
        if not _is_int(orientation) or not 0 <= orientation <= 5:
            raise ScenarioError(f"{where}: orientation must be 0..5, got {orientation!r}")
        cell = _as_cell(entry["cell"], where)
        if mid in ids:
            raise ScenarioError(f"{where}: module id {mid} used twice")
        if cell in out:
            raise ScenarioError(f"{where}: cell {cell} holds two modules")
        ids.add(mid)
        out[cell] = Module(mid, orientation)
    return Configuration(out)


def names_modules(path: str | Path) -> bool:
    """Does the file give each module's id ([[module]] tables), rather than
    cells numbered in reading order?"""
    path = Path(path)
    if path.suffix.lower() != ".toml":
        return False
    return "module" in load_toml(read_text(path), path)


def load_configuration(path: str | Path) -> Configuration:
    """Read a configuration file; the format follows the suffix (``.toml`` or grid text)."""
    path = Path(path)
    text = read_text(path)
    if path.suffix.lower() == ".toml":
        return parse_toml(text, str(path))
    return parse_grid(text, str(path))
