"""Running avrdude for one ATmega162, and turning its output into words.

avrdude does the programming; this module builds its command lines, reads
back what it wrote to files (signature, fuses, lock), and turns its error
lines into one readable message with a hint at the usual cause.
"""

from __future__ import annotations

import os
import re
import select
import shutil
import subprocess
import tempfile
import time
from dataclasses import dataclass, field
from pathlib import Path

from hexbot.errors import FlashingError, LinkUnavailableError
from hexbot.host.flash.fuses import FuseSet

PART = "m162"
PROBE_TIMEOUT_S = 60.0  # avrdude retries a silent port for about a minute
WRITE_TIMEOUT_S = 300.0  # a full 16 KiB at 115200 baud takes a few seconds
# avrdude writes something (a progress '#', or "timeout" every 5 s while a
# programmer is silent) at least every few seconds; a port that vanishes
# mid-write leaves it looping without a word. This long without a byte on
# its stdout/stderr, it is stopped and the port counted as lost (exit 4).
NO_PROGRESS_S = 20.0
ERASED_NOTE = "; the chip may be erased or half-written: flash it again"
_DONE = "avrdude done.  Thank you."
# stderr of a port that cannot be opened (avrdude 7.x; 6.x ser_open())
_PORT_MISSING = ("cannot open port", "can't open device", "ser_open()")
# stderr of a port lost while open (unplugged adapter, closed pty)
_PORT_LOST = ("input/output error", "ser_send(): write error", "ser_recv(): read error",
              "no such device")

_WRITTEN = re.compile(r"(\d+) bytes? of (\w+) written")
_VERIFIED = re.compile(r"(\d+) bytes? of (\w+) verified")
_VERIFYING = re.compile(r"verifying (\w+) memory")
_MISMATCH = re.compile(r"device (0x[0-9a-fA-F]+) != input (0x[0-9a-fA-F]+)")
_PREFIX = re.compile(r"^avrdude(?: OS)?(?: \S+\(\))?(?: (?:error|warning))?: ")
_PROBABLY = re.compile(r"device signature = 0x([0-9a-fA-F]{6})(?: \(probably (\S+)\))?")


@dataclass(frozen=True)
class DeviceInfo:
    signature: bytes
    fuses: FuseSet
    part_guess: str | None = None  # avrdude's name for the signature, if it knows one

    @property
    def signature_text(self) -> str:
        return self.signature.hex(" ").upper()


@dataclass
class WriteReport:
    written: dict[str, int] = field(default_factory=dict)  # memory -> bytes
    verified: dict[str, int] = field(default_factory=dict)
    log: str = ""


def explain(stderr: str, port: str, programmer: str) -> str:
    """avrdude's error lines, cleaned up, plus the likely cause."""
    lines = [ln.strip() for ln in stderr.splitlines()]
    errors = [_PREFIX.sub("", ln) for ln in lines if re.match(r"^avrdude.* (?:error|warning):", ln)]
    errors += [_PREFIX.sub("", ln) for ln in lines if "verification error" in ln]
    # avrdude 6.x has no "error:" prefix and ends with a blank line: take
    # the last line that says something
    said = [re.sub(r"^avrdude(?: OS)?: ", "", ln) for ln in lines if ln and ln != _DONE]
    text = "; ".join(dict.fromkeys(errors)) or (said[-1] if said else "no output")
    low = stderr.lower()
    mismatch = _MISMATCH.search(stderr)
    if port_missing(stderr):
        hint = (f"is the programmer plugged in at {port}, and may you open it "
                "(group dialout)?")
    elif "communicating with programmer" in low or "getsync" in low:
        # before "initialization failed": avrdude 7 says both when nothing answers
        hint = f"no {programmer} programmer answered on {port}"
    elif "initialization failed" in low or "program enable" in low:
        hint = ("the programmer answered but the ATmega162 did not enter programming mode: "
                "check the ISP cable, the programming jumper of that board, and that the "
                "programmer powers the module (thesis 3.4.6)")
    elif "timeout" in low or "getsync" in low or "not in sync" in low:
        hint = f"no {programmer} programmer answered on {port}"
    elif mismatch or "verification error" in low:
        memory = verifying(stderr) or "flash"
        found = (f"the {memory} reads back {mismatch.group(1)}, not {mismatch.group(2)}"
                 if mismatch else f"the {memory} does not hold what was written")
        hint = found + (" (lock bits set? worn flash?)" if memory == "flash" else
                        ": some fuse bits cannot be changed over ISP (SPIEN), or lock bits "
                        "block the write")
    else:
        hint = ""
    return f"avrdude failed: {text}" + (f" ({hint})" if hint else "")


def verifying(stderr: str) -> str | None:
    """The memory avrdude was verifying last (``verifying hfuse memory against ...``)."""
    found = _VERIFYING.findall(stderr)
    return found[-1] if found else None


def _flash_verified(stderr: str) -> bool:
    return any(m.group(2) == "flash" for m in _VERIFIED.finditer(stderr))


def port_missing(stderr: str) -> bool:
    low = stderr.lower()
    return any(sign in low for sign in _PORT_MISSING)


def port_lost(stderr: str) -> bool:
    low = stderr.lower()
    return any(sign in low for sign in _PORT_LOST)


