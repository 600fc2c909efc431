"""Kind ``hil-script``: one .hbs script on the embedded simulator, for one
firmware build, scenario and seed.

The task is ``hexbot run SCRIPT --port hexbot-sim://SCENARIO?seed=N&speed=0
[&firmware=DIR]``: the same session set-up and the same
:class:`~hexbot.host.script.ScriptRunner`, in virtual time, so a case gives
the same result wherever it runs. The script's lines and the session's
messages are kept (``log``) for the JUnit report (:mod:`hexbot.sweep.junit`).
Scripts and firmware folders are named relative to the sweep file; on a
remote cluster they must exist at the same paths on every worker.
"""

from __future__ import annotations

import argparse
import io
from contextlib import redirect_stderr
from pathlib import Path

from hexbot.errors import HexBotError, ScenarioError
from hexbot.hil_sim.scenario import is_scenario_file, load_scenario
from hexbot.host.cli_common import session
from hexbot.host.cli_run import declared_scenario
from hexbot.host.endpoints import DEFAULT_SCENARIO, add_port_arguments, sim_url
from hexbot.host.script import ScriptRunner, load_script
from hexbot.sweep.kinds import Param
from hexbot.sweep.summary import markdown

IMAGES = ("comm.elf", "control.elf")


def _check_script(path: str) -> None:
    load_script(Path(path))  # every line checked now, before the sweep runs
    declared_scenario(Path(path))  # its scenario line too (a file beside the script)


def _check_firmware(folder: str) -> None:
    missing = [i for i in IMAGES if not (Path(folder) / i).is_file()]
    if missing:
        raise ScenarioError(f"no {' or '.join(missing)} in {folder} (a firmware build folder)")


PARAMS = [
    Param("script", str, help=".hbs script", path=True, check=_check_script),
    # a file (x.toml, ./x) beside the sweep file; a built-in name stays a name
    Param("scenario", str, None, "simulator scenario (default: the script's "
          "'# scenario:' line, else flower7)", path=is_scenario_file, check=load_scenario),
    Param("seed", int, None, "simulator seed (default: the scenario's)"),
    Param("firmware", str, None, "folder with comm.elf and control.elf (default: the "
          "scenario's images)", path=True, check=_check_firmware),
]
COUNT_BY = (("script", "firmware", "scenario"), "result")


def run(script: str, scenario: str | None, seed: int | None, firmware: str | None) -> dict:
    path = Path(script)
    steps = load_script(path)
    scenario = scenario or declared_scenario(path) or DEFAULT_SCENARIO
    parser = argparse.ArgumentParser()
    add_port_arguments(parser, debug=False)
    args = parser.parse_args(["--port", sim_url(scenario, seed, 0.0, firmware), "--no-log"])
    log = io.StringIO()
    figures: dict = {"scenario_run": scenario, "steps": len(steps)}
    with redirect_stderr(log):
        try:
            with session(args, verbose_states=False) as sess:
                runner = ScriptRunner(sess, path.name, out=lambda line: print(line, file=log))
                try:
                    runner.run(steps)
                finally:
                    figures.update(steps_passed=runner.steps_done, sim_seconds=sess.now())
        except HexBotError as exc:  # a failed step, a lost port, a module that never booted
            figures["failure"] = str(exc)
    figures["result"] = "failed" if "failure" in figures else "passed"
    figures["log"] = log.getvalue()
    return figures


def summarize(rows: list[dict]) -> str:
    """One line per case, as a CI server lists them."""
    body = [[r["script"], r.get("firmware") or "scenario's", r.get("scenario_run"),
             r.get("seed"), r.get("result") or r["outcome"],
             f"{r.get('steps_passed') or 0}/{r.get('steps') or '?'}", r.get("sim_seconds"),
             r["seconds"]]
            for r in sorted(rows, key=lambda r: (r["script"], str(r.get("firmware")),
                                                 str(r.get("scenario")), str(r.get("seed"))))]
    header = ["script", "firmware", "scenario", "seed", "result", "steps", "simulated s",
              "wall s"]
    return markdown(header, body)
