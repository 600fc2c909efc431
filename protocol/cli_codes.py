"""``hexbot codes [NAME...]``: the function-code table, as text or JSON;
with names, each function in full (arguments' ranges and meaning, the
reply and how long it may take), all read from ``protocol/``."""

import argparse
import difflib
import json

from hexbot.errors import FrameError
from hexbot.protocol import timing
from hexbot.protocol.codes import BY_NAME, CODES, Arg, FunctionCode, Status, lookup


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("names", nargs="*", metavar="NAME",
                        help="functions by name or code (e.g. CW, 1): each in full")
    parser.add_argument("--all", action="store_true", help="include unused and reserved codes")
    parser.add_argument("--json", action="store_true", help="one JSON list")


def find(name: str) -> FunctionCode:
    """A function by name or code, or a FrameError naming the close names."""
    try:
        return lookup(name)
    except KeyError:
        close = difflib.get_close_matches(name.lower(), BY_NAME, n=3, cutoff=0.6)
        hint = f" (did you mean {', '.join(BY_NAME[c].name for c in close)}?)" if close else ""
        raise FrameError(f"no function {name!r}{hint}; `hexbot codes` lists them") from None


def arg_range(arg: Arg) -> str:
    return f"{arg.lo}..{arg.hi}" + (" x 10 ms" if arg.unit == "tick" else "")


def describe(fn: FunctionCode) -> list[str]:
    """The text of ``hexbot codes NAME``."""
    tag = {Status.USED: "Table 3-7", Status.EXTENSION: "an extension of Table 3-7"}
    lines = [f"{fn.code} {fn.signature()}",
             f"  board      {fn.board.value}",
             f"  status     {fn.status.value}" + (f" ({tag[fn.status]})" if fn.status in tag
                                                  else ""),
             f"  does       {fn.comment}"]
    if fn.args:
        lines.append("  arguments")
        width = max(len(arg_range(a)) for a in fn.args)
        lines += [f"    {a.name:<4} {arg_range(a):<{width}}  {a.meaning}" for a in fn.args]
    else:
        lines.append("  arguments  none")
    if fn.status is Status.UNUSED:
        lines.append(f"  reply      ACK N (not used): the module refuses code {fn.code}")
    elif fn.executable:
        bound = timing.reply_timeout_s(fn.code, 1)
        kind = "STA" if fn.name == "Status" else f"ACK {fn.code}"
        worst = " (arguments at the top of their ranges)" if fn.args else ""
        lines.append(f"  reply      {kind} from each addressed module; one module's within "
                     f"{bound:.1f} s at most{worst}")
    return lines


def run(args: argparse.Namespace) -> int:
    if args.names:
        rows = [find(name) for name in args.names]  # every name checked before printing
    else:
        rows = [fn for fn in CODES.values() if args.all or fn.executable]
    if args.json:
        print(json.dumps([
            {"code": fn.code, "name": fn.name, "board": fn.board.value,
             "status": fn.status.value, "comment": fn.comment,
             "args": [{"name": a.name, "meaning": a.meaning, "min": a.lo, "max": a.hi,
                       "unit": a.unit} for a in fn.args]}
            for fn in rows], indent=1))
        return 0
    if args.names:
        print("\n\n".join("\n".join(describe(fn)) for fn in rows))
        return 0
    for fn in rows:
        print(f"{fn.code:3d}  {fn.board.value:<7} {fn.signature():<42} {fn.comment}")
    return 0
