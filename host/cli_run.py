"""``hexbot run SCRIPT``: run a HexBot script (grammar in hexbot.host.script)."""

from __future__ import annotations

import argparse
import re
import sys
from pathlib import Path

from hexbot.cli_args import output_file
from hexbot.errors import HexBotError, ScenarioError
from hexbot.files import read_text
from hexbot.host.cli_common import session
from hexbot.host.endpoints import add_port_arguments
from hexbot.host.junit import write_junit
from hexbot.host.script import (
    INTERRUPTED,
    ScriptFailed,
    ScriptRunner,
    StepResult,
    load_script,
    not_started,
)


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("script", type=Path, help="a .hbs script (see docs/console.md)")
    parser.add_argument("--check", action="store_true",
                        help="only check the script's syntax; send nothing")
    parser.add_argument("--junit", type=output_file, metavar="XML",
                        help="write JUnit XML for CI: one testcase per step with its time "
                             "(simulated seconds on the simulator); written also on failure")
    add_port_arguments(parser)


_SCENARIO_PRAGMA = re.compile(r"^#\s*scenario:\s*(\S+)\s*$")


def declared_scenario(path: Path) -> str | None:
    """A script may name the simulator scenario it was written for in a
    comment line ``# scenario: NAME``; used when neither --port nor
    --scenario is given, so ``hexbot run SCRIPT`` just works. A scenario
    file (a name ending in ``.toml`` or with a folder in it) is relative to
    the script's folder, whatever the current one; a built-in or generated
    name (``pair``, ``blob:50``) stays a name. The scenario must exist and
    load: else a ScenarioError ``SCRIPT:LINE: scenario: ...`` naming the
    resolved file (checked with the script's other lines)."""
    from hexbot.hil_sim.scenario import is_scenario_file, load_scenario

    for number, line in enumerate(read_text(path, "script").splitlines(), start=1):
        m = _SCENARIO_PRAGMA.match(line.strip())
        if m:
            name = m.group(1)
            if is_scenario_file(name):
                name = str(path.parent / name)  # beside the script, not the cwd
            try:
                load_scenario(name)
            except HexBotError as exc:
                raise ScenarioError(f"{path}:{number}: scenario: {exc}") from None
            return name
    return None


def run(args: argparse.Namespace) -> int:
    steps = load_script(args.script)  # every line checked before anything is sent
    if not steps:  # "all 0 steps passed" would pass a truncated or wrong file
        raise ScenarioError(f"{args.script}: no steps (only comments and blank lines)")
    declared = declared_scenario(args.script)  # a line of the script: checked with them
    if args.check:
        print(f"{args.script}: {len(steps)} steps, syntax OK")
        return 0
    if not args.port and not args.scenario:
        args.scenario = declared
    # Scripts are regressions: on the embedded simulator they run in virtual
    # time (default --sim-speed 0), where every time-out is simulated seconds.
    runner: ScriptRunner | None = None
    results: list[StepResult] = []
    try:
        with session(args) as sess:
            runner = ScriptRunner(sess, str(args.script))
            results = runner.results
            try:
                runner.run(steps)
            except ScriptFailed as exc:
                print(f"FAILED {exc}", file=sys.stderr)
                print(f"{runner.steps_done} of {len(steps)} steps passed", file=sys.stderr)
                return exc.exit_status
    except (HexBotError, KeyboardInterrupt) as exc:
        if not results:  # no step began: the port, the boot, or Ctrl-C during it
            reason = INTERRUPTED if isinstance(exc, KeyboardInterrupt) else str(exc)
            results = not_started(steps, reason)
        raise
    finally:  # a lost port too: CI shows which step could not be judged
        if args.junit:
            write_junit(args.junit, str(args.script), results)
    print(f"{args.script}: all {len(steps)} steps passed", file=sys.stderr)
    return 0
