"""``hexbot plan INITIAL GOAL``: plan a reconfiguration and print its moves and commands.

Exit status 0 when the plan reaches the goal; 1 (reason on stderr) when it
does not, when the independent checker rejects a faithful plan (the thesis'
loops check nothing across the moves of a step), or when an input file is
invalid; 2 for a usage error, found before any planning.

Plans have no size or id limit. Firmware commands address modules by their
DIP-switch id through the legacy Select frame (1..``MAX_SELECT_ID``): for a
configuration with larger ids the moves are printed without commands (``"commands": null`` and a
``"commands_omitted"`` reason in ``--json``), and ``--execute`` refuses.
"""

from __future__ import annotations

import argparse
import json
import sys
from collections.abc import Iterable, Iterator
from typing import Any, TextIO

from hexbot.cli_args import count, image_file
from hexbot.errors import HexBotError, ScenarioError, UsageError
from hexbot.host.endpoints import add_port_arguments
from hexbot.host.workflows import Verify
from hexbot.planning.bounds import NEVER, PlanBounds, plan_bounds
from hexbot.planning.budget import DEFAULT_BUDGET
from hexbot.planning.commands import MoveCommands, command_json, plan_to_commands
from hexbot.planning.config_io import load_configuration
from hexbot.planning.configuration import Configuration, is_connected
from hexbot.planning.hexlattice import Cell
from hexbot.planning.moves import Move
from hexbot.planning.plan import Plan
from hexbot.protocol.wire import MAX_SELECT_ID

MODES = ("faithful-serial", "faithful-parallel", "robust", "exact")
#: What ``--plot`` and ``--render`` write (matplotlib picks the format by the suffix).
PLOT_SUFFIXES, RENDER_SUFFIXES = (".png",), (".gif",)


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("initial", help="initial configuration (0/1 grid text or .toml)")
    parser.add_argument("goal", help="goal configuration (0/1 grid text or .toml)")
    parser.add_argument("--mode", choices=MODES, default="robust",
                        help="planner (default: robust)")
    parser.add_argument("--json", action="store_true", help="print one JSON object")
    parser.add_argument("--summary", action="store_true",
                        help="leave the steps out: the summary line, the notes and warnings "
                             "(--json: the object without \"steps\"); a plan of 10,000 "
                             "modules has millions of moves")
    parser.add_argument("--plot", metavar="FILE.png", type=image_file(PLOT_SUFFIXES),
                        help="draw one panel per time step (plot extra)")
    parser.add_argument("--render", metavar="FILE.gif", type=image_file(RENDER_SUFFIXES),
                        help="animate the plan: a frame per time step, grid, counter, legend "
                             "(plot extra)")
    parser.add_argument("--style", choices=("combined", "single"), default="combined",
                        help="firmware commands: combined CW/CCW (67/68, default) or "
                             "single-role MCW..SCCW (21-24)")
    parser.add_argument("--serial", action="store_true",
                        help="robust and exact modes: one move per time step")
    parser.add_argument("--fixed", metavar="X,Y", type=_cell,
                        help="robust and exact modes: the module fixed to the base (never moves)")
    parser.add_argument("--budget", type=_seconds, default=DEFAULT_BUDGET, metavar="SECONDS",
                        help="robust and exact modes: give up (exit 1, with the reason) "
                             f"after this many seconds (default {DEFAULT_BUDGET:g})")
    parser.add_argument("--max-steps", type=count, default=200,
                        help="faithful modes: give up after this many time steps (default 200)")
    hil = parser.add_argument_group(
        "execution (on the embedded simulator by default, or on --port: real modules or a pty)")
    hil.add_argument("--execute", action="store_true",
                     help="localize the cluster, check it is INITIAL, plan from it and send "
                          "the plan's rotations through the port, verifying every move")
    hil.add_argument("--reference", type=int, metavar="ID",
                     help="the module that becomes (0,0) and never moves (default: the "
                          "scenario's base module, else the lowest id)")
    hil.add_argument("--verify", choices=[v.value for v in Verify], default="auto",
                     help="how each move is checked: plant (simulator only), localize (any "
                          "port), status (quick, blind to refused mechanics); default auto: "
                          "plant on the embedded simulator, localize elsewhere")
    add_port_arguments(parser, debug=False)


def _cell(text: str) -> Cell:
    try:
        x, y = (int(v) for v in text.replace("(", "").replace(")", "").split(","))
    except ValueError as exc:
        raise argparse.ArgumentTypeError(f"expected X,Y (two integers), got {text!r}") from exc
    return (x, y)


