"""Progress of long CLI runs, read from a real pty as a user's terminal
shows it (issue 13, defect 9): boot waits and random-map sweeps; Ctrl-C
keeps what finished."""

from __future__ import annotations

import json
import os
import re
import select
import signal
import subprocess
import sys
import time


def _ctrl_c_as_on_a_terminal() -> None:
    # A suite started in the background (`make test &`) passes Ctrl-C on as
    # ignored, and Python then never raises KeyboardInterrupt: give the child
    # the default, as a terminal would.
    signal.signal(signal.SIGINT, signal.SIG_DFL)


def _start(*argv: str) -> tuple[subprocess.Popen, int]:
    """The CLI with stderr on a pty (a terminal: bars are drawn), stdout piped."""
    master, slave = os.openpty()
    proc = subprocess.Popen([sys.executable, "-m", "hexbot.cli", *argv],
                            stdout=subprocess.PIPE, stderr=slave, text=True,
                            env={**os.environ, "COLUMNS": "120", "TERM": "xterm"},
                            preexec_fn=_ctrl_c_as_on_a_terminal)
    os.close(slave)
    return proc, master


def _read_until(master: int, needle: bytes, limit_s: float = 120.0) -> bytes:
    seen = b""
    end = time.monotonic() + limit_s
    while needle not in seen and time.monotonic() < end:
        if select.select([master], [], [], 0.5)[0]:
            try:
                seen += os.read(master, 4096)
            except OSError:  # the child closed the pty
                break
    return seen


def test_random_sweep_shows_a_bar_and_keeps_partial_results_on_ctrl_c():
    proc, master = _start("locomotion", "random", "salvador", "--seeds", "0:300",
                          "--n", "5", "--json")
    try:
        shown = _read_until(master, b"3/300")
        assert b"random maps, salvador" in shown and b"3/300" in shown, shown[-400:]
        proc.send_signal(signal.SIGINT)
        out, _ = proc.communicate(timeout=60)
        tail = _read_until(master, b"seeds done", 10)
    finally:
        proc.kill()
        os.close(master)
    assert proc.returncode == 130
    report = json.loads(out)
    assert report["interrupted"] is True
    first, end = map(int, report["seeds"].split(":"))
    assert first == 0 and 3 <= end < 300 and report["runs"] == end  # one size: a run per seed
    assert f"interrupted: {end} of 300 seeds done".encode() in tail


def test_boot_wait_counts_the_modules_that_booted(log_dir):
    proc, master = _start("send", "Status", "--module", "2", "--scenario", "pair")
    try:
        out, _ = proc.communicate(timeout=120)
        shown = _read_until(master, b"modules booted in", 10)
    finally:
        proc.kill()
        os.close(master)
    assert proc.returncode == 0, shown
    assert b"simulator pair: modules booted" in shown and b"2/2" in shown
    assert b"simulator: pair, 2 of 2 modules booted in " in shown


def test_send_shows_replies_elapsed_and_time_out_while_it_waits():
    from hexbot.host.simproc import SimProcess

    with SimProcess("pair", speed=5) as sim:  # paced: the localization takes seconds
        for _ in range(30):  # until the modules have booted and module 1 takes Ref
            ref = subprocess.run([sys.executable, "-m", "hexbot.cli", "send", "Ref", "--module",
                                  "1", "--port", sim.ports.ir, "--no-log"], capture_output=True)
            if ref.returncode == 0:
                break
        assert ref.returncode == 0, ref.stderr
        proc, master = _start("send", "Localize", "--module", "0", "--port", sim.ports.ir,
                              "--no-log")
        try:
            proc.communicate(timeout=120)
            shown = _read_until(master, b"ok: Localize", 10)
        finally:
            proc.kill()
            os.close(master)
    assert proc.returncode == 0, shown
    assert b"Localize(): replied" in shown and b"/2" in shown
    assert re.search(rb"\d+\.\d s of \d+ s", shown), shown


def test_plan_shows_the_stage_the_planner_is_at_and_keeps_a_pipe_clean(tmp_path):
    from hexbot.bench.planning import make_pair

    files = []
    for name, cells in zip(("initial", "goal"), make_pair("blob", 300, 0), strict=True):
        path = tmp_path / f"{name}.toml"
        path.write_text("cells = [" + ", ".join(f"[{x}, {y}]" for x, y in sorted(cells)) + "]\n")
        files.append(str(path))
    proc, master = _start("plan", *files)  # the local flows take seconds here
    try:
        out, _ = proc.communicate(timeout=120)
        shown = _read_until(master, b"\x00", 2)  # whatever the pty still holds
    finally:
        proc.kill()
        os.close(master)
    assert proc.returncode == 0 and out.startswith("mode robust (local): goal reached")
    assert b"planning 300 modules: local" in shown
    # piped, nothing is drawn
    piped = subprocess.run([sys.executable, "-m", "hexbot.cli", "plan", *files],
                           capture_output=True, text=True, timeout=120)
    assert piped.returncode == 0 and piped.stderr == ""
