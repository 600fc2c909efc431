"""Running avrdude for one ATmega162, and turning its output into words.

avrdude does the programming; this module builds its command lines, reads
back what it wrote to files (signature, fuses, lock), and turns its error
lines into one readable message with a hint at the usual cause.
"""

from __future__ import annotations

import re
import shutil
import subprocess
import tempfile
from dataclasses import dataclass, field
from pathlib import Path

from hexbot.errors import FlashingError
from hexbot.host.flash.fuses import FuseSet

PART = "m162"
PROBE_TIMEOUT_S = 60.0  # avrdude retries a silent port for about a minute
WRITE_TIMEOUT_S = 300.0  # a full 16 KiB at 115200 baud takes a few seconds

_WRITTEN = re.compile(r"(\d+) bytes? of (\w+) written")
_VERIFIED = re.compile(r"(\d+) bytes? of (\w+) verified")
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
    errors = [re.sub(r"^avrdude(?: OS)?(?: \S+\(\))? error: ", "", ln)
              for ln in lines if re.match(r"^avrdude.* error:", ln)]
    errors += [ln for ln in lines if "verification error" in ln or "mismatch" in ln]
    text = "; ".join(dict.fromkeys(errors)) or (lines[-1] if lines else "no output")
    low = stderr.lower()
    if "cannot open port" in low or "can't open device" in low:
        hint = (f"is the programmer plugged in at {port}, and may you open it "
                "(group dialout)?")
    elif "initialization failed" in low or "program enable" in low:
        hint = ("the programmer answered but the ATmega162 did not enter programming mode: "
                "check the ISP cable, the programming jumper of that board, and that the "
                "programmer powers the module (thesis 3.4.6)")
    elif "timeout" in low or "getsync" in low or "not in sync" in low:
        hint = f"no {programmer} programmer answered on {port}"
    elif "verification error" in low or "mismatch" in low:
        hint = "the chip does not hold what was written (lock bits set? worn flash?)"
    else:
        hint = ""
    return f"avrdude failed: {text}" + (f" ({hint})" if hint else "")


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
        if self.baud:
            cmd += ["-b", str(self.baud)]
        if self.bitclock:
            cmd += ["-B", self.bitclock]
        return cmd

    def run(self, args: list[str], timeout: float) -> subprocess.CompletedProcess[str]:
        cmd = self.base_command() + args
        try:
            proc = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
        except subprocess.TimeoutExpired:
            raise FlashingError(
                f"avrdude gave no result within {timeout:.0f} s: no {self.programmer} "
                f"programmer answered on {self.port}?") from None
        if proc.returncode != 0:
            raise FlashingError(explain(proc.stderr, self.port, self.programmer))
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
            values = {name: Path(tmp, name).read_bytes() for name in names}
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
        proc = self.run(self.write_args(image, fuses, verify), WRITE_TIMEOUT_S)
        report = WriteReport(log=proc.stderr)
        for m in _WRITTEN.finditer(proc.stderr):
            report.written[m.group(2)] = report.written.get(m.group(2), 0) + int(m.group(1))
        for m in _VERIFIED.finditer(proc.stderr):
            report.verified[m.group(2)] = report.verified.get(m.group(2), 0) + int(m.group(1))
        return report
