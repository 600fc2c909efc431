"""The ``hexbot`` entry point lists its subcommands and runs them."""

import subprocess
import sys


def test_help_lists_subcommands():
    out = subprocess.run(
        [sys.executable, "-m", "hexbot.cli", "--help"], capture_output=True, text=True, check=True
    ).stdout
    for name in ("codes", "gen-header"):
        assert name in out


def test_unknown_command_fails():
    proc = subprocess.run(
        [sys.executable, "-m", "hexbot.cli", "no-such-command"], capture_output=True, text=True
    )
    assert proc.returncode != 0


TELEPORT = ("ruleset tp\nstates static active\nresting static\nsupport module\nsymmetry none\n"
            'rule R1 "east"\n  priority 10\n  state static\n  require E is empty\n  move E\n')


def _into_a_closed_pipe(*argv: str) -> subprocess.CompletedProcess:
    """Run hexbot with its stdout a pipe whose reader is already gone (as
    `hexbot ... | head -2` once head has exited), block-buffered as Python
    makes a pipe (no PYTHONUNBUFFERED)."""
    import os

    read, write = os.pipe()
    os.close(read)
    env = {k: v for k, v in os.environ.items() if k != "PYTHONUNBUFFERED"}
    try:
        return subprocess.run([sys.executable, "-m", "hexbot.cli", *argv], stdout=write,
                              stderr=subprocess.PIPE, text=True, timeout=300, env=env)
    finally:
        os.close(write)


def test_a_closed_output_pipe_is_quiet_and_never_exit_0(tmp_path):
    """It was exit 0 whatever the command's outcome: a rule set that breaks an
    invariant (exit 1 unpiped) looked like a success behind `| head`."""
    rules = tmp_path / "teleport.rules"
    rules.write_text(TELEPORT)
    # the run fails before its short report reaches the pipe: its own status
    proc = _into_a_closed_pipe("locomotion", "run", str(rules), "flat", "--n", "3",
                               "--rounds", "20")
    assert proc.returncode == 1 and proc.stderr == ""
    # the pipe breaks while the long report is written: 128 + SIGPIPE
    proc = _into_a_closed_pipe("locomotion", "run", str(rules), "flat", "--n", "3000",
                               "--rounds", "20")
    assert proc.returncode == 141 and proc.stderr == ""
    proc = _into_a_closed_pipe("codes")  # a success whose output was cut short
    assert proc.returncode == 141 and proc.stderr == ""


def test_a_command_started_with_stdout_closed_keeps_its_status():
    """`hexbot codes >&-` (a daemon, a cron job): the flush for a closed pipe
    met no stdout at all and turned a success into a traceback, exit 1."""
    proc = subprocess.run(f'exec 1>&-; "{sys.executable}" -m hexbot.cli codes', shell=True,
                          stderr=subprocess.PIPE, text=True, timeout=300)
    assert proc.returncode == 0 and "Traceback" not in proc.stderr, proc.stderr
