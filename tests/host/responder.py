"""A unit-test double for a small cluster behind a pty (never a product path).

It answers PC frames the way docs/protocol.md says modules do: Select switches
to addressed mode and picks the listed modules, each selected module ACKs
with its prefix (``M03: ``), Status answers STA, Localize makes every
module print a localization report, an out-of-range argument gets
ERR ARG_RANGE, an unused code ACK 'N'. No timing model: replies are
written at once, in rank order. The real behaviour is tested against the
simulator in test_sim_*.py.
"""

from __future__ import annotations

import os
import threading
import tty
from dataclasses import dataclass, field

from hexbot.errors import FrameError
from hexbot.protocol import frames, parser, wire
from hexbot.protocol.codes import CODES, ErrorCode


@dataclass
class FakeModule:
    ident: int
    position: tuple[int, int]
    yref: int = 0
    role: str = "M"
    localized: bool = False


FLOWER = [(0, 0), (-1, 1), (0, 1), (1, 0), (1, -1), (0, -1), (-1, 0)]


@dataclass
class PtyResponder:
    modules: list[FakeModule] = field(default_factory=lambda: [
        FakeModule(i + 1, pos, yref=i % 6) for i, pos in enumerate(FLOWER)])
    silent: bool = False  # swallow everything (time-out tests)

    def __post_init__(self) -> None:
        self.master, self.slave = os.openpty()
        tty.setraw(self.slave)
        self.path = os.ttyname(self.slave)
        self.received: list[bytes] = []
        self.selected: list[int] | None = None  # None = legacy mode, all execute
        self._stop = threading.Event()
        self._thread = threading.Thread(target=self._run, daemon=True)
        self._thread.start()

    def close(self) -> None:
        # Idempotent: a second close must not close a recycled fd number
        # that now belongs to someone else. Join before closing: a recycled
        # fd must not be read by this thread on behalf of the next test's pty.
        if self._stop.is_set():
            return
        self._stop.set()
        self._thread.join(timeout=2)
        for fd in (self.master, self.slave):
            try:
                os.close(fd)
            except OSError:
                pass

    def write(self, data: bytes) -> None:
        os.write(self.master, data)

    def _run(self) -> None:
        import select

        buf = b""
        while not self._stop.is_set():
            try:
                ready, _, _ = select.select([self.master], [], [], 0.05)
                if not ready:
                    continue
                buf += os.read(self.master, 256)
            except OSError:
                return
            while b"*" in buf:
                buf = buf[buf.index(b"*"):]
                if len(buf) < wire.PC_FRAME_LEN:
                    break
                frame, buf = buf[: wire.PC_FRAME_LEN], buf[wire.PC_FRAME_LEN:]
                self.received.append(frame)
                if not self.silent:
                    self._answer(frame)

    def _targets(self) -> list[FakeModule]:
        if self.selected is None:
            return list(self.modules)
        by_id = {m.ident: m for m in self.modules}
        return [by_id[i] for i in self.selected if i in by_id]

    def _reply(self, m: FakeModule, body: bytes) -> None:
        prefix = (f"{m.role}{m.ident:02d}: " if self.selected is not None else f"{m.role}: ")
        self.write(wire.PREAMBLE + prefix.encode() + body + wire.EOL)

    def _answer(self, frame: bytes) -> None:  # noqa: C901 - one branch per code
        code = frame[1]
        try:
            cmd = frames.decode_pc(frame)
        except FrameError:
            fn = CODES.get(code)
            targets = self._targets()
            for m in targets:
                if fn is not None and fn.executable:
                    self._reply(m, b"ERR" + bytes([code, ErrorCode.ARG_RANGE]))
                else:
                    self._reply(m, b"ACKN")
            return
        if code == 69:
            self.selected = sorted(m.ident for m in self.modules) if cmd.args == (0,) \
                else list(cmd.args)
        for m in self._targets():
            if code == 65:
                m.role, m.localized, m.position, m.yref = "S", True, (0, 0), 0
            if code == 66:
                m.localized = True
                x, y = m.position
                # as the firmware does: the report, then the ACK
                self.write(wire.PREAMBLE + b"LOCALIZED" + wire.EOL
                           + f"Side: {(m.yref % 6) + 1}".encode() + wire.EOL
                           + f"Yref: {m.yref}".encode() + wire.EOL
                           + f"Pos: {x:+03d}{y:+03d}".encode() + wire.EOL)
            if code == 70:
                self.write(parser.reply_status(m.ident, m.role, m.localized, *m.position,
                                               m.yref, 0, prefix_role=m.role))
                continue
            if code == 71:
                m.role = "M" if cmd.args[0] == 1 else "S"
            self._reply(m, b"ACK" + bytes([code]))
