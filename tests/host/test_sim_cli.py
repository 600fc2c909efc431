"""The scripting CLI against the embedded simulator (real firmware, ptys)."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

EXAMPLES = Path(__file__).parents[2] / "docs" / "examples"
SIM = ["--sim-speed", "20"]


def hexbot(*argv: str, timeout: float = 120) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "hexbot.cli", *argv], capture_output=True,
                          text=True, timeout=timeout)


def test_send_status_to_a_simulated_module(log_dir):
    proc = hexbot("send", "Status", "--module", "2", "--scenario", "pair", *SIM, "--json")
    assert proc.returncode == 0, proc.stderr
    rows = [json.loads(line) for line in proc.stdout.splitlines()]
    assert rows[0]["kind"] == "ack" and rows[0]["module"] == 2 and rows[0]["function"] == "Select"
    assert rows[1]["kind"] == "statusreport" and rows[1]["module_id"] == 2
    assert rows[1]["role"] == "M" and rows[1]["localized"] is False
    # the session capture replays to the same status
    (folder,) = list(log_dir.iterdir())
    replay = hexbot("replay", str(folder), "--json", "--port", "ir")
    kinds = [json.loads(line)["kind"] for line in replay.stdout.splitlines()]
    assert "statusreport" in kinds and kinds.count("tx") == 2


def test_pair_rotation_script_moves_the_mobile_module(log_dir):
    """Localize, rotate CW about lattice joint 4, localize again: module 2
    is at (0,1) with its orientation turned by two sides."""
    proc = hexbot("run", str(EXAMPLES / "pair_rotate.hbs"), "--scenario", "pair", *SIM)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    assert "STA id 2 role M at (+00,+01) yref 2" in proc.stdout


def test_failing_expectation_on_the_simulator(log_dir, tmp_path):
    script = tmp_path / "bad.hbs"
    script.write_text("select 1\nstatus\nexpect status 1 localized\n")
    proc = hexbot("run", str(script), "--scenario", "pair", *SIM)
    assert proc.returncode == 1
    assert "bad.hbs:3: expect status 1 localized: module is not localized" in proc.stderr


def test_simulator_dies_with_its_host(tmp_path):
    """A killed console (SIGKILL: no clean-up runs) leaves no simulator."""
    code = ("from hexbot.host.simproc import SimProcess\n"
            "import os, time\n"
            "s = SimProcess('single')\n"
            "print(s._proc.pid, flush=True)\n"
            "time.sleep(60)\n")
    proc = subprocess.Popen([sys.executable, "-c", code], stdout=subprocess.PIPE, text=True)
    child = int(proc.stdout.readline())
    proc.kill()
    proc.wait()
    import os
    import time

    for _ in range(100):
        try:
            os.kill(child, 0)
        except ProcessLookupError:
            break
        time.sleep(0.05)
    else:
        os.kill(child, 9)
        raise AssertionError("simulator outlived its host")


def test_simulator_outlives_the_thread_that_started_it():
    """The console opens its session in a worker thread that then ends."""
    import threading
    import time

    from hexbot.host.simproc import SimProcess

    box: list[SimProcess] = []
    t = threading.Thread(target=lambda: box.append(SimProcess("single")))
    t.start()
    t.join()
    try:
        time.sleep(0.5)
        assert box[0].running
    finally:
        box[0].close()
    assert not box[0].running
