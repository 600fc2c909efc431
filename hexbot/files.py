"""Reading the toolchain's input files: one place that turns "cannot read"
and "not text" into a one-line ``file: reason`` error instead of a traceback.

Every input format (configurations, scenarios, maps, rule files, scripts,
sweep files) is UTF-8 text; a binary file passed by mistake must fail like
a missing one.
"""

from __future__ import annotations

from pathlib import Path

from hexbot.errors import ScenarioError


def read_text(path: str | Path, what: str = "") -> str:
    """The file's text; ScenarioError ``PATH: cannot read[ WHAT]: reason`` or
    ``PATH: not a text file (UTF-8)``. ``what`` names the kind of file
    (``"rule file"``) where the path alone does not say it."""
    path = Path(path)
    try:
        return path.read_text(encoding="utf-8")
    except UnicodeDecodeError as exc:
        raise ScenarioError(
            f"{path}: not a text file (UTF-8): byte 0x{exc.object[exc.start]:02x} "
            f"at offset {exc.start}") from None
    except OSError as exc:
        kind = f" {what}" if what else ""
        raise ScenarioError(f"{path}: cannot read{kind}: {exc.strerror or exc}") from None
