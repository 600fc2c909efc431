"""Who holds a serial port: two programs reading one port split its bytes
silently, so the host opens ports exclusively (an advisory ``flock``, as
pyserial's ``exclusive=True`` and miniterm's ``--exclusive`` take it) and,
when the lock is taken, names the process that holds it (``/proc/locks``)."""

from __future__ import annotations

import os
from pathlib import Path


def lock_holders(device: str) -> list[int]:
    """PIDs holding a ``flock`` on ``device`` (Linux; [] elsewhere or unknown)."""
    try:
        st = os.stat(device)
        locks = Path("/proc/locks").read_text()
    except OSError:
        return []
    want = (os.major(st.st_dev), os.minor(st.st_dev), st.st_ino)
    pids = []
    for line in locks.splitlines():
        fields = line.split()
        if len(fields) < 6 or fields[1] != "FLOCK":
            continue
        try:
            major, minor, inode = fields[5].split(":")
            key = (int(major, 16), int(minor, 16), int(inode))
        except ValueError:
            continue
        if key == want:
            pids.append(int(fields[4]))
    return pids


def describe_holder(pid: int) -> str:
    """``PID 1234 (hexbot monitor --port /dev/pts/3)``."""
    try:
        raw = Path(f"/proc/{pid}/cmdline").read_bytes()
    except OSError:
        return f"PID {pid}"
    # one line: arguments may hold newlines (python -c '...')
    words = " ".join(raw.decode(errors="replace").replace("\0", " ").split())
    return f"PID {pid} ({words[:120]})" if words else f"PID {pid}"


def busy_reason(device: str) -> str:
    """The one-line reason for a port whose exclusive lock is taken."""
    holders = [describe_holder(p) for p in lock_holders(device) if p != os.getpid()]
    return (f"port busy, held by {', '.join(holders)}" if holders
            else "port busy: another program holds its lock")
