"""``hexbot run SCRIPT``: run a HexBot script (grammar in hexbot.host.script)."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from hexbot.host.cli_common import session
from hexbot.host.endpoints import add_port_arguments
from hexbot.host.script import ScriptFailed, ScriptRunner, load_script


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("script", type=Path, help="a .hbs script (see docs/console.md)")
    parser.add_argument("--check", action="store_true",
                        help="only check the script's syntax; send nothing")
    parser.add_argument("--quiet", type=float, default=1.5, metavar="S",
                        help="after a broadcast, answers are over when the link was quiet "
                             "this long (default 1.5; less with a fast simulator)")
    add_port_arguments(parser)


def run(args: argparse.Namespace) -> int:
    steps = load_script(args.script)  # every line checked before anything is sent
    if args.check:
        print(f"{args.script}: {len(steps)} steps, syntax OK")
        return 0
    with session(args) as host:
        runner = ScriptRunner(host, str(args.script), quiet=args.quiet)
        try:
            runner.run(steps)
        except ScriptFailed as exc:
            print(f"FAILED {exc}", file=sys.stderr)
            print(f"{runner.steps_done} of {len(steps)} steps passed", file=sys.stderr)
            return 1
    print(f"{args.script}: all {len(steps)} steps passed", file=sys.stderr)
    return 0
