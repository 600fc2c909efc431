"""``hexbot codes``: the function-code table, as text or JSON."""

import argparse
import json

from hexbot.protocol.codes import CODES


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--all", action="store_true", help="include unused and reserved codes")
    parser.add_argument("--json", action="store_true", help="one JSON list")


def run(args: argparse.Namespace) -> int:
    rows = [fn for fn in CODES.values() if args.all or fn.executable]
    if args.json:
        print(json.dumps([
            {"code": fn.code, "name": fn.name, "board": fn.board.value,
             "status": fn.status.value, "comment": fn.comment,
             "args": [{"name": a.name, "meaning": a.meaning, "min": a.lo, "max": a.hi,
                       "unit": a.unit} for a in fn.args]}
            for fn in rows], indent=1))
        return 0
    for fn in rows:
        print(f"{fn.code:3d}  {fn.board.value:<7} {fn.signature():<42} {fn.comment}")
    return 0
