"""Every file, or part of a file, that ``hexbot gen-header`` writes from the
protocol: the firmware headers and the tables in the docs.

They are checked in so that the firmware builds without Python; a test
fails when any of them differs from what the protocol would generate now.
A document keeps its prose by hand: only the part between its markers is
generated.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

from hexbot.protocol import docs_table, header, mavlink_gen, mavlink_xml, pins_header

DOCS = Path(__file__).resolve().parent.parent / "docs"


@dataclass(frozen=True)
class Generated:
    path: Path
    block: str | None  # marker name inside a document; None = the whole file
    render: Callable[[], str]

    def markers(self) -> tuple[str, str]:
        return (f"<!-- BEGIN GENERATED: {self.block} (hexbot gen-header) -->",
                f"<!-- END GENERATED: {self.block} -->")

    def expected(self, current: str) -> str:
        """What the file should hold, given what it holds now."""
        if self.block is None:
            return self.render()
        begin, end = self.markers()
        if begin not in current or end not in current:
            raise ValueError(f"{self.path} lacks the markers of the generated {self.block}")
        head, rest = current.split(begin, 1)
        _, tail = rest.split(end, 1)
        return f"{head}{begin}\n{self.render()}\n{end}{tail}"

    def is_stale(self, path: Path | None = None) -> bool:
        path = path or self.path
        if not path.exists():
            return True
        current = path.read_text()
        return self.expected(current) != current

    def write(self) -> Path:
        current = self.path.read_text() if self.block else ""
        self.path.parent.mkdir(parents=True, exist_ok=True)
        self.path.write_text(self.expected(current))
        return self.path


@dataclass(frozen=True)
class MavgenOutput(Generated):
    """A file pymavlink's mavgen writes from the dialect: its day stamp
    alone does not make a copy stale."""

    def expected(self, current: str) -> str:
        fresh = self.render()
        return current if mavlink_gen.same_but_date(current, fresh) else fresh

    def write(self) -> Path:
        current = self.path.read_text() if self.path.exists() else ""
        self.path.parent.mkdir(parents=True, exist_ok=True)
        self.path.write_text(self.expected(current))
        return self.path


def _mavgen_outputs() -> tuple[Generated, ...]:
    files = mavlink_gen.generate()
    return tuple(MavgenOutput(path, None, lambda p=path: mavlink_gen.generate()[p])
                 for path in files)


ARTIFACTS: tuple[Generated, ...] = (
    Generated(header.HEADER_PATH, None, header.render),
    Generated(header.MAKE_PATH, None, header.render_make),
    Generated(pins_header.PATH, None, pins_header.render),
    Generated(DOCS / "protocol.md", "function-table", docs_table.render_table),
    Generated(DOCS / "firmware.md", "pin-map", docs_table.render_pin_table),
    Generated(DOCS / "firmware.md", "timing", docs_table.render_timing_table),
    Generated(mavlink_xml.XML_PATH, None, mavlink_xml.render),
    Generated(mavlink_xml.MINIMAL_PATH, None, mavlink_xml.render_minimal),
    *_mavgen_outputs(),
)


def stale() -> list[Generated]:
    return [a for a in ARTIFACTS if a.is_stale()]


def leftovers(folder: Path | None = None) -> list[Path]:
    """Files in mavgen's C folder that mavgen no longer writes (a message
    removed from the dialect): the folder is all generated, so they are stale."""
    folder = folder or mavlink_gen.C_DIR
    known = {a.path for a in ARTIFACTS}
    return sorted(p for p in folder.rglob("*") if p.is_file() and p not in known)


def write_all() -> list[Path]:
    """Write every artifact and remove the leftovers; the paths written."""
    for path in leftovers():
        path.unlink()
    return [a.write() for a in ARTIFACTS]
