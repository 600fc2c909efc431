"""Helpers shared by the host's CLI commands: open the session, print."""

from __future__ import annotations

import argparse
import sys
from collections.abc import Iterator
from contextlib import contextmanager

from hexbot.host import commands, endpoints
from hexbot.host.host import Host, Listener
from hexbot.host.link import LinkState


@contextmanager
def session(args: argparse.Namespace, *, wait_s: float = 5.0, verbose_states: bool = True,
            listener: Listener | None = None, wait_boot: bool = True) -> Iterator[Host]:
    """Open the ports (or the simulator), yield the host, close everything.
    ``listener`` sees everything from the first byte (boot texts included);
    with ``wait_boot`` a simulated cluster is given time to finish booting."""
    ends = endpoints.resolve(args)
    host = None
    try:
        host = endpoints.open_host(args, ends)
        if verbose_states:
            host.add_listener(_print_state)
        if listener is not None:
            host.add_listener(listener)
        host.start(wait_s)
        if host.log is not None:
            print(f"session log: {host.log.folder}", file=sys.stderr)
        if ends.sim is not None and wait_boot:
            print(f"simulator: {ends.sim.scenario}, waiting for the modules to boot",
                  file=sys.stderr)
            ids = endpoints.scenario_module_ids(ends.sim.scenario)
            commands.wait_until_booted(host, expected=ids)
        yield host
    finally:
        if host is not None:
            host.close()
        ends.close()


def _print_state(kind: str, port: str, payload: object) -> None:
    if kind != "state":
        return
    state, detail, _t = payload  # type: ignore[misc]
    if state in (LinkState.LOST, LinkState.CONNECTED):
        print(f"{port}: {state.value} {detail}".rstrip(), file=sys.stderr, flush=True)
