"""``hexbot flash --all --scenario NAME``: rebuild the firmware and reflash
every board of a simulated cluster through its STK500v2 ptys, with the same
avrdude path and checks as a real board; then boot the cluster and show what
each module says.
"""

from __future__ import annotations

import argparse
import re
import subprocess
from pathlib import Path

from hexbot.errors import FlashingError, LinkUnavailableError, ScenarioError
from hexbot.host.flash.cli import DEFAULT_BUILD, REPO_ROOT, flash_board
from hexbot.protocol import timing, wire

DEFAULT_VERSION = wire.FW_VERSION  # what `make` builds without VERSION=
_LISTENING = re.compile(re.escape(wire.TEXT_COMM_LISTENING + wire.BOOT_ID_TAIL) + r"(\d+)"
                        + re.escape(wire.BOOT_FW_TAIL) + r"(\S+)")


def flashed_version(args: argparse.Namespace) -> str:
    """The version the images were built with: --firmware-version, else the
    build folder's version stamp, else the Makefile's default."""
    if args.firmware_version:
        return args.firmware_version
    stamp = Path(args.build_dir) / "version.stamp"
    try:
        return stamp.read_text().strip() or DEFAULT_VERSION
    except OSError:
        return DEFAULT_VERSION


def not_booted(modules: list[int], heard: str, version: str) -> list[str]:
    """Modules whose ``COMM. LISTENING ID=nn FW=<version>`` is not in
    ``heard``, each with what was heard from it instead."""
    seen: dict[int, list[str]] = {}
    for m in _LISTENING.finditer(heard):
        seen.setdefault(int(m.group(1)), []).append(m.group(2))
    missing = []
    for module in modules:
        versions = seen.get(module, [])
        if version in versions:
            continue
        what = (f"booted FW={', '.join(dict.fromkeys(versions))}" if versions
                else "no COMM. LISTENING with its id")
        missing.append(f"{module} ({what})")
    return missing


def build_firmware(version: str | None, build_dir: Path, say=print) -> None:
    makefile = REPO_ROOT / "firmware" / "Makefile"
    if not makefile.exists():
        raise FlashingError(f"{makefile}: missing, cannot rebuild the firmware")
    cmd = ["make", "-C", str(makefile.parent)]
    if build_dir.resolve() != DEFAULT_BUILD.resolve():
        cmd.append(f"BUILD={build_dir.resolve()}")
    if version:
        cmd.append(f"VERSION={version}")
    say("building: " + " ".join(cmd))
    try:
        proc = subprocess.run(cmd, capture_output=True, text=True)
    except OSError as exc:
        raise FlashingError(f"cannot run make: {exc.strerror or exc} (sudo apt-get install "
                            "make gcc-avr avr-libc)") from exc
    if proc.returncode != 0:
        tail = "\n".join((proc.stdout + proc.stderr).strip().splitlines()[-15:])
        raise FlashingError(f"firmware build failed (make exit {proc.returncode}):\n{tail}")


def flash_all(args: argparse.Namespace, say=print) -> int:
    from hexbot.hil_sim import Simulator
    from hexbot.hil_sim.isp.cluster import open_simulator_isp
    from hexbot.hil_sim.scenario import load_scenario

    try:  # before the build: a bad name costs no rebuild
        scenario = load_scenario(args.scenario)
    except (ScenarioError, OSError) as exc:
        raise LinkUnavailableError(f"cannot start scenario {args.scenario!r}: {exc}") from exc
    if not args.dry_run:
        build_firmware(args.firmware_version, args.build_dir, say)
    try:
        sim = Simulator(scenario)
    except OSError as exc:  # a scenario image missing or unreadable
        raise FlashingError(f"cannot start scenario {args.scenario!r}: {exc}") from exc
    isp = open_simulator_isp(sim)
    try:
        isp.server.start()  # the simulation is not stepped while avrdude runs
        for module, boards in isp.ports_json().items():
            for board, port in boards.items():
                say(f"--- module {module}, {board} board ({port})")
                one = argparse.Namespace(**{**vars(args), "board": board, "port": port,
                                            "image": args.build_dir / f"{board}.hex",
                                            "programmer": "stk500v2", "baud": None,
                                            "bitclock": None})
                flash_board(one, say)
    finally:
        isp.server.close()
    if args.dry_run:
        return 0
    # until the last module's boot slot has passed: its boot text then reached the PC
    boot = timing.boot_seconds(sim.modules, flashed_version(args))
    sim.run(boot)
    say(f"--- after {boot:.1f} s of simulated time")
    for module in sorted(sim.modules):
        text = sim.debug_read(module).decode("ascii", "replace").strip()
        say(f"module {module} control debug port: {text or '(silent)'}")
    pc = sim.pc_read().decode("ascii", "replace").strip()
    say(f"PC transceiver heard (one IR medium shared by all modules): {pc or '(nothing)'}")
    version = flashed_version(args)
    missing = not_booted(sorted(sim.modules), pc, version)
    if missing:
        raise FlashingError(
            f"flashed, but not every module booted FW={version}: the PC heard no "
            f"'{wire.TEXT_COMM_LISTENING}{wire.BOOT_ID_TAIL}nn{wire.BOOT_FW_TAIL}{version}' "
            f"from module {', '.join(missing)}")
    say(f"every module booted FW={version}: {', '.join(map(str, sorted(sim.modules)))}")
    return 0