def _seconds(text: str) -> float:
    try:
        value = float(text)
    except ValueError as exc:
        raise argparse.ArgumentTypeError(f"expected a number of seconds, got {text!r}") from exc
    if not value > 0:
        raise argparse.ArgumentTypeError(f"the budget must be positive, got {text!r}")
    return value


def unaddressable(plan: Plan) -> str:
    """Why the plan's modules cannot be addressed by firmware commands ("" if they can)."""
    high = [m.id for m in plan.initial.values() if not 1 <= m.id <= MAX_SELECT_ID]
    if not high:
        return ""
    return (f"{len(high)} module id(s) outside 1..{MAX_SELECT_ID} (e.g. {max(high)}): "
            "the link cannot address them, so no firmware commands are given")


def make_plan(args: argparse.Namespace, initial: Configuration | None = None) -> Plan:
    if initial is None:
        initial = load_configuration(args.initial)
    goal = load_configuration(args.goal).cells
    if args.mode == "robust":
        from hexbot.host.cli_progress import stages
        from hexbot.planning.robust import plan_robust

        # on a terminal, the stage the planner is at (minutes at 10,000 modules)
        what = f"planning {len(initial)} modules"
        with stages(what) as shown:
            return plan_robust(initial, goal, parallel=not args.serial, fixed=args.fixed,
                               budget=args.budget,
                               progress=lambda stage: shown.describe(f"{what}: {stage}"))
    if args.mode == "exact":
        from hexbot.planning.exact import plan_exact

        return plan_exact(initial, goal, fixed=args.fixed, budget=args.budget,
                          parallel=not args.serial)
    from hexbot.planning.checker import check_plan
    from hexbot.planning.thesis.planner import FaithfulOptions, plan_faithful

    plan = plan_faithful(initial, goal, parallel=args.mode == "faithful-parallel",
                         options=FaithfulOptions(max_steps=args.max_steps))
    if plan.reached:  # the thesis' loops check no constraint across the moves of a step
        report = check_plan(initial, plan.goal, plan.steps)
        plan.rejected = "" if report.ok else report.problem
    return plan


def plan_failure(plan: Plan) -> tuple[str, str] | None:
    """Why the plan is no success (what, why), or None: its goal is not
    reached, or the independent checker rejects it (exit status 1 either way)."""
    if not plan.reached:
        return "goal not reached", plan.reason
    if plan.rejected:
        return "the independent checker rejects the plan", plan.rejected
    return None


def draw(plan: Plan, args: argparse.Namespace) -> None:
    """``--plot`` and ``--render`` (their names were checked before planning;
    a write that fails now, a full disk say, is a one-line error)."""
    for option, path in (("--plot", args.plot), ("--render", args.render)):
        if not path:
            continue
        from hexbot.planning import plot

        try:
            (plot.plot_plan if option == "--plot" else plot.render_plan)(plan, path)
        except OSError as exc:
            raise HexBotError(f"{option}: cannot write {path}: {exc.strerror or exc}") from None


def plan_json(plan: Plan, style: str = "combined") -> dict[str, Any]:
    """The ``--json`` object (``commands`` null when the ids cannot be addressed)."""
    omitted = unaddressable(plan)
    return {**_json_head(plan, omitted), "steps": list(_steps_json(plan, style, omitted))}


def write_plan_json(plan: Plan, style: str, out: TextIO,
                    extra: dict[str, Any] | None = None, steps: bool = True) -> None:
    """The text of ``json.dumps({**plan_json(plan, style), **extra})`` and a
    newline, written a step at a time: a strip plan of 10,000 modules has five
    million moves, and their dicts all at once needed gigabytes. Without
    ``steps``, the object without its ``"steps"``."""
    omitted = unaddressable(plan)
    if not steps:
        out.write(json.dumps({**_json_head(plan, omitted), **(extra or {})}) + "\n")
        return
    out.write(json.dumps(_json_head(plan, omitted))[:-1] + ', "steps": [')
    for k, step in enumerate(_steps_json(plan, style, omitted)):
        out.write((", " if k else "") + json.dumps(step))
    out.write("]" + (", " + json.dumps(extra)[1:-1] if extra else "") + "}\n")


