"""Command palette (ctrl+p): every workflow, tab and function code."""

from __future__ import annotations

from collections.abc import Callable
from functools import partial
from typing import TYPE_CHECKING

from textual.command import DiscoveryHit, Hit, Hits, Provider

from hexbot.protocol.codes import executable_codes

if TYPE_CHECKING:
    from hexbot.host.console.app import HexBotConsole


class ConsoleCommands(Provider):
    def _commands(self) -> list[tuple[str, str, Callable[[], object]]]:
        app: HexBotConsole = self.app  # type: ignore[assignment]
        out: list[tuple[str, str, Callable[[], object]]] = []
        for action, title, help_text in app.WORKFLOWS:
            out.append((title, help_text, partial(app.do_workflow, action)))
        for tab, title in app.TABS:
            out.append((f"Show {title}", f"switch to the {title} tab",
                        partial(app.show_tab, tab)))
        for fn in executable_codes():
            out.append((f"Compose {fn.code} {fn.signature()}", fn.comment,
                        partial(app.compose_function, fn.code)))
        return out

    async def discover(self) -> Hits:
        for title, help_text, callback in self._commands():
            if not title.startswith("Compose"):
                yield DiscoveryHit(title, callback, help=help_text)

    async def search(self, query: str) -> Hits:
        matcher = self.matcher(query)
        for title, help_text, callback in self._commands():
            score = matcher.match(title)
            if score > 0:
                yield Hit(score, matcher.highlight(title), callback, help=help_text)
