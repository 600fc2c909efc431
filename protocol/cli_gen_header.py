"""``hexbot gen-header``: regenerate firmware/include/hexbot_codes.h and the
function table of docs/protocol.md from protocol/codes.py."""

import argparse
from pathlib import Path

from hexbot.protocol import docs_table, header


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--output", type=Path, default=header.HEADER_PATH,
                        help="where to write the header (default: %(default)s)")
    parser.add_argument("--check", action="store_true",
                        help="only check; exit 1 if the file is stale")


def run(args: argparse.Namespace) -> int:
    if args.check:
        stale = [p for p, s in ((args.output, header.is_stale(args.output)),
                                 (docs_table.DOC_PATH, docs_table.is_stale())) if s]
        for path in stale:
            print(f"{path} is stale: run `hexbot gen-header`")
        return 1 if stale else 0
    print(f"wrote {header.write(args.output)}")
    print(f"wrote {docs_table.write()}")
    return 0