def _json_head(plan: Plan, omitted: str) -> dict[str, Any]:
    extra: dict[str, Any] = {"commands_omitted": omitted} if omitted else {}
    if plan.tried:
        extra["tried"] = plan.tried
    if plan.reason:
        extra["reason"] = plan.reason
    if plan.warnings:
        extra["warnings"] = plan.warnings
    if plan.rejected:
        extra["rejected"] = plan.rejected
    bounds = pair_bounds(plan)
    if bounds is not None:
        extra["bounds"] = bounds.as_json()
    return {**extra, "mode": plan.mode, "method": plan.method, "reached": plan.reached,
            "moves": plan.move_count, "time_steps": plan.time_steps}


def pair_bounds(plan: Plan) -> PlanBounds | None:
    """The lower bounds of the plan's pair (None when the pair is not one: the
    module counts differ, the goal is empty, the fixed module is not in both,
    a configuration is not one piece; or when no plan can exist: a module
    must leave that never can)."""
    fixed, cells = plan.fixed, plan.initial.cells
    if (not plan.goal or len(cells) != len(plan.goal)
            or (fixed is not None and (fixed not in cells or fixed not in plan.goal))
            or not is_connected(cells) or not is_connected(plan.goal)):
        return None
    bounds = plan_bounds(cells, plan.goal, fixed)
    return bounds if bounds.time_steps.value < NEVER else None


def plan_summary(plan: Plan) -> str:
    """One line: the method, whether the goal is reached, the plan's size and
    what no plan of this pair can beat (docs/planning.md, *Bounds*)."""
    outcome = "NOT reached" if not plan.reached else (
        "reached by an ILLEGAL plan" if plan.rejected else "reached")
    line = (f"mode {plan.mode}{f' ({plan.method})' if plan.method else ''}: "
            f"goal {outcome}, "
            f"{plan.time_steps} time step(s), {plan.move_count} move(s)")
    bounds = pair_bounds(plan)
    if bounds is None:
        return line
    return line + (f" (lower bounds: {_bound(bounds.moves, 'move(s)')}, "
                   f"{_bound(bounds.time_steps, 'time step(s)')}; "
                   f"plain bottleneck {_bound(bounds.bottleneck, 'step(s)')})")


def _bound(bound, unit: str) -> str:
    return f"{bound.value} {unit}" + (" (nearest cells)" if bound.kind == "nearest" else "")


def _steps_json(plan: Plan, style: str, omitted: str) -> Iterator[dict[str, Any]]:
    """The ``steps`` of the ``--json`` object, one at a time."""
    if omitted:  # no commands: the steps as they are (any size)
        for step in plan.steps:
            yield {"moves": [_move_json(move, None) for move in step.moves]}
        return
    for step in plan_to_commands(plan, style):  # type: ignore[arg-type]
        yield {"moves": [_move_json(mc.move, [command_json(c) for c in mc.commands])
                         for mc in step]}


def _move_json(move: Move, commands: list | None) -> dict[str, Any]:
    return {"module": move.module, "from": list(move.src), "to": list(move.dst),
            "joint": move.joint, "direction": move.direction,
            "substrate": list(move.substrate), "commands": commands}


def _move_commands(plan: Plan, style: str, omitted: str) -> Iterable[list[MoveCommands]]:
    """Per step, per move: its commands (none when the ids cannot be addressed)."""
    if omitted:
        return ([MoveCommands(m, ()) for m in step.moves] for step in plan.steps)
    return plan_to_commands(plan, style)  # type: ignore[arg-type]


def plan_text(plan: Plan, style: str = "combined", steps: bool = True) -> str:
    return "\n".join(_text_lines(plan, style, steps))


def _text_lines(plan: Plan, style: str, steps: bool = True) -> Iterator[str]:
    """The lines of the text report, one at a time (a plan may have millions of
    moves); without ``steps``, all but the steps."""
    yield plan_summary(plan)
    if plan.rejected:
        yield f"note: the independent checker rejects the plan: {plan.rejected}"
    for reason in plan.tried:
        yield f"note: tried first, no plan: {reason}"
    omitted = unaddressable(plan)
    if omitted:
        yield f"note: {omitted}"
    for t, step in enumerate(_move_commands(plan, style, omitted) if steps else (), start=1):
        yield f"step {t}:"
        for mc in step:
            m = mc.move
            yield (f"  module {m.module}: {m.src} -> {m.dst}  joint {m.joint} {m.direction}, "
                   f"substrate {m.substrate} (module {m.substrate_module})")
            if mc.commands:
                yield "      " + " ".join(str(c) for c in mc.commands)
    for warning in plan.warnings:
        yield f"warning: {warning}"


