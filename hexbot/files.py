"""Reading the toolchain's input files: one place that turns "cannot read"
and "not text" into a one-line ``file: reason`` error instead of a traceback.

Every input format (configurations, scenarios, maps, rule files, scripts,
sweep files) is UTF-8 text; a binary file passed by mistake must fail like
a missing one. A leading byte-order mark (Windows editors write one) is
dropped here, so no reader sees it.
"""

from __future__ import annotations

import re
import tomllib
from pathlib import Path
from typing import Any

from hexbot.errors import ScenarioError


def read_text(path: str | Path, what: str = "") -> str:
    """The file's text; ScenarioError ``PATH: cannot read[ WHAT]: reason`` or
    ``PATH: not a text file (UTF-8)``. ``what`` names the kind of file
    (``"rule file"``) where the path alone does not say it. A UTF-8
    byte-order mark at the start is not part of the text."""
    path = Path(path)
    try:
        return path.read_text(encoding="utf-8").removeprefix("\ufeff")
    except UnicodeDecodeError as exc:
        raise ScenarioError(
            f"{path}: not a text file (UTF-8): byte 0x{exc.object[exc.start]:02x} "
            f"at offset {exc.start}") from None
    except OSError as exc:
        kind = f" {what}" if what else ""
        raise ScenarioError(f"{path}: cannot read{kind}: {exc.strerror or exc}") from None


def read_bytes(path: str | Path, what: str = "") -> bytes:
    """The file's bytes (captures, which may end in half a character);
    ScenarioError ``PATH: cannot read[ WHAT]: reason`` as :func:`read_text`."""
    path = Path(path)
    try:
        return path.read_bytes()
    except OSError as exc:
        kind = f" {what}" if what else ""
        raise ScenarioError(f"{path}: cannot read{kind}: {exc.strerror or exc}") from None


#: where tomllib says the error is: a line and column, or the end
_TOML_WHERE = re.compile(r"\((?:at line (\d+), column \d+|at end of document)\)")


def load_toml(text: str, source: str | Path) -> dict[str, Any]:
    """``text`` parsed as TOML; a syntax error is ScenarioError
    ``SOURCE:LINE: problem``, the last line for one at the end of the text."""
    try:
        return tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        m = _TOML_WHERE.search(str(exc))
        line = (m.group(1) or max(1, len(text.splitlines()))) if m else None
        where = f"{source}:{line}" if line else str(source)
        raise ScenarioError(f"{where}: {_TOML_WHERE.sub('', str(exc)).strip()}") from None
