"""``HexAll_P`` / ``HexAll_S`` and the loops of ``Test_All_*``, kept faithful.

Per time step, on the current configuration C:

1. layer 2: electrons, voids, mobile electrons, potential voids; with no
   potential void or no mobile electron the thesis stops ("There is no more
   possible motion");
2. layer 3: ``HexVP`` pairs potential voids with mobile electrons;
3. layer 4: ``MDP_NRL`` recommends each paired electron's next cell;
4. layer 5: ``HexActuate`` finds the rotation (pivot joint, substrate).

The parallel planner moves every pair of the step (all planned on the same
C, as ``HexAll_P`` does); the serial planner moves the first pair only.
The loop stops when the goal is reached, when a step moves nothing (the
thesis loops forever there), when a move would land on an occupied cell
(``Hexmove`` would silently merge two modules) or after ``max_steps``.

Unlike the robot, the faithful planner checks no constraint across moves;
it records what it breaks (disconnection, moving substrate) as warnings.
"""

from __future__ import annotations

from dataclasses import dataclass

from hexbot.planning.bounds import move_lower_bound
from hexbot.planning.configuration import Configuration
from hexbot.planning.hexlattice import Cell
from hexbot.planning.moves import Move
from hexbot.planning.plan import Plan, Step, apply_move, check_step
from hexbot.planning.thesis.actuation import hex_actuate
from hexbot.planning.thesis.layers import find_ve, mobile_electrons, potential_voids
from hexbot.planning.thesis.mdp import next_location
from hexbot.planning.thesis.voidprop import pair_voids


@dataclass(frozen=True)
class Motion:
    """One row of ``HexAll``'s ``S``: electron, next recommended location, void,
    and the actuation found for it (None when layer 5 found no rotation)."""

    electron: Cell
    next: Cell
    void: Cell
    move: Move | None


@dataclass(frozen=True)
class FaithfulOptions:
    exclude_assigned: bool = True  # HexVP fix, see voidprop
    action_limit: int | None = None  # MDP_VI's truncated max, see mdp
    max_steps: int = 200


def hexall(
    config: Configuration, goal: frozenset[Cell], parallel: bool, options: FaithfulOptions
) -> tuple[list[Motion], str]:
    """One call of ``HexAll_P`` (parallel) or ``HexAll_S``: (motions, reason if none)."""
    current = config.cells
    _, electrons = find_ve(current, goal)
    mobile = mobile_electrons(electrons, current)
    voids = potential_voids(current, goal, mobile)
    if not voids or not mobile:
        return [], "There is no more possible motion (no potential void or no mobile electron)"
    pairs = pair_voids(current, goal, options.exclude_assigned)
    if not pairs:
        return [], "void propagation paired no potential void with a mobile electron"
    if not parallel:
        pairs = pairs[:1]
    motions = []
    for pair in pairs:
        nxt = next_location(
            current, goal, pair.electron, pair.void, action_limit=options.action_limit
        )
        found = hex_actuate(pair.electron, nxt, current)
        move = None
        if found is not None:
            rule, sub = found
            move = Move(
                module=config[pair.electron].id,
                src=pair.electron,
                dst=nxt,
                joint=rule.joint,
                direction=rule.direction,
                substrate=sub,
                substrate_module=config[sub].id,
            )
        motions.append(Motion(pair.electron, nxt, pair.void, move))
    return motions, ""


def plan_faithful(
    initial: Configuration,
    goal: frozenset[Cell],
    parallel: bool,
    options: FaithfulOptions | None = None,
) -> Plan:
    """Run the thesis' test loop (``Test_All_P01`` / ``Test_All_S01``)."""
    options = options or FaithfulOptions()
    mode = "faithful-parallel" if parallel else "faithful-serial"
    plan = Plan(mode=mode, initial=initial, goal=frozenset(goal))
    plan.lower_bound = move_lower_bound(initial.cells, plan.goal).value
    if len(initial) != len(goal):
        plan.reason = f"the goal has {len(goal)} cells for {len(initial)} modules"
        return plan
    config = initial
    while config.cells != plan.goal:
        if len(plan.steps) >= options.max_steps:
            plan.reason = f"goal not reached after {options.max_steps} time steps"
            return plan
        motions, reason = hexall(config, plan.goal, parallel, options)
        moves: list[Move] = []
        nxt = config
        for motion in motions:
            if motion.move is None:
                # Test_All_*: "There is no more possible actuation"; break
                reason = (
                    f"layer 5 found no rotation from {motion.electron} to {motion.next} "
                    f"(electron bound for {motion.void})"
                )
                break
            if motion.move.dst in nxt.cells or motion.move.src not in nxt.cells:
                plan.reason = (
                    f"time step {len(plan.steps) + 1}: module {motion.move.module} cannot move "
                    f"from {motion.move.src} to {motion.move.dst}: the cell is taken "
                    "(Hexmove would merge two modules)"
                )
                if moves:
                    plan.steps.append(Step(moves))
                return plan
            moves.append(motion.move)
            nxt = apply_move(nxt, motion.move)
        if not moves:
            plan.reason = f"stalled at time step {len(plan.steps) + 1}: {reason}"
            return plan
        step = Step(moves)
        for problem in check_step(config, step):
            plan.warnings.append(f"time step {len(plan.steps) + 1}: {problem}")
        plan.steps.append(step)
        config = nxt
    plan.reached = True
    return plan
