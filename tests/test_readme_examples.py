"""Every command the README shows runs as written (issue 13: "the README's
examples all run as written").

The examples are read from README.md itself, so an example added there is
run here too; one that needs hardware or a person at the keyboard must be
listed in NOT_RUN with the reason and the test that covers it instead."""

from __future__ import annotations

import json
import re
import shlex
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
BIN = Path(sys.executable).parent

#: Examples not run here, by a substring of the command: why, and where instead.
NOT_RUN = {
    "/dev/tty": "needs modules or an ISP on a real serial port (tests/flash, "
                "tests/host run the same paths on ptys)",
    "hexbot console": "interactive TUI: tests/host/test_console.py drives it with Pilot",
    "hexbot.hil_sim.miniterm": "interactive terminal: tests/hil_sim/test_miniterm*.py",
    "hexbot sim flower7 --pty": "runs until stopped: test_the_pty_example_prints_its_ports",
}


def readme_examples() -> list[str]:
    """The `.venv/bin/...` command lines of the README's sh blocks, with
    continuation lines joined and trailing comments dropped."""
    text = (ROOT / "README.md").read_text()
    commands = []
    for block in re.findall(r"```sh\n(.*?)```", text, flags=re.S):
        for line in block.replace("\\\n", " ").splitlines():
            line = line.strip()
            if line.startswith(".venv/bin/"):
                commands.append(" ".join(shlex.split(line, comments=True)))
    return commands


def runnable() -> list[str]:
    return [c for c in readme_examples() if not any(key in c for key in NOT_RUN)]


def test_the_readme_has_examples_and_each_unrun_one_is_accounted_for():
    examples = readme_examples()
    assert len(examples) >= 15
    for key in NOT_RUN:
        assert any(key in c for c in examples), f"NOT_RUN lists {key!r}, no longer in README"


@pytest.fixture(scope="module")
def workdir(tmp_path_factory) -> Path:
    """One scratch folder for all examples, run in README order as a reader
    would (``sweep report`` reads what ``sweep`` wrote); it sees the
    repository's example files, and outputs such as run.gif land here."""
    tmp_path = tmp_path_factory.mktemp("readme")
    for name in ("docs", "planning"):
        (tmp_path / name).symlink_to(ROOT / name)
    return tmp_path


@pytest.mark.parametrize("command", runnable())
def test_readme_example_runs_as_written(command: str, workdir: Path):
    argv = shlex.split(command)
    argv[0] = str(BIN / Path(argv[0]).name)
    done = subprocess.run(argv, cwd=workdir, capture_output=True, text=True, timeout=900)
    assert done.returncode == 0, f"{command}\n{done.stdout[-2000:]}\n{done.stderr[-2000:]}"
    for out in re.findall(r"--render (\S+)", command):
        assert (workdir / out).stat().st_size > 0


def test_the_pty_example_prints_its_ports(tmp_path: Path):
    (command,) = [c for c in readme_examples() if "hexbot sim flower7 --pty" in c]
    argv = shlex.split(command)
    argv[0] = str(BIN / "hexbot")
    proc = subprocess.Popen(argv, cwd=tmp_path, stdout=subprocess.PIPE, text=True)
    try:
        ports = json.loads(proc.stdout.readline())
        assert Path(ports["ir"]).exists()
        assert sorted(ports["uart1"], key=int) == [str(i) for i in range(1, 8)]
    finally:
        proc.terminate()
        proc.wait(timeout=60)