def _collect(proc: subprocess.Popen[bytes], timeout: float) -> tuple[bytes, bytes, str | None]:
    """stdout and stderr of ``proc`` until it ends; kill it and say why
    ("timeout", "stalled") when it runs too long or is silent too long."""
    assert proc.stdout is not None and proc.stderr is not None
    out, err = bytearray(), bytearray()
    streams = {proc.stdout.fileno(): out, proc.stderr.fileno(): err}
    start = last = time.monotonic()
    why = None
    while streams:
        now = time.monotonic()
        if now - start > timeout:
            why = "timeout"
            break
        if now - last > NO_PROGRESS_S:
            why = "stalled"
            break
        ready, _, _ = select.select(list(streams), [], [], 0.2)
        for fd in ready:
            data = os.read(fd, 65536)
            if data:
                streams[fd] += data
                last = time.monotonic()
            else:
                del streams[fd]
    if why is None:
        try:
            proc.wait(max(0.0, timeout - (time.monotonic() - start)) + 1.0)
        except subprocess.TimeoutExpired:
            why = "timeout"
    if why is not None:
        proc.kill()
        proc.wait()
    return bytes(out), bytes(err), why


@dataclass
class Avrdude:
    port: str
    programmer: str = "stk500v2"
    executable: str = "avrdude"
    baud: int | None = None
    bitclock: str | None = None  # avrdude -B, e.g. "125kHz" for a slow target

    def base_command(self) -> list[str]:
        exe = shutil.which(self.executable)
        if exe is None:
            raise FlashingError(
                f"avrdude not found ({self.executable!r}): sudo apt-get install avrdude")
        cmd = [exe, "-c", self.programmer, "-P", self.port, "-p", PART]
        if self.baud is not None:
            cmd += ["-b", str(self.baud)]
        if self.bitclock:
            cmd += ["-B", self.bitclock]
        return cmd

    def run(self, args: list[str], timeout: float,
            writing: bool = False) -> subprocess.CompletedProcess[str]:
        """Run avrdude with ``args``; ``writing``: the chip erase may have
        started, so a failure may leave the chip erased."""
        cmd = self.base_command() + args
        note = ERASED_NOTE if writing else ""
        try:
            popen = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
        except OSError as exc:
            raise FlashingError(f"cannot run avrdude ({cmd[0]}): {exc}") from exc
        with popen:
            out, err, why = _collect(popen, timeout)
        stdout = out.decode("utf-8", "replace")
        stderr = err.decode("utf-8", "replace")
        if why == "stalled":
            raise LinkUnavailableError(
                f"avrdude stopped: no output for {NO_PROGRESS_S:.0f} s, the programmer on "
                f"{self.port} was lost or stopped answering{note}")
        if why == "timeout":
            raise FlashingError(
                f"avrdude gave no result within {timeout:.0f} s: no {self.programmer} "
                f"programmer answered on {self.port}?{note}")
        proc = subprocess.CompletedProcess(cmd, popen.returncode, stdout, stderr)
        if proc.returncode != 0:
            if verifying(stderr) not in (None, "flash") and _flash_verified(stderr):
                note = "; the flash was written and verified before"  # a fuse failed
            text = explain(stderr, self.port, self.programmer) + note
            if port_missing(stderr) or port_lost(stderr):
                raise LinkUnavailableError(text)
            raise FlashingError(text)
        return proc

    def read_device(self) -> DeviceInfo:
        """Signature, fuses and lock byte, whatever the chip is (-F: we do
        the signature check ourselves, to say clearly what is there)."""
        with tempfile.TemporaryDirectory(prefix="hexbot-flash-") as tmp:
            names = ("signature", "lfuse", "hfuse", "efuse", "lock")
            ops = []
            for name in names:
                ops += ["-U", f"{name}:r:{Path(tmp, name)}:r"]
            proc = self.run(["-F", *ops], PROBE_TIMEOUT_S)
            try:
                values = {name: Path(tmp, name).read_bytes() for name in names}
            except OSError as exc:
                raise FlashingError(
                    f"avrdude ({self.executable}) ended without reading the device: "
                    f"no {Path(exc.filename or '?').name} came back") from exc
        if len(values["signature"]) != 3 or any(len(values[n]) != 1 for n in names[1:]):
            raise FlashingError(f"avrdude returned incomplete device data: {values}")
        match = _PROBABLY.search(proc.stderr)
        return DeviceInfo(
            signature=values["signature"],
            fuses=FuseSet(values["lfuse"][0], values["hfuse"][0], values["efuse"][0],
                          values["lock"][0]),
            part_guess=match.group(2) if match else None,
        )

    @staticmethod
    def write_args(image: Path, fuses: FuseSet | None, verify: bool) -> list[str]:
        ops = ["-U", f"flash:w:{image}:i"]
        if fuses is not None:
            # Fuses before lock: once locked, the fuses could not be changed.
            ops += ["-U", f"lfuse:w:0x{fuses.lfuse:02X}:m", "-U", f"hfuse:w:0x{fuses.hfuse:02X}:m",
                    "-U", f"efuse:w:0x{fuses.efuse:02X}:m", "-U", f"lock:w:0x{fuses.lock:02X}:m"]
        return ops if verify else ["-V", *ops]

    def write(self, image: Path, fuses: FuseSet | None, verify: bool) -> WriteReport:
        """Chip erase, flash (Intel HEX), then the fuses if given; avrdude
        reads every memory back unless ``verify`` is false."""
        proc = self.run(self.write_args(image, fuses, verify), WRITE_TIMEOUT_S,
                        writing=True)
        report = WriteReport(log=proc.stderr)
        for m in _WRITTEN.finditer(proc.stderr):
            report.written[m.group(2)] = report.written.get(m.group(2), 0) + int(m.group(1))
        for m in _VERIFIED.finditer(proc.stderr):
            report.verified[m.group(2)] = report.verified.get(m.group(2), 0) + int(m.group(1))
        return report
