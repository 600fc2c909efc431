"""Serve one simulated ATmega162 behind an STK500v2 on a pty.

    python -m hexbot.hil_sim.isp [--signature 1e950f] [--hfuse 0xd9]

prints one JSON line ``{"isp": "/dev/pts/N"}`` and serves until interrupted;
point avrdude at the path: ``avrdude -c stk500v2 -P /dev/pts/N -p m162``.
"""

from __future__ import annotations

import argparse
import json
import signal
import sys

from hexbot.hil_sim.isp import Atmega162Isp, Atmega162Memory, IspPtyServer, MemoryBackend
from hexbot.hil_sim.isp.stk500v2 import Stk500v2Programmer
from hexbot.protocol.wire import SIGNATURE


def _byte(text: str) -> int:
    value = int(text, 0)
    if not 0 <= value <= 0xFF:
        raise argparse.ArgumentTypeError(f"{text} does not fit in a byte")
    return value


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m hexbot.hil_sim.isp", description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--signature", default=SIGNATURE.hex(),
                        help="device signature, 6 hex digits (default: ATmega162)")
    parser.add_argument("--lfuse", type=_byte)
    parser.add_argument("--hfuse", type=_byte)
    parser.add_argument("--efuse", type=_byte)
    args = parser.parse_args(argv)
    try:
        signature = bytes.fromhex(args.signature)
        memory = Atmega162Memory(signature=signature)
    except ValueError as exc:
        parser.error(f"--signature {args.signature}: {exc}")
    for name in ("lfuse", "hfuse", "efuse"):
        if getattr(args, name) is not None:
            setattr(memory, name, getattr(args, name))
    memory.efuse |= 0xE1
    with IspPtyServer() as server:
        path = server.add("isp", Stk500v2Programmer(Atmega162Isp(MemoryBackend(memory))))
        print(json.dumps({"isp": path}), flush=True)
        signal.signal(signal.SIGTERM, lambda *_: sys.exit(0))
        try:
            while True:
                server.poll(0.5)
        except KeyboardInterrupt:
            pass
    return 0


if __name__ == "__main__":
    sys.exit(main())
