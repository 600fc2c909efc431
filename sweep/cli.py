"""``hexbot sweep``: run a sweep file on Dask, or report on its results.

    hexbot sweep docs/examples/sweep_locomotion.toml     # embedded cluster, a worker per core
    hexbot sweep SPEC.toml --scheduler tcp://10.0.0.5:8786  # the same on a Dask cluster
    hexbot sweep SPEC.toml --resume                      # only the tasks not in the table yet
    hexbot sweep report sweep_locomotion.results [--plot outcomes.png]

Exit status: 0 every task ok, 1 some task failed or was lost (the table
says which) or the sweep file is wrong, 2 a usage error, 4 the Dask
scheduler cannot be reached, has no worker, or was lost mid-sweep (the rows
taken back are kept), 130 interrupted (finished rows are kept; --resume
goes on).
"""

from __future__ import annotations

import argparse
import os
import sys
from pathlib import Path

from hexbot.cli_args import count, output_file
from hexbot.errors import CancelledError, HexBotError, UsageError
from hexbot.extras import require

REPORT = "report"
RUN_OPTIONS = ("out", "resume", "scheduler", "workers", "check", "no_progress")


def scheduler_address(text: str) -> str:
    """A Dask scheduler's address (``tcp://HOST:PORT``), checked before anything
    runs: a scheme Dask has no transport for or a missing port is a usage error."""
    from distributed.comm.addressing import parse_address, parse_host_port
    from distributed.comm.registry import backends

    try:
        scheme, location = parse_address(text)
        if scheme not in backends:
            known = ", ".join(sorted(backends))
            raise ValueError(f"unknown scheme {scheme!r} (Dask knows {known})")
        if scheme != "inproc":
            parse_host_port(location)
    except ValueError as exc:
        raise argparse.ArgumentTypeError(f"{text!r}: {exc}") from None
    return text


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.formatter_class = argparse.RawDescriptionHelpFormatter
    parser.epilog = __doc__.split("\n\n", 1)[1]
    parser.add_argument("target", metavar="SPEC.toml | report",
                        help="a sweep file to run, or the word 'report'")
    parser.add_argument("results", nargs="?", metavar="RESULTS",
                        help="report: the results folder of a sweep")
    run = parser.add_argument_group("running a sweep")
    run.add_argument("--out", type=Path, help="results folder (default: the file's 'output', "
                     "else SPEC-NAME.results in the current folder)")
    run.add_argument("--resume", action="store_true",
                     help="keep the folder's rows and run only the missing tasks")
    run.add_argument("--scheduler", metavar="tcp://HOST:8786", type=scheduler_address,
                     help="a running Dask scheduler (default: an embedded local cluster)")
    run.add_argument("--workers", type=count, metavar="N",
                     help="embedded cluster: worker processes (default: one per core)")
    run.add_argument("--check", action="store_true",
                     help="only check the sweep file and count its tasks")
    run.add_argument("--no-progress", action="store_true", help="no progress bar")
    rep = parser.add_argument_group("report")
    rep.add_argument("--plot", metavar="FILE.png", type=output_file,
                     help="also draw the outcomes per setting")


def run(args: argparse.Namespace) -> int:
    for module in ("pyarrow", "distributed"):
        require(module, "sweep", "hexbot sweep")
    if args.target == REPORT:
        return _report(args)
    if args.results or args.plot:
        raise UsageError("RESULTS and --plot belong to 'hexbot sweep report RESULTS'")
    return _run(args)


def _report(args: argparse.Namespace) -> int:
    from hexbot.sweep.report import plot, report

    given = [o for o in RUN_OPTIONS if getattr(args, o) not in (None, False)]
    if given:
        raise UsageError(f"--{given[0].replace('_', '-')} is for running a sweep, not report")
    if not args.results:
        raise UsageError("report needs the results folder: hexbot sweep report RESULTS")
    print(report(args.results))
    if args.plot:
        print(f"plot: {plot(args.results, args.plot)}", file=sys.stderr)
    return 0


def _run(args: argparse.Namespace) -> int:
    from hexbot.sweep.spec import load_spec

    if args.workers is not None and args.scheduler:  # the command line before the file
        raise UsageError("--workers is for the embedded cluster, not with --scheduler")
    spec = load_spec(args.target)  # every error of the file, before anything runs
    tasks = spec.tasks()
    out = args.out or spec.output or Path(f"{spec.path.stem}.results")
    _check_out(out, create=not args.check)
    if args.check:
        print(f"{spec.path}: kind {spec.kind.name}, {len(tasks)} tasks, results in {out}")
        return 0
    from hexbot.sweep.engine import connect, run_sweep
    from hexbot.sweep.progress import SweepProgress
    from hexbot.sweep.results import ResultStore

    with ResultStore(out, spec.kind.name, spec.param_names) as store:
        store.existing()  # a folder it refuses (damaged, another kind): before any cluster
        with connect(args.scheduler, args.workers,
                     on_note=lambda note: print(note, file=sys.stderr)) as client, \
                SweepProgress(spec.path.name, not args.no_progress) as bar:
            outcome = run_sweep(spec, client, store, resume=args.resume,
                                on_start=bar.on_start, on_result=bar.on_result)
    _write_junit(spec.kind.name, out)
    done = outcome.skipped + outcome.stored
    failed = outcome.failed + outcome.failed_before  # a --resume does not wash them out
    before = f" ({outcome.failed_before} stored before this run)" if outcome.failed_before else ""
    print(f"{out}: {done} of {outcome.total} tasks stored ({outcome.stored} by this run, "
          f"{outcome.seconds:.1f} s), {failed} failed{before}", file=sys.stderr)
    if outcome.interrupted:
        raise CancelledError(f"interrupted: {outcome.missing} tasks not run; "
                             f"add --resume to run only them")
    if outcome.lost:
        raise HexBotError(f"{outcome.lost} tasks lost ({outcome.lost_reason}); "
                          "--resume runs them again")
    if failed:
        print(f"{failed} tasks failed: hexbot sweep report {out}", file=sys.stderr)
        return 1
    return 0


def _check_out(out: Path, create: bool) -> None:
    """The results folder must be one this process can write, before anything
    runs; ``create`` makes it (a usage error when that fails)."""
    if out.exists() and not out.is_dir():
        raise UsageError(f"--out {out}: is a file, not a results folder")
    parent = out
    while not parent.exists():
        parent = parent.parent
    if not parent.is_dir():
        raise UsageError(f"--out {out}: {parent} is not a folder")
    if not os.access(parent, os.W_OK | os.X_OK):
        raise UsageError(f"--out {out}: cannot write in {parent}")
    if create:
        try:
            out.mkdir(parents=True, exist_ok=True)
        except OSError as exc:
            raise UsageError(f"--out {out}: cannot make the folder: "
                             f"{exc.strerror or exc}") from None


def _write_junit(kind: str, out: Path) -> None:
    if kind != "hil-script":
        return
    from hexbot.sweep.junit import write_junit
    from hexbot.sweep.results import read_table

    table = read_table(out)
    if table is not None:
        print(f"JUnit: {write_junit(table.to_pylist(), out)}", file=sys.stderr)

