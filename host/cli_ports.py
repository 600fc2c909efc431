"""``hexbot ports``: the serial ports this machine has (pyserial's
``list_ports``), the simulator's URLs, and the ptys of ``hexbot sim --pty``
processes that are running."""

from __future__ import annotations

import argparse
import json
import os
from pathlib import Path

from serial.tools import list_ports

from hexbot.hil_sim.scenario import builtin_names
from hexbot.host.endpoints import sim_url


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--json", action="store_true", help="one JSON object")


def running_simulators() -> list[dict]:
    """``hexbot sim --pty`` processes and the ptys they hold, in the order
    they opened them (the IR port first, then each module's UART1)."""
    found = []
    for proc in Path("/proc").iterdir():
        if not proc.name.isdigit() or int(proc.name) == os.getpid():
            continue
        try:
            words = [w.decode(errors="replace")
                     for w in (proc / "cmdline").read_bytes().split(b"\0") if w]
            fds = sorted((int(fd.name), os.readlink(fd)) for fd in (proc / "fd").iterdir())
            program = Path(os.readlink(proc / "exe")).name
        except (OSError, ValueError):
            continue  # gone, or not ours to look at
        if "sim" not in words or "--pty" not in words or not any("hexbot" in w for w in words):
            continue
        if "python" not in program:  # a wrapper (`timeout 600 hexbot sim pair --pty`)
            continue
        # fds 0-2 are the terminal it runs in (`hexbot sim pair --pty &`), not its ports
        ptys = [target for fd, target in fds if fd > 2 and target.startswith("/dev/pts/")]
        found.append({"pid": int(proc.name), "command": " ".join(words), "ptys": ptys})
    return sorted(found, key=lambda s: s["pid"])


def run(args: argparse.Namespace) -> int:
    hardware = [{"device": p.device, "description": p.description, "hwid": p.hwid}
                for p in sorted(list_ports.comports(), key=lambda p: p.device)]
    urls = [sim_url(name) for name in builtin_names()]
    sims = running_simulators()
    if args.json:
        print(json.dumps({"serial": hardware, "simulator_urls": urls, "running": sims}))
        return 0
    print("serial ports:" if hardware else "serial ports: none found")
    for p in hardware:
        print(f"  {p['device']:<16} {p['description']} [{p['hwid']}]")
    print("embedded simulator (this process; --scenario NAME or --port URL):")
    for url in urls:
        print(f"  {url}")
    print("running `hexbot sim --pty` (IR port first):" if sims
          else "running `hexbot sim --pty`: none")
    for s in sims:
        print(f"  PID {s['pid']}: {' '.join(s['ptys'])}  ({s['command']})")
    return 0
