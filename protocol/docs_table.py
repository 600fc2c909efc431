"""The function-code table of docs/protocol.md, generated from ``CODES``.

The document keeps its prose by hand; only the part between the markers is
rewritten by ``hexbot gen-header`` (and a test fails when it is stale).
"""

from __future__ import annotations

from pathlib import Path

from hexbot.protocol.codes import CODES, Status

DOC_PATH = Path(__file__).resolve().parent.parent / "docs" / "protocol.md"
BEGIN = "<!-- BEGIN GENERATED: function-table (hexbot gen-header) -->"
END = "<!-- END GENERATED: function-table -->"


def _args(fn) -> str:
    if not fn.args:
        return "-"
    parts = []
    for a in fn.args:
        unit = " ×10 ms" if a.unit == "tick" else ""
        parts.append(f"`{a.name}` {a.lo}..{a.hi}{unit}: {a.meaning}")
    return "<br>".join(parts)


def render_table() -> str:
    rows = ["| code | function | board | arguments | what it does |",
            "|---:|---|---|---|---|"]
    for fn in CODES.values():
        if fn.status is Status.UNUSED:
            continue
        name = f"`{fn.signature()}`" if fn.executable else f"*{fn.status.value}*"
        tag = " (extension)" if fn.status is Status.EXTENSION else ""
        rows.append(f"| {fn.code} | {name} | {fn.board.value} | {_args(fn)} | "
                    f"{fn.comment}{tag} |")
    unused = [str(fn.code) for fn in CODES.values() if fn.status is Status.UNUSED]
    rows.append("")
    rows.append(f"Not used (the module answers `ACK N`): {', '.join(unused)}.")
    return "\n".join(rows)


def splice(text: str) -> str:
    if BEGIN not in text or END not in text:
        raise ValueError(f"{DOC_PATH} lacks the generated-table markers")
    head, rest = text.split(BEGIN, 1)
    _, tail = rest.split(END, 1)
    return f"{head}{BEGIN}\n{render_table()}\n{END}{tail}"


def is_stale(path: Path = DOC_PATH) -> bool:
    text = path.read_text()
    return splice(text) != text


def write(path: Path = DOC_PATH) -> Path:
    path.write_text(splice(path.read_text()))
    return path
