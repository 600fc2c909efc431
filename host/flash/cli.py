"""``hexbot flash``: program a module board's ATmega162 through avrdude.

One board:  hexbot flash --board control --port /dev/ttyUSB0 [--fuses]
Simulator:  hexbot flash --all --scenario pair

Steps, each reported in plain words: check the image, read the device
(signature, fuses, lock), refuse anything that is not an ATmega162 or fuse
values that would lock the board out (unless --force), then erase, write and
verify flash, and the fuses when asked.
"""

from __future__ import annotations

import argparse
import re
import shlex
from pathlib import Path

from hexbot.cli_args import count, port_name
from hexbot.errors import FlashingError, Terminated, UsageError
from hexbot.host.flash.avrdude import Avrdude
from hexbot.host.flash.fuses import TABLE_3_6, FuseSet, check_fuses, fuse_notes
from hexbot.host.flash.ihex import read_hex
from hexbot.protocol import image_mark, wire
from hexbot.protocol.header import SCHEMA_HASH

FLASH_BYTES = wire.FLASH_BYTES
BOARDS = ("comm", "control")
REPO_ROOT = Path(__file__).resolve().parents[2]
DEFAULT_BUILD = REPO_ROOT / "firmware" / "build"
PROGRAMMER = "stk500v2"
#: options of one board that --all sets itself (every simulated board has an
#: STK500v2 pty and its image is <build dir>/<board>.hex)
NOT_WITH_ALL = ("image", "programmer", "baud", "bitclock", "port", "board")
#: options that only --all reads
ONLY_WITH_ALL = ("scenario", "firmware_version")


def _byte(text: str) -> int:
    try:
        value = int(text, 0)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a number (use 0x62 or 98)") from None
    if not 0 <= value <= 0xFF:
        raise argparse.ArgumentTypeError(f"{text} does not fit in one byte")
    return value


def firmware_version(text: str) -> str:
    """A version for ``make VERSION=``: it goes into a C string and the boot
    text (`` FW=...``), which the flasher reads back up to the first space."""
    if not re.fullmatch(r"[0-9A-Za-z._+~-]+", text):
        raise argparse.ArgumentTypeError(
            f"{text!r}: use letters, digits and . _ + ~ - (no spaces or quotes)")
    return text


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--board", choices=BOARDS, help="which board of the module")
    parser.add_argument("--image", type=Path,
                        help="Intel HEX image (default: firmware/build/<board>.hex)")
    parser.add_argument("--port", type=port_name,
                        help="programmer port, e.g. /dev/ttyUSB0 or /dev/pts/7")
    parser.add_argument("--programmer", help=f"avrdude -c (default {PROGRAMMER})")
    parser.add_argument("--baud", type=count,
                        help="avrdude -b, serial speed to the programmer (at least 1)")
    parser.add_argument("--bitclock", help="avrdude -B, ISP clock period/frequency")
    parser.add_argument("--avrdude", default="avrdude", help="avrdude executable")
    parser.add_argument("--fuses", action="store_true",
                        help=f"also write the fuses (Table 3-6: low 0x{wire.FUSE_LOW:02X}, "
                             f"high 0x{wire.FUSE_HIGH:02X}, ext 0x{wire.FUSE_EXTENDED:02X})")
    for name in ("lfuse", "hfuse", "efuse", "lock"):
        parser.add_argument(f"--{name}", type=_byte, metavar="BYTE",
                            help=f"{name} value to write instead of Table 3-6's (implies --fuses)")
    parser.add_argument("--verify", action=argparse.BooleanOptionalAction, default=True,
                        help="read back and compare everything written (default on)")
    parser.add_argument("--force", action="store_true",
                        help="write fuse/lock values even if they would lock the board out, "
                        "and an image built for another board or from another protocol schema")
    parser.add_argument("--all", action="store_true",
                        help="rebuild the firmware and reflash every board of a simulated cluster")
    parser.add_argument("--scenario", help="simulator scenario for --all")
    parser.add_argument("--firmware-version", type=firmware_version,
                        help="with --all: make -C firmware VERSION=...")
    parser.add_argument("--build-dir", type=Path, default=DEFAULT_BUILD,
                        help="where the images are (and, with --all, are built); "
                        "default firmware/build")
    parser.add_argument("--dry-run", action="store_true",
                        help="print the avrdude commands instead of running them")


def requested_fuses(args: argparse.Namespace) -> FuseSet | None:
    overrides = {n: getattr(args, n) for n in ("lfuse", "hfuse", "efuse", "lock")
                 if getattr(args, n) is not None}
    if not args.fuses and not overrides:
        return None
    return FuseSet(**{**TABLE_3_6.__dict__, **overrides})


def guard_fuses(fuses: FuseSet, force: bool, say=print) -> None:
    """Refuse dangerous values unless forced; say harmless oddities."""
    problems = check_fuses(fuses)
    for note in fuse_notes(fuses):
        say(f"note: {note}")
    if not problems:
        return
    lines = "\n".join(f"  - {p.text}" for p in problems)
    if not force:
        raise FlashingError(
            f"refusing to write fuses {fuses}:\n{lines}\n"
            "nothing was written; give --force if you really mean it")
    say(f"WARNING: writing dangerous fuses because of --force:\n{lines}")