def run(args: argparse.Namespace) -> int:
    if args.fixed is not None and args.mode not in ("robust", "exact"):
        raise UsageError(f"--fixed is for the robust and exact modes: the thesis' planner "
                         f"({args.mode}) bolts no module")
    if args.plot or args.render:
        from hexbot.planning import plot  # noqa: F401  (no plot extra: say so before planning)
    if args.execute:
        return run_execute(args)
    plan = make_plan(args)
    if args.json:
        write_plan_json(plan, args.style, sys.stdout, steps=not args.summary)
    else:
        for line in _text_lines(plan, args.style, steps=not args.summary):
            print(line)
    draw(plan, args)
    failure = plan_failure(plan)
    if failure:
        print(f"hexbot plan: {failure[0]}: {failure[1]}", file=sys.stderr)
        return 1
    return 0


def run_execute(args: argparse.Namespace) -> int:
    """Localize the cluster behind the port, plan from it, execute the plan."""
    from hexbot.host.cli_common import session
    from hexbot.host.workflows import localize, reference_problem
    from hexbot.planning.config_io import names_modules
    from hexbot.planning.execute import (
        check_plan_fits,
        configuration_of,
        default_reference,
        execute,
    )

    if args.style != "combined":
        raise UsageError("--execute sends each move as the console does (SetRole, Select, "
                         "then the combined CW/CCW frame): --style single only prints")
    if args.reference is not None and reference_problem(args.reference):
        raise UsageError(f"--reference: {reference_problem(args.reference)}")
    port = str(getattr(args, "port", None) or "")
    if args.verify == "plant" and port and not port.startswith("hexbot-sim"):
        raise UsageError("--verify plant needs the embedded simulator (--scenario or a "
                         "hexbot-sim:// port); use localize or status on a real port")
    given = load_configuration(args.initial)
    wanted = given.cells
    if len(wanted) > MAX_SELECT_ID:
        raise ScenarioError(
            f"{args.initial}: {len(wanted)} modules, but the link addresses module ids "
            f"1..{MAX_SELECT_ID} only: plan it without --execute")
    with session(args) as sess:
        reference = args.reference if args.reference is not None else default_reference(sess)
        poses = localize(sess, reference)
        initial = configuration_of(poses)
        where = f"scenario {args.scenario}" if args.scenario else "the cluster"
        if wanted != initial.cells:
            raise ScenarioError(
                f"{args.initial} does not describe {where}: cells "
                f"{sorted(wanted)} vs localized {sorted(initial.cells)}")
        ids = {c: m.id for c, m in given.items()}
        if names_modules(args.initial) and ids != {c: m.id for c, m in initial.items()}:
            cell = next(c for c in sorted(ids) if ids[c] != initial[c].id)
            raise ScenarioError(
                f"{args.initial} does not describe {where}: module {ids[cell]} at {cell}, "
                f"localized module {initial[cell].id} there")
        if args.mode in ("robust", "exact"):
            args.fixed = poses[reference].cell  # localization needs the reference to stay
        plan = make_plan(args, initial)
        failure = plan_failure(plan)
        if failure:
            if args.json:
                write_plan_json(plan, args.style, sys.stdout, {"execution": None},
                                steps=not args.summary)
            else:
                print(plan_text(plan, args.style, steps=not args.summary))
            draw(plan, args)
            print(f"hexbot plan: {failure[0]}, nothing executed: {failure[1]}",
                  file=sys.stderr)
            return 1
        check_plan_fits(plan, sess, reference)  # before a word is printed or sent
        if not args.json:
            print(plan_text(plan, args.style, steps=not args.summary))
            print(f"executing through {sess.host.channel().settings.url}: move by move, "
                  f"verify {args.verify}")
        report = execute(plan, sess, reference, verify=Verify(args.verify), poses=poses,
                         log=None if args.json else print)
    if args.json:
        write_plan_json(plan, args.style, sys.stdout, {"execution": report.as_json()},
                        steps=not args.summary)
    else:
        print(report.line(plan.move_count))
    draw(plan, args)  # the plan that was executed (whole, even if the run stopped early)
    if not report.reached:
        print(f"hexbot plan: execution stopped: {report.failure}", file=sys.stderr)
        return report.exit_status or 1
    return 0
