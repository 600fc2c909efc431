"""User words to commands: ``["JxOpen", "3"]`` -> a validated frame.

The CLI, scripts and the console's composer accept a function by name or
code and its argument bytes; this is where those words become a
:class:`~hexbot.protocol.frames.Command`. Sending and waiting is the
session's job (:mod:`hexbot.host.session`), rotations are a workflow
(:mod:`hexbot.host.workflows`).
"""

from __future__ import annotations

import ast

from hexbot.errors import FrameError
from hexbot.protocol import frames
from hexbot.protocol.codes import lookup
from hexbot.protocol.frames import Command


def parse_command(words: list[str], *, strict: bool = True) -> Command:
    """``["JxOpen", "3"]`` or ``["1", "3"]`` -> a validated command. With
    ``strict=False`` any code and byte values pass (to test the firmware's
    own checks); they still must be bytes."""
    if not words:
        raise FrameError("no function given")
    try:
        fn = lookup(words[0])
    except KeyError:
        if strict or not words[0].isdigit():
            raise FrameError(f"unknown function {words[0]!r} (see `hexbot codes`)") from None
        fn = None
    args = []
    for w in words[1:]:
        try:
            args.append(int(w, 0))
        except ValueError:
            raise FrameError(f"{words[0]}: argument {w!r} is not a number") from None
    code = fn.code if fn is not None else int(words[0])
    return frames.make(code, *args, strict=strict)


def parse_raw(text: str, what: str = "raw") -> bytes:
    """Bytes to send as they are: hex (``2A 46 4E...``, ``2a:46``, ``2A46``)
    or, in quotes, text with escapes (``"*FNNNNNNNN#"``, ``'\\x2a...'``).
    Shared by ``hexbot send --raw`` and the console's composer."""
    text = text.strip()
    if len(text) >= 2 and text[0] == text[-1] and text[0] in "'\"":
        try:
            data = ast.literal_eval("b" + text)
        except (SyntaxError, ValueError):
            raise FrameError(f"{what}: not a text of bytes: {text}") from None
    else:
        try:
            data = bytes.fromhex(text.replace(":", " "))
        except ValueError:
            raise FrameError(f"{what}: not hex bytes (or \"text\" in quotes): {text!r}") from None
    if not data:
        raise FrameError(f"{what}: no bytes")
    return data
