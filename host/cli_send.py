"""``hexbot send CODE [ARGS...]``: one message, its decoded replies, an exit code.

Exit 0 when the replies the addressing implies arrived and acknowledge the
command (from each ``--module``, which is selected first with code 69);
otherwise the reason on stderr and the exit status of its kind: 1 refused
(ERR, unused code, control board time-out) or garbled (bytes that decode
as no reply: replies collided), 3 no reply in time, 4 port lost. How long
to wait comes from the protocol (each function's own duration);
``--timeout`` overrides it. Everything the port heard after the first frame
is printed in the order it arrived; ``--linger`` keeps printing.

Each ``send`` opens its port anew; to build state across several sends
(Ref, then Localize) keep a simulator running (``hexbot sim SCENARIO
--pty``) and pass its pty as ``--port``, as with real modules.
"""

from __future__ import annotations

import argparse
import json
import sys

from hexbot.cli_args import whole_in
from hexbot.errors import FrameError, UsageError
from hexbot.host.cli_common import session
from hexbot.host.cli_progress import session_waits
from hexbot.host.commands import parse_command, parse_raw
from hexbot.host.describe import describe_event, describe_tx, event_json
from hexbot.host.endpoints import add_port_arguments
from hexbot.host.events import Observed
from hexbot.host.script import linger_seconds, timeout_seconds
from hexbot.host.session import Session, select
from hexbot.protocol import frames, wire
from hexbot.protocol.frames import Command
from hexbot.protocol.mavlink_codec import Framing


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("function", metavar="CODE", nargs="?",
                        help="function code or name (hexbot codes)")
    parser.add_argument("args", nargs="*", metavar="ARG", help="argument bytes")
    parser.add_argument("--raw", metavar="HEX",
                        help="send these bytes as they are instead of CODE: hex (e.g. "
                             "2A464E4E4E4E4E4E4E4E23) or quoted text ('\"*FNNNNNNNN#\"'); "
                             "any ACK/ERR/STA answers them")
    parser.add_argument("--dry-run", action="store_true",
                        help="print the frames' bytes and send nothing")
    parser.add_argument("--module", type=_module_id, action="append", metavar="ID",
                        help="select this module first (code 69) and expect its reply; "
                             "repeat for several; 0 = every module")
    parser.add_argument("--expect", type=reply_count, default=None, metavar="N",
                        help="replies to wait for without --module (default: what the "
                             "addressing implies; 1 before any Select)")
    parser.add_argument("--timeout", type=timeout_seconds, default=None, metavar="S",
                        help="seconds to wait for the replies (default: as long as the "
                             "protocol says the function takes)")
    parser.add_argument("--json", action="store_true", help="print replies as JSON lines")
    parser.add_argument("--linger", type=linger_seconds, default=0.0, metavar="S",
                        help="after the replies, keep printing events for S seconds "
                             "(e.g. localization reports)")
    parser.add_argument("--unchecked", action="store_true",
                        help="send codes/arguments outside the table's ranges (tests the "
                             "firmware's own checks)")
    add_port_arguments(parser, debug=False)


#: ``--expect N``: replies of N modules, one per module id (1..255, the DIP
#: switches): more never come, and the wait for them grew with N (99999 ran
#: for minutes).
reply_count = whole_in(1, wire.MAX_MODULE_ID)


def _module_id(text: str) -> int:
    """A module id for Select: the DIP switches' range, 0 for every module."""
    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"not a module id: {text!r}") from None
    if not 0 <= value <= wire.MAX_MODULE_ID:
        raise argparse.ArgumentTypeError(
            f"a module id is 1..{wire.MAX_MODULE_ID} (0 = every module), got {value}")
    return value


def run(args: argparse.Namespace) -> int:
    steps = _steps(args)  # every frame checked before a port opens
    if args.dry_run:
        for frame in steps:
            data = frame if isinstance(frame, bytes) else frames.encode_pc(
                frame, strict=not args.unchecked)
            print(f"{describe_tx(data)}: {data.hex(' ')}")
        return 0
    # --module 0 selects all: the session's addressing decides who answers
    modules = None if args.module in (None, [0]) else args.module
    with session(args) as sess:
        if sess.host.framing is Framing.AUTO:  # the probe's reply is not the command's
            print(f"framing: {sess.settle_framing().value}", file=sys.stderr)
        printer = _Printer(sess, sess.host.mark(), args.json)
        for frame in steps:
            with session_waits(sess):
                out = sess.exchange(frame, modules=modules,
                                    count=None if modules else args.expect,
                                    timeout=_timeout(sess, frame, args.timeout),
                                    strict=not args.unchecked)
            printer.catch_up()
            out.raise_for_status()
        printer.linger(args.linger)
    print(f"ok: {describe_tx(steps[-1]) if isinstance(steps[-1], bytes) else steps[-1]}",
          file=sys.stderr)
    return 0


def _steps(args: argparse.Namespace) -> list[Command | bytes]:
    """The frames to send: Select(--module...) first, then the command."""
    if args.raw is None and args.function is None:
        raise UsageError("give a function (CODE [ARG...]) or --raw HEX")
    if args.raw is not None and args.function is not None:
        raise UsageError("give a function (CODE [ARG...]) or --raw HEX, not both")
    if args.raw is not None:
        if args.args:
            raise FrameError("--raw takes no ARG words")
        last: Command | bytes = parse_raw(args.raw, "--raw")
    else:
        last = parse_command([args.function, *args.args], strict=not args.unchecked)
    return ([select(*args.module)] if args.module else []) + [last]


def _timeout(sess: Session, frame: Command | bytes, given: float | None) -> float | None:
    """A raw frame has no protocol time-out of its own: the decoded frame's,
    or the Status bound when the bytes are no frame."""
    if given is not None or not isinstance(frame, bytes):
        return given
    try:
        command = frames.decode_pc(frame)
    except FrameError:
        command = frames.make("Status")
    return sess.reply_timeout(command, sess.selection, 1)


class _Printer:
    """Prints the journal from a mark on, in the order it arrived."""

    def __init__(self, sess: Session, mark: int, as_json: bool) -> None:
        self.sess, self.next, self.as_json = sess, mark, as_json

    def catch_up(self) -> None:
        for obs in self.sess.host.since(self.next):
            _print(obs, self.as_json)
            self.next = obs.seq + 1

    def linger(self, seconds: float) -> None:
        """Print events as they come for ``seconds`` of session time."""
        clock = self.sess.clock
        end = clock.now() + seconds
        while (left := end - clock.now()) > 0:
            clock.wait(lambda: self.sess.host.mark() > self.next, left)
            self.catch_up()


def _print(obs: Observed, as_json: bool) -> None:
    if as_json:
        print(json.dumps({"t": round(obs.t, 3), "port": obs.port, **event_json(obs.event)}),
              flush=True)
    else:
        print(f"{obs.t:8.3f} {obs.port:<5} {describe_event(obs.event)}", flush=True)
