"""Helpers shared by the host's CLI commands: open the session, print."""

from __future__ import annotations

import argparse
import sys
import threading
from collections.abc import Iterator
from contextlib import contextmanager
from urllib.parse import parse_qs, urlsplit

from hexbot.host import endpoints
from hexbot.host.cli_progress import meter
from hexbot.host.events import HostEvent, HostWarning, Listener, PortChanged
from hexbot.host.link import LinkState
from hexbot.host.session import Session
from hexbot.protocol import wire
from hexbot.protocol.parser import Garbage


@contextmanager
def session(args: argparse.Namespace, *, wait_s: float = 5.0, verbose_states: bool = True,
            listener: Listener | None = None, wait_boot: bool = True,
            default_speed: float = 0.0) -> Iterator[Session]:
    """Open the ports (or the embedded simulator, by default in virtual
    time), yield the session, close everything. ``listener`` sees
    everything from the first byte (boot texts included); with
    ``wait_boot`` a simulated cluster is given time to finish booting."""
    ends = endpoints.resolve(args, default_speed)
    listeners = ([_state_printer()] if verbose_states else []) + ([listener] if listener else [])
    host = endpoints.open_host(args, ends, listeners)
    try:
        for ch in host.channels.values():
            ch.link.start(wait_s)
        if host.log is not None:
            err_line(f"session log: {host.log.folder}")
        sim = host.simulator
        sess = Session(host, sim.module_ids() if sim is not None else ())
        if sim is not None and wait_boot:
            _wait_booted(sess, ends.scenario or ends.ir.url, sim.module_ids())
        yield sess
    finally:
        host.close()


_stderr_lock = threading.Lock()


def err_line(text: str) -> None:
    """One whole line on stderr. Port states come from the link's reader
    thread while the main thread prints too: print() writes the text and
    its newline separately, so two threads' lines ran into one."""
    with _stderr_lock:
        sys.stderr.write(text + "\n")
        sys.stderr.flush()


def _state_printer() -> Listener:
    """Warnings, and the ports' states once they have been up: a port that
    never opened is the command's own error line (exit 4), said once."""
    been_up: set[str] = set()

    def print_state(event: HostEvent) -> None:
        if isinstance(event, HostWarning):
            err_line(f"warning: {event.text}")
        elif isinstance(event, PortChanged):
            if event.state is LinkState.CONNECTED:
                been_up.add(event.port)
            elif event.state is not LinkState.LOST or event.port not in been_up:
                return
            err_line(f"{event.port}: {event.state.value} {event.detail}".rstrip())
    return print_state


def _wait_booted(sess: Session, scenario: str, ids: list[int]) -> None:
    """Wait for a simulated cluster's boot texts with "n of N booted" on a
    terminal, ask the modules whose texts were not heard whole for their
    Status, then one line saying how it went."""
    started = sess.now()
    with meter(f"simulator {scenario}: modules booted", len(ids)) as bar:
        def booted(_ident: int) -> None:
            bar.advance()
        # by the radio the PC hears only the modules in its range: it cannot
        # ask the others either
        by_radio = parse_qs(urlsplit(scenario).query).get("radio") == ["1"]
        heard, answered = sess.boot(ids, on_boot=booted, ask=not by_radio)
    up = heard | answered
    how = f" ({len(heard)} by boot text, {len(answered)} by Status)" if answered else ""
    print(f"simulator: {scenario}, {len(up)} of {len(ids)} modules booted in "
          f"{sess.now() - started:.1f} s{how}", file=sys.stderr)
    if not up and any(isinstance(o.event, Garbage) for o in sess.host.since(0)):
        print(f"warning: only garbled bytes heard: the modules speak {wire.BAUD_IR} 8N1 "
              "(check --baud, --parity, --data-bits, --stop-bits, or the scenario's "
              "faults)", file=sys.stderr)
    missing = sorted(set(ids) - up)
    if missing and up and not by_radio and not sess.cancel.is_set():
        # not a failure: a run that passes on part of the cluster is fine, but
        # say it, so that it does not read as the whole
        print(f"warning: module(s) {', '.join(map(str, missing))}: no "
              f"{wire.TEXT_COMM_LISTENING} text of theirs heard whole and no answer to a "
              "Status: not booted, or out of reach; steps addressed to them will fail",
              file=sys.stderr)
