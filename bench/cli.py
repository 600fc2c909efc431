"""``hexbot bench NAME [OPTIONS]``: every benchmark of this package, by name.

A benchmark is a module here with ``add_arguments(parser)`` and
``run(args) -> int``, like the hexbot commands. It is imported only when it
runs, so a benchmark of a part that is broken or not built does not stop the
others.
"""

from __future__ import annotations

import argparse

from hexbot.cli import load_command

# name -> (module, one-line help)
BENCHMARKS: dict[str, tuple[str, str]] = {
    "sim": ("hexbot.bench.sim", "simulator throughput: real firmware, the whole Python loop"),
    "sim-core": ("hexbot.bench.sim_core", "the C core and scheduler against raw simavr (JSON)"),
    "isp": ("hexbot.bench.isp", "the STK500v2 engine and ATmega162 ISP model, no I/O"),
    "host": ("hexbot.bench.host", "capture writing, replay, console rendering (JSON)"),
    "planning": ("hexbot.bench.planning", "hex reconfiguration planners: time and moves"),
    "surface": ("hexbot.bench.surface",
                "where a module can roll: surface segments of the planning bench's shapes"),
    "pockets": ("hexbot.bench.pockets",
                "how much of a holes pair its holes' digs move (goal-peel closures)"),
    "locomotion": ("hexbot.bench.locomotion", "square-lattice locomotion engine (JSON)"),
    "ir-noise": ("hexbot.bench.ir_noise",
                 "wrong and lost commands on a noisy IR link, legacy vs MAVLink"),
    "traversal": ("hexbot.bench.traversal",
                  "layering traversal: FINDBRIDGECELLS on 1e3-1e5 perimeter cells, 1,000 modules"),
    "pyramid-search": (
        "hexbot.bench.pyramid_search",
        "random symmetric staircases against Table 2 of the locomotion thesis (JSON)",
    ),
    "sweep": ("hexbot.bench.sweep", "sweep engine on Dask: 2-vs-1 worker speed-up, per-task cost"),
}


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.formatter_class = argparse.RawDescriptionHelpFormatter
    parser.epilog = "benchmarks:\n" + "\n".join(
        f"  {name:16}{help_text}" for name, (_, help_text) in BENCHMARKS.items()
    )
    parser.add_argument("benchmark", choices=BENCHMARKS, metavar="NAME",
                        help="the benchmark to run (list below)")
    options = parser.add_argument("options", nargs=argparse.REMAINDER,
                                  help="its options: hexbot bench NAME --help")
    options.required = False  # else a missing NAME reads "required: NAME, options"


def run(args: argparse.Namespace) -> int:
    module_name, help_text = BENCHMARKS[args.benchmark]
    module, options = load_command(
        f"hexbot bench {args.benchmark}", module_name, help_text, args.options
    )
    return int(module.run(options) or 0)
