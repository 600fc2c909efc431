"""``hexbot gen-header``: write firmware/include/hexbot_codes.h."""

import argparse
from pathlib import Path

from hexbot.protocol import header


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--output", type=Path, default=header.HEADER_PATH,
                        help="where to write the header (default: %(default)s)")
    parser.add_argument("--check", action="store_true",
                        help="only check; exit 1 if the file is stale")


def run(args: argparse.Namespace) -> int:
    if args.check:
        if header.is_stale(args.output):
            print(f"{args.output} is stale: run `hexbot gen-header`")
            return 1
        print(f"{args.output} is up to date")
        return 0
    print(f"wrote {header.write(args.output)}")
    return 0
