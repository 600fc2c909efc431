"""Where a session on the embedded simulator connects (session 35's audit):
the speed asked for, 0 included, and the UART1 of the lowest module id
unless --debug-module names another."""

from __future__ import annotations

import re

import pytest

from hexbot.cli import main


@pytest.mark.parametrize("argv, uart1", [([], 1), (["--debug-module", "2"], 2)])
def test_monitor_on_the_simulator_at_speed_0_opens_the_uart1_asked_for(
        capsys, log_dir, argv, uart1):
    # --sim-speed 0 (virtual time) must not fall back to the monitor's default, 1
    assert main(["monitor", "--scenario", "pair", "--sim-speed", "0", "--duration", "3",
                 *argv]) == 0
    out = capsys.readouterr()
    assert "ir: connected hexbot-sim://pair?speed=0 300 8N1" in out.err, out.err
    assert re.search(rf"^debug: connected hexbot-sim://@\d+/uart1/{uart1} 4800 8N1$",
                     out.err, re.M), out.err
    debug = [line for line in out.out.splitlines() if line.split()[1] == "debug"]
    assert f"CTR. BOARD READY [ID=0{uart1} " in debug[0], debug
