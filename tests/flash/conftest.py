"""Fixtures for the flashing tests: simulated programmers on ptys, test
images built with avr-gcc, and a runner for ``hexbot flash``."""

from __future__ import annotations

import shutil
import subprocess
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from pathlib import Path

import pytest

from hexbot.cli import main as hexbot_main
from hexbot.hil_sim.isp import (
    Atmega162Isp,
    Atmega162Memory,
    IspPtyServer,
    MemoryBackend,
    Stk500v2Programmer,
)

AVR_DIR = Path(__file__).parent / "avr"



@dataclass
class SimChip:
    port: str
    backend: MemoryBackend
    programmer: Stk500v2Programmer

    @property
    def memory(self) -> Atmega162Memory:
        return self.backend.memory


@pytest.fixture
def isp_server() -> Iterator[Callable[..., SimChip]]:
    """Factory: ``chip = isp_server(memory=...)`` serves one simulated
    ATmega162 behind an STK500v2 on a fresh pty."""
    server = IspPtyServer()
    count = 0

    def add(memory: Atmega162Memory | None = None) -> SimChip:
        nonlocal count
        backend = MemoryBackend(memory)
        programmer = Stk500v2Programmer(Atmega162Isp(backend))
        count += 1
        path = server.add(f"chip{count}", programmer)
        server.start()
        return SimChip(path, backend, programmer)

    yield add
    server.close()


def build_image(out_dir: Path, version: str) -> tuple[Path, Path]:
    """Compile avr/hello.c with a version string; return (elf, hex)."""
    out_dir.mkdir(parents=True, exist_ok=True)
    elf, hexfile = out_dir / f"hello-{version}.elf", out_dir / f"hello-{version}.hex"
    subprocess.run(
        ["avr-gcc", "-mmcu=atmega162", "-Os", "-DF_CPU=1000000UL", f'-DVERSION="{version}"',
         "-o", str(elf), str(AVR_DIR / "hello.c")], check=True)
    subprocess.run(["avr-objcopy", "-O", "ihex", "-R", ".eeprom", str(elf), str(hexfile)],
                   check=True)
    return elf, hexfile


@pytest.fixture(scope="session")
def images(tmp_path_factory) -> Callable[[str], tuple[Path, Path]]:
    if shutil.which("avr-gcc") is None:
        pytest.skip("avr-gcc missing")
    out = tmp_path_factory.mktemp("images")
    cache: dict[str, tuple[Path, Path]] = {}

    def get(version: str) -> tuple[Path, Path]:
        if version not in cache:
            cache[version] = build_image(out, version)
        return cache[version]

    return get


@dataclass
class CliResult:
    code: int
    out: str
    err: str


@pytest.fixture
def hexbot_flash(capsys) -> Callable[..., CliResult]:
    def run(*argv: str) -> CliResult:
        code = hexbot_main(["flash", *argv])
        captured = capsys.readouterr()
        return CliResult(code, captured.out, captured.err)

    return run


FIRMWARE = Path(__file__).resolve().parents[2] / "firmware"


@pytest.fixture(scope="session")
def firmware_build(tmp_path_factory) -> Callable[[str], Path]:
    """Build the real firmware with a version string into a private folder
    (``make -C firmware BUILD=... VERSION=...``); return that folder."""
    if not (FIRMWARE / "Makefile").exists() or shutil.which("avr-gcc") is None:
        pytest.skip("firmware/Makefile or avr-gcc missing")
    built: dict[str, Path] = {}

    def get(version: str) -> Path:
        if version not in built:
            out = tmp_path_factory.mktemp("fw") / "build"
            subprocess.run(["make", "-s", "-C", str(FIRMWARE), f"BUILD={out}",
                            f"VERSION={version}"], check=True, capture_output=True)
            built[version] = out
        return built[version]

    return get
