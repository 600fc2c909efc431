"""Line numbers of TOML keys, for error messages that point into the file.

tomllib reports the line of a syntax error but gives parsed values no
positions; a file that parses yet says something wrong (an unknown key, a
value of the wrong type) still deserves ``file:line``. :class:`TomlLines`
scans the text once for table headers and keys and answers "where is key K
of table T". Scenario files, configuration files and sweep specs use it;
:func:`unknown_key` words the refusal of a key a table does not know, for
all of them that refuse one the same way.
"""

from __future__ import annotations

import difflib
import re
from collections.abc import Iterable


class TomlLines:
    """Finds the line of a key inside a table of the TOML text (tomllib has no positions)."""

    _header = re.compile(r"^\s*(\[\[?)\s*([A-Za-z0-9_.\"-]+)\s*\]\]?")
    _key = re.compile(r"^\s*([A-Za-z0-9_-]+)\s*[=.]")  # `a.b = 1`: the key a

    def __init__(self, text: str) -> None:
        # (table name, array index or -1) -> {key: line}, plus the header line under key ""
        self.tables: dict[tuple[str, int], dict[str, int]] = {("", -1): {"": 1}}
        counts: dict[str, int] = {}
        current = ("", -1)
        for number, raw in enumerate(text.splitlines(), start=1):
            line = raw.split("#", 1)[0] if '"' not in raw else raw
            header = self._header.match(line)
            if header:
                name = header.group(2)
                if header.group(1) == "[[":
                    counts[name] = counts.get(name, -1) + 1
                    current = (name, counts[name])
                else:
                    current = (name, -1)
                self.tables.setdefault(current, {})[""] = number
                # `[bogus]` sets the top-level key bogus: that is its line
                self.tables[("", -1)].setdefault(name.split(".", 1)[0].strip('"'), number)
                continue
            key = self._key.match(line)
            if key:
                self.tables.setdefault(current, {}).setdefault(key.group(1), number)

    def find(self, table: str = "", index: int = -1, key: str = "") -> int:
        entries = self.tables.get((table, index)) or self.tables[("", -1)]
        return entries.get(key, entries.get("", 1))


def unknown_key(key: str, known: Iterable[str], table: str = "") -> str:
    """The problem with a key its table does not know: ``unknown key
    'orientaton' in [[module]] (did you mean 'orientation'?)``, with the
    close known key where difflib finds one (``table``, when given, is how
    the message names the table). A typo must not be ignored: the default it
    leaves in force looks like the value the file asked for."""
    close = difflib.get_close_matches(key, sorted(known), n=1)
    where = f" in {table}" if table else ""
    hint = f" (did you mean {close[0]!r}?)" if close else ""
    return f"unknown key {key!r}{where}{hint}"
