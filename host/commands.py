"""The thesis' workflows as commands, and waiting for their replies.

The user thinks in lattice (global) directions; the firmware wants joint
indices in each module's body frame. A module with orientation Yref (the
global side of its body side 1, minus one) has its body joint
``((global - 1 - Yref) mod 6) + 1`` at global joint ``global``. The combined
rotations 67/68 carry one index for the substrate and one for the mobile
module (thesis listing: ``SCW(i)``/``MCW(i)`` take the *mobile's* rotation
joint, each in its own frame), so both are the same global joint converted
with each module's own orientation.
"""

from __future__ import annotations

import re
import threading
import time
from collections.abc import Collection
from dataclasses import dataclass, field

from hexbot.errors import FrameError
from hexbot.host.describe import describe_event
from hexbot.host.host import IR, Host, Observed
from hexbot.protocol import frames, rotation
from hexbot.protocol.codes import lookup
from hexbot.protocol.frames import Command
from hexbot.protocol.parser import Ack, ErrorReply, StatusReport, Text


@dataclass(frozen=True)
class Timing:
    """Delays of one rotation half, in 10 ms ticks."""

    t1: int
    t2: int
    t3: int


# Table 3-1 in ticks, from the protocol: direction -> (substrate, mobile).
THESIS_TIMINGS: dict[str, tuple[Timing, Timing]] = {
    d.lower(): (Timing(*rotation.THESIS_TIMINGS[(d, "substrate")]),
                Timing(*rotation.THESIS_TIMINGS[(d, "mobile")]))
    for d in ("CW", "CCW")
}


def body_joint(global_joint: int, orientation: int) -> int:
    """Body-frame index of a global joint for a module with this Yref."""
    return rotation.body_index(global_joint, orientation)


def rotate(direction: str, global_joint: int, mobile_orientation: int,
           substrate_orientation: int, timings: tuple[Timing, Timing] | None = None) -> Command:
    """Code 67 (cw) or 68 (ccw) for a rotation of the mobile module about
    ``global_joint`` (lattice frame)."""
    sub, mob = timings or (None, None)
    return rotation.combined_rotation(
        direction, global_joint, mobile_orientation, substrate_orientation,
        substrate=(sub.t1, sub.t2, sub.t3) if sub else None,
        mobile=(mob.t1, mob.t2, mob.t3) if mob else None)


def select(*ids: int) -> Command:
    return frames.select(list(ids))


def ref() -> Command:
    return frames.make("Ref")


def localize() -> Command:
    return frames.make("Localize")


def status() -> Command:
    return frames.make("Status")


def all_off() -> Command:
    return frames.make("TurnOffAll")


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


# --- waiting for replies --------------------------------------------------


@dataclass
class Outcome:
    command: Command
    replies: list[Observed] = field(default_factory=list)
    ok: bool = False
    message: str = ""

    def lines(self) -> list[str]:
        return [describe_event(r.event) for r in self.replies]


def _reply_to(obs: Observed, code: int, modules: set[int] | None, port: str = IR) -> bool:
    if obs.port != port:  # a control board's debug port echoes ACKs too
        return False
    ev = obs.event
    if not isinstance(ev, (Ack, ErrorReply, StatusReport)):
        return False
    if isinstance(ev, ErrorReply) and ev.code != code:
        return False
    if modules is not None:
        ident = ev.module_id if isinstance(ev, StatusReport) else ev.module
        return ident in modules
    return True


def exchange(host: Host, command: Command, *, modules: list[int] | None = None,
             count: int = 1, timeout: float = 5.0, port: str = IR,
             cancel: threading.Event | None = None, strict: bool = True) -> Outcome:
    """Send ``command`` and wait for ``count`` replies (ACK, ERR, or STA for
    Status), from ``modules`` if given (one reply each). ``ok`` when every
    reply is the expected ACK/status and enough arrived."""
    wanted = set(modules) if modules else None
    need = len(wanted) if wanted else count
    out = Outcome(command)
    mark = host.send(command, port, strict=strict)
    deadline = time.monotonic() + timeout
    seen = mark
    while len(out.replies) < need:
        if cancel is not None and cancel.is_set():
            out.message = "cancelled"
            return out
        left = deadline - time.monotonic()
        if left <= 0:
            break
        obs = host.wait_for(lambda o: _reply_to(o, command.code, wanted, port), seen,
                             min(left, 0.1))
        if obs is None:
            seen = max(seen, host.mark())
            continue
        seen = obs.seq + 1
        if wanted is not None:
            wanted.discard(obs.event.module_id if isinstance(obs.event, StatusReport)
                           else obs.event.module)
        out.replies.append(obs)
    bad = [r for r in out.replies if not _is_success(r, command.code)]
    if bad:
        out.message = "; ".join(describe_event(r.event) for r in bad)
    elif len(out.replies) < need:
        missing = f" (no reply from {', '.join(str(m) for m in sorted(wanted))})" if wanted else ""
        out.message = (f"{command}: {len(out.replies)} of {need} replies "
                       f"within {timeout:g} s{missing}")
    else:
        out.ok = True
        out.message = f"{command}: {len(out.replies)} reply(ies) OK"
    return out


def _is_success(obs: Observed, code: int) -> bool:
    ev = obs.event
    if isinstance(ev, StatusReport):
        return code == lookup("Status").code
    return isinstance(ev, Ack) and ev.code == code


def collect_until_quiet(host: Host, since: int, quiet: float, timeout: float,
                        cancel: threading.Event | None = None) -> list[Observed]:
    """Events from ``since`` until none arrived for ``quiet`` seconds (or
    ``timeout`` passed): for broadcasts whose number of answers is unknown."""
    deadline = time.monotonic() + timeout
    last_count, last_change = -1, time.monotonic()
    while time.monotonic() < deadline:
        if cancel is not None and cancel.is_set():
            break
        n = host.mark()
        now = time.monotonic()
        if n != last_count:
            last_count, last_change = n, now
        elif now - last_change >= quiet:
            break
        time.sleep(0.05)
    return host.since(since)


def wait_until_booted(host: Host, quiet: float = 2.0, timeout: float = 60.0,
                      cancel: threading.Event | None = None,
                      expected: Collection[int] | None = None) -> int:
    """Wait for the boot texts of a freshly started cluster to end. With
    ``expected`` module ids (an embedded simulator knows them), until each
    has said ``COMM. LISTENING ID=nn`` — the firmware staggers those texts in
    per-id slots, so silence alone can end too early when ids leave gaps.
    Otherwise until no event arrived for ``quiet`` seconds (a fast simulator
    may have booted before the port opened: then this is just ``quiet``).
    Commands sent while modules boot are lost (their UARTs are not
    listening yet). Returns the number of events seen."""
    if not expected:
        return len(collect_until_quiet(host, 0, quiet, timeout, cancel))
    missing = set(expected)
    deadline = time.monotonic() + timeout
    seen = 0
    while missing and time.monotonic() < deadline:
        if cancel is not None and cancel.is_set():
            break
        events = host.since(0)
        seen = len(events)
        missing -= {ident for obs in events if (ident := _listening_id(obs.event)) is not None}
        time.sleep(0.05)
    return seen


def _listening_id(event: object) -> int | None:
    """The module id of a ``COMM. LISTENING ID=nn ...`` boot text."""
    if isinstance(event, Text) and event.phrase == "COMM. LISTENING":
        m = re.search(r"\bID=(\d+)", event.tail)
        if m:
            return int(m.group(1))
    return None
