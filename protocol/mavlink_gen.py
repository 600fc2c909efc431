"""Run pymavlink's mavgen on the dialect: C headers for the firmware,
a Python module for the host. Both come from the XML that
``mavlink_xml.render()`` gives now, so a change of the function table
shows up in every generated file (and a stale checked-in copy fails the
test of ``generated.py``).

The outputs are checked in (the firmware builds without Python):
``firmware/include/mavlink/`` (mavgen's C, wire protocol 2.0) and
``protocol/hexbot_mavlink.py`` (mavgen's Python3 module). mavgen stamps
the C headers with the day of generation (``MAVLINK_BUILD_DATE``); that
line alone does not make a copy stale.
"""

from __future__ import annotations

import contextlib
import functools
import io
import tempfile
from pathlib import Path

from pymavlink.generator import mavgen, mavparse

from hexbot.protocol import mavlink_xml

ROOT = Path(__file__).resolve().parent.parent
C_DIR = ROOT / "firmware" / "include" / "mavlink"
PY_PATH = Path(__file__).resolve().parent / "hexbot_mavlink.py"
DATE_LINE = "#define MAVLINK_BUILD_DATE"


def _mavgen(language: str, output: Path, xml: Path) -> None:
    opts = mavgen.Opts(str(output), wire_protocol=mavparse.PROTOCOL_2_0, language=language,
                       validate=True)
    chatter = io.StringIO()  # mavgen prints progress; keep it for the error
    with contextlib.redirect_stdout(chatter):
        ok = mavgen.mavgen(opts, [str(xml)])
    if not ok:
        raise RuntimeError(f"mavgen --lang {language} failed on {xml}:\n{chatter.getvalue()}")


@functools.cache
def generate() -> dict[Path, str]:
    """Every generated file (absolute path in the repository) and its text."""
    out: dict[Path, str] = {}
    with tempfile.TemporaryDirectory(prefix="hexbot-mavgen-") as tmp:
        tmp_path = Path(tmp)
        xml = tmp_path / f"{mavlink_xml.DIALECT}.xml"
        xml.write_text(mavlink_xml.render())
        (tmp_path / mavlink_xml.MINIMAL).write_text(mavlink_xml.render_minimal())
        _mavgen("C", tmp_path / "c", xml)
        for path in sorted((tmp_path / "c").rglob("*.h")):
            out[C_DIR / path.relative_to(tmp_path / "c")] = path.read_text()
        _mavgen("Python3", tmp_path / "hexbot_mavlink.py", xml)
        out[PY_PATH] = (tmp_path / "hexbot_mavlink.py").read_text()
    return out


def same_but_date(current: str, fresh: str) -> bool:
    """Equal except for mavgen's build-date line."""
    def strip(text: str) -> list[str]:
        return [ln for ln in text.splitlines() if not ln.startswith(DATE_LINE)]
    return strip(current) == strip(fresh)
