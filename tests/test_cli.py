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
