"""The embedded simulator stopping mid-session (a fault of its core): `send`,
`run` and `monitor` end at once with one error line and exit 4 (docs/console.md's
exit table: "the simulator stopped"), on the stepped clock (`--sim-speed 0`)
and on the paced one, instead of a traceback or a wait that never ends.

The fault is injected as a test double on the real path: the simulator's
``run`` raises once simulated time passes ``FAULT_T``. Each command runs in
a subprocess whose ``timeout`` only guards against a hang."""

from __future__ import annotations

import os
import subprocess
import sys

import pytest

#: ``python -c``: Simulator.run raises past FAULT_T simulated seconds, then the CLI.
FAULTY_CLI = """
import os, sys
from hexbot.hil_sim import simulator
run = simulator.Simulator.run
def faulty(self, seconds, *args, **kwargs):
    if self.time > float(os.environ["FAULT_T"]):
        raise RuntimeError("injected fault")
    return run(self, seconds, *args, **kwargs)
simulator.Simulator.run = faulty
from hexbot.cli import main
sys.exit(main(sys.argv[1:]))
"""
HANG_GUARD_S = 300  # far beyond any of these runs: only a hang reaches it


@pytest.fixture
def script(tmp_path):
    path = tmp_path / "t.hbs"
    path.write_text("timeout 10\nselect 1\nwait 20\nselect 2\n")
    return path


CASES = {
    # name: (FAULT_T, argv); the pair boots in 8.5 s of simulated time
    "send, stepped, while booting": (3, ["send", "Status", "--module", "2"]),
    "send, stepped, while waiting for a reply": (9, ["send", "Status", "--module", "2"]),
    "send --linger, stepped, while lingering": (12, ["send", "Status", "--module", "2",
                                                     "--linger", "20"]),
    "run, stepped, during a wait step": (12, ["run", "{script}"]),
    "send, paced, while booting": (3, ["send", "Status", "--module", "2",
                                       "--sim-speed", "20"]),
    "run, paced, while booting": (3, ["run", "{script}", "--sim-speed", "20"]),
    "run, paced, during a wait step": (12, ["run", "{script}", "--sim-speed", "20"]),
    "monitor, stepped": (3, ["monitor", "--sim-speed", "0", "--duration", "60"]),
    "monitor, paced": (3, ["monitor", "--sim-speed", "20", "--duration", "60"]),
}


@pytest.mark.parametrize("case", CASES)
def test_a_simulator_that_stops_ends_the_command_with_exit_4(case, script, log_dir):
    fault_t, argv = CASES[case]
    argv = [a.format(script=script) for a in argv] + ["--scenario", "pair"]
    proc = subprocess.run([sys.executable, "-c", FAULTY_CLI, *argv], capture_output=True,
                          text=True, timeout=HANG_GUARD_S,
                          env={**os.environ, "FAULT_T": str(fault_t)})
    assert proc.returncode == 4, proc.stderr
    assert "Traceback" not in proc.stderr, proc.stderr
    (error,) = [line for line in proc.stderr.splitlines() if ": error: " in line]
    assert error.startswith(f"hexbot {argv[0]}: error: "), proc.stderr
    assert "the simulator stopped: RuntimeError: injected fault" in error, proc.stderr
