"""``hexbot gen-header``: regenerate the firmware headers
(firmware/include/hexbot_codes.h, hexbot_pins.h) and the generated tables of
docs/protocol.md and docs/firmware.md from protocol/."""

import argparse

from hexbot.protocol import generated


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--check", action="store_true",
                        help="only check; exit 1 if a generated file is stale")


def run(args: argparse.Namespace) -> int:
    if args.check:
        stale = generated.stale()
        for item in stale:
            where = f" ({item.block})" if item.block else ""
            print(f"{item.path}{where} is stale: run `hexbot gen-header`")
        left = generated.leftovers()
        for path in left:
            print(f"{path} is no longer generated: run `hexbot gen-header` (it removes it)")
        return 1 if stale or left else 0
    for path in generated.leftovers():
        print(f"removed {path}")
    for path in dict.fromkeys(generated.write_all()):
        print(f"wrote {path}")
    return 0
