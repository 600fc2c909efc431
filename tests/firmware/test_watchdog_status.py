"""A restart by the watchdog is named in Status as WATCHDOG_RESET, not as
another cause (firmware mutation audit, session 32)."""

from __future__ import annotations

import subprocess

from fwsim import BUILD, Bench

from hexbot.protocol import frames
from hexbot.protocol.codes import ErrorCode

RJMP_SELF = bytes([0xFF, 0xCF])  # rjmp .-2: a hang that no longer feeds the watchdog


def symbol(elf, name: str) -> int:
    out = subprocess.run(["avr-nm", str(elf)], check=True, capture_output=True, text=True).stdout
    for line in out.splitlines():
        addr, _kind, sym = line.split()[:3]
        if sym == name:
            return int(addr, 16)
    raise LookupError(name)


def test_a_watchdog_restart_is_reported_in_status(single: Bench):
    # The comm board hangs in reply_status (its flash patched with a jump to
    # itself): the 2 s watchdog restarts it. With the flash restored it boots
    # again, and its first Status names the cause.
    comm = single.sim.modules[1].comm
    flash = comm.cluster.read_flash(comm.index)
    at = symbol(BUILD / "comm.elf", "reply_status")
    comm.cluster.write_flash(comm.index, flash[:at] + RJMP_SELF + flash[at + 2:])
    single.send(frames.encode_pc(frames.make("Status")))
    single.run(3.0)  # the frame (0.37 s), then 2 s of hang
    assert single.sim.resets(1, 0, 1 << 62), "the watchdog did not fire"
    comm.cluster.write_flash(comm.index, flash)
    single.run(4.0)
    assert b"COMM. BOARD READY" in single.drain()
    (sta,) = single.command("Status")
    assert sta.error == ErrorCode.WATCHDOG_RESET, sta
    assert sta.module_id == 1
