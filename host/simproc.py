"""The simulator in another process, behind pty ports: the hardware path.

``hexbot sim SCENARIO --pty`` prints one JSON line
``{"ir": "/dev/pts/N", "uart1": {"3": "/dev/pts/M", ...}}`` and serves those
ptys until it is stopped. :class:`SimProcess` starts it and reads that
line; the host then opens the ptys as it would open an RS232 converter and
knows nothing else about the simulator (no plant verdicts, no truth): what
works here works on real modules. The in-process simulator is the
``hexbot-sim://`` URL instead.
"""

from __future__ import annotations

import ctypes
import json
import os
import selectors
import signal
import subprocess
import sys
import tempfile
import threading
import time
from dataclasses import dataclass

from hexbot.errors import LinkUnavailableError

# Looked up before any fork: the child must not load libraries (another
# thread of the console may hold the import or malloc lock at fork time).
_PRCTL = ctypes.CDLL(None).prctl if sys.platform.startswith("linux") else None
_PR_SET_PDEATHSIG = 1


def _die_with_parent() -> None:
    """In the child: ask Linux to SIGTERM it when the host process dies, so
    a killed console never leaves a simulator running."""
    if _PRCTL is not None:
        _PRCTL(_PR_SET_PDEATHSIG, int(signal.SIGTERM))


@dataclass(frozen=True)
class SimPorts:
    ir: str
    uart1: dict[int, str]


class SimProcess:
    def __init__(self, scenario: str = "flower7", seed: int | None = None,
                 speed: float = 1.0, start_timeout: float = 60.0,
                 wait_client: bool = False) -> None:
        self.scenario = scenario
        self.speed = speed
        cmd = [sys.executable, "-m", "hexbot.cli", "sim", scenario, "--pty",
               "--speed", f"{speed:g}"]
        if seed is not None:
            cmd += ["--seed", str(seed)]
        if wait_client:  # hold the clock until the IR port is open: the boot texts reach it
            cmd.append("--wait-client")
        self.command = cmd
        # stderr to a file and stdout drained by a thread: a chatty child
        # must never block on a full pipe.
        self._stderr = tempfile.TemporaryFile()
        self._proc = self._spawn(cmd)
        try:
            self.ports = self._read_ports(start_timeout)
        except BaseException:
            self.close()
            raise
        threading.Thread(target=self._drain, daemon=True, name="sim stdout").start()

    def _spawn(self, cmd: list[str]) -> subprocess.Popen:
        """Start the child from a thread that lives until close(): Linux
        sends the parent-death signal when the *thread* that forked exits,
        and callers (the console's workers) are short-lived threads."""
        started = threading.Event()
        self._release = threading.Event()
        box: list[subprocess.Popen | BaseException] = []

        def owner() -> None:
            try:
                box.append(subprocess.Popen(cmd, stdin=subprocess.DEVNULL,
                                            stdout=subprocess.PIPE, stderr=self._stderr,
                                            preexec_fn=_die_with_parent))
            except BaseException as exc:  # handed to the caller below
                box.append(exc)
            finally:
                started.set()
            self._release.wait()

        threading.Thread(target=owner, name="sim owner", daemon=True).start()
        started.wait()
        if isinstance(box[0], BaseException):
            raise LinkUnavailableError(f"cannot start the simulator: {box[0]}") from box[0]
        return box[0]

    def _drain(self) -> None:
        stream = self._proc.stdout
        try:
            while stream is not None and stream.read(4096):
                pass
        except (OSError, ValueError):
            pass  # closed by close()

    def _read_ports(self, timeout: float) -> SimPorts:
        assert self._proc.stdout is not None
        sel = selectors.DefaultSelector()
        sel.register(self._proc.stdout, selectors.EVENT_READ)
        deadline = time.monotonic() + timeout
        buf = b""
        fd = self._proc.stdout.fileno()
        while b"\n" not in buf:
            left = deadline - time.monotonic()
            if left <= 0 or not sel.select(left):
                raise LinkUnavailableError(
                    f"simulator ({' '.join(self.command[2:])}) printed no ports "
                    f"within {timeout:g} s")
            chunk = os.read(fd, 4096)
            if not chunk:
                err = self._stderr_tail()
                raise LinkUnavailableError(
                    f"simulator exited before printing its ports"
                    f" (exit {self._proc.wait()}){': ' + err if err else ''}")
            buf += chunk
        line = buf.split(b"\n", 1)[0]
        try:
            info = json.loads(line)
            return SimPorts(ir=info["ir"],
                            uart1={int(k): v for k, v in info.get("uart1", {}).items()})
        except (ValueError, KeyError, TypeError) as exc:
            raise LinkUnavailableError(f"simulator printed {line[:200]!r}, "
                                       f"expected a JSON line with 'ir' and 'uart1'") from exc

    def _stderr_tail(self) -> str:
        try:
            self._proc.wait(timeout=2)
        except subprocess.TimeoutExpired:
            return ""
        self._stderr.seek(0)
        return self._stderr.read().decode(errors="replace").strip()[-400:]

    @property
    def running(self) -> bool:
        return self._proc.poll() is None

    def close(self) -> None:
        """Stop the simulator. Idempotent."""
        if self._proc.poll() is None:
            self._proc.terminate()
            try:
                self._proc.wait(timeout=5)
            except subprocess.TimeoutExpired:
                self._proc.kill()
                self._proc.wait()
        if self._proc.stdout is not None:
            self._proc.stdout.close()
        self._stderr.close()
        self._release.set()

    def __enter__(self) -> SimProcess:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()