def check_device(signature: bytes, part_guess: str | None, port: str) -> None:
    if signature == wire.SIGNATURE:
        return
    sig = signature.hex(" ").upper()
    if signature in (b"\x00\x00\x00", b"\xff\xff\xff"):
        raise FlashingError(
            f"no device answered on {port} (signature {sig}): check the ISP cable, "
            "the programming jumper and the module's power")
    what = f" ({part_guess})" if part_guess else ""
    raise FlashingError(
        f"the device on {port} has signature {sig}{what}, not an ATmega162 "
        f"({wire.SIGNATURE.hex(' ').upper()}); "
        "refusing to flash it, nothing was written")


def guard_image(image: Path, mark: image_mark.ImageMark | None, board: str | None,
                force: bool, say) -> None:
    """Refuse an image built for another board or from another protocol than
    this host's (its modules would not understand the host), unless forced."""
    # no board only without a mark (the mark names one), and then nothing to check
    problems = [p for p in image_mark.mismatch(mark, (board,) if board else (), SCHEMA_HASH) if p]
    if not problems:
        return
    if force:
        for problem in problems:
            say(f"warning: {image.name}: {problem} (--force: flashing it anyway)")
        return
    raise FlashingError(f"{image}: {'; '.join(problems)}; refusing to flash it, nothing was "
                        "written (--force flashes it anyway)")


def flash_board(args: argparse.Namespace, say=print) -> int:
    if not args.board and not args.image:
        raise UsageError("give --board comm|control (or --image FILE), or --all --scenario")
    if not args.port:
        raise UsageError("give --port: the programmer's serial port")
    image = args.image or Path(getattr(args, "build_dir", DEFAULT_BUILD)) / f"{args.board}.hex"
    if not image.exists():
        raise FlashingError(f"{image}: no such image (build it: make -C firmware)")
    hexfile = read_hex(image, limit=FLASH_BYTES)
    mark = image_mark.read_mark(hexfile.to_bytes())
    board = args.board or (mark.board if mark else None)
    label = f"{board} board" if board else "board"
    what = f"{mark.describe()}, " if mark else ""
    say(f"image {image}: {what}{hexfile.used} bytes "
        f"({100 * hexfile.size / FLASH_BYTES:.0f} % of the {FLASH_BYTES // 1024} KiB flash)")
    guard_image(image, mark, board, args.force, say)
    fuses = requested_fuses(args)
    if fuses is not None:
        guard_fuses(fuses, args.force, say)  # before touching the device at all
    avrdude = Avrdude(args.port, args.programmer or PROGRAMMER, args.avrdude, args.baud,
                      args.bitclock)
    if args.dry_run:
        base = avrdude.base_command()
        say(shlex.join([*base, "-F", "-U", "signature:r:SIG:r", "-U", "lfuse:r:LFUSE:r",
                        "-U", "hfuse:r:HFUSE:r", "-U", "efuse:r:EFUSE:r", "-U", "lock:r:LOCK:r"]))
        say(shlex.join([*base, *avrdude.write_args(image, fuses, args.verify)]))
        return 0
    say(f"reading the device on {args.port} through {avrdude.programmer} ...")
    device = avrdude.read_device()
    check_device(device.signature, device.part_guess, args.port)
    say(f"found an ATmega162 (signature {device.signature_text}); fuses {device.fuses}")
    if fuses is None and device.fuses != TABLE_3_6:
        say("note: the device's fuses differ from Table 3-6; add --fuses to set them")
    try:  # from the line on: a Ctrl-C after it is told as one during the write
        say(f"erasing and writing {hexfile.used} bytes of flash"
            + (f", then fuses {fuses}" if fuses else "") + " ...")
        report = avrdude.write(image, fuses, args.verify)
    except (KeyboardInterrupt, Terminated):  # the chip was erased: say so before the last line
        say(f"stopped while writing: the {label} on {args.port} may hold a part of "
            f"{image.name} or nothing; flash it again")
        raise
    done = f"{report.written.get('flash', 0)} bytes of flash written"
    if args.verify:
        done += f", {report.verified.get('flash', 0)} verified"
    say(done)
    say(f"done: {label} on {args.port} programmed with {image.name}")
    return 0


def run(args: argparse.Namespace) -> int:
    if args.all:
        from hexbot.host.flash.cluster import flash_all

        given = [f"--{name}" for name in NOT_WITH_ALL if getattr(args, name, None) is not None]
        if given:
            raise UsageError(f"{', '.join(given)} cannot be used with --all (it flashes every "
                             "simulated board with <build dir>/<board>.hex through its "
                             "STK500v2 pty)")
        if not args.scenario:
            raise UsageError("--all needs --scenario NAME (a simulated cluster)")
        return flash_all(args)
    given = [f"--{name.replace('_', '-')}" for name in ONLY_WITH_ALL
             if getattr(args, name, None) is not None]
    if given:
        raise UsageError(f"{', '.join(given)} only go with --all (one board is flashed "
                         "with the image given, as it is)")
    return flash_board(args)
