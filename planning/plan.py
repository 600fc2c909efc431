"""A plan: time steps of moves, and how to replay and check it.

Planners return a :class:`Plan`; the CLI prints it, ``plan_to_commands``
turns it into firmware frames, and the plot and JSON views read it.
"""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass, field

from hexbot.planning.configuration import Configuration, is_connected
from hexbot.planning.hexlattice import Cell
from hexbot.planning.moves import Move, orientation_after, rule_of


@dataclass
class Step:
    moves: list[Move]


@dataclass
class Plan:
    mode: str
    initial: Configuration
    goal: frozenset[Cell]
    steps: list[Step] = field(default_factory=list)
    reached: bool = False
    reason: str = ""
    warnings: list[str] = field(default_factory=list)
    lower_bound: int | None = None  # fewest moves of any plan (bounds.move_lower_bound)
    fixed: Cell | None = None  # the module bolted to the base (robust and exact modes)
    method: str = ""  # robust mode: which method planned (direct, backwards, canonical)
    tried: list[str] = field(default_factory=list)  # robust mode: why the methods before it did not
    rejected: str = ""  # faithful modes: why the independent checker rejects the plan ("" if legal)

    @property
    def move_count(self) -> int:
        return sum(len(s.moves) for s in self.steps)

    @property
    def time_steps(self) -> int:
        return len(self.steps)

    def configurations(self) -> list[Configuration]:
        """The configuration before the first step and after each step."""
        configs = [self.initial]
        for step in self.steps:
            configs.append(apply_step(configs[-1], step))
        return configs

    @property
    def final(self) -> Configuration:
        return self.configurations()[-1]


def apply_move(config: Configuration, move: Move) -> Configuration:
    """Move one module; its orientation turns with the rotation."""
    module = config[move.src]
    if module.id != move.module:
        raise ValueError(f"module {move.module} is not at {move.src}")
    return config.moved(move.src, move.dst, orientation_after(module.orientation, move.direction))


def apply_step(config: Configuration, step: Step) -> Configuration:
    """Apply the moves of one time step in order (they run at the same time on the robot)."""
    for move in step.moves:
        config = apply_move(config, move)
    return config


def check_step(config: Configuration, step: Step) -> list[str]:
    """Problems of a time step under the robot's constraints (empty list = legal).

    Checked: each move follows Table 4-3 with everything that does not move
    in this step; no substrate moves in the step; no two moves share a
    cell; the modules that stay put are connected and hold every mover's
    substrate; the result is connected.
    """
    problems = []
    movers = {m.src for m in step.moves}
    if len(movers) < len(step.moves):  # one module, two moves: each alone may look legal
        twice = Counter(m.src for m in step.moves)
        problems += [f"the module at {src} is given {n} moves in one step"
                     for src, n in sorted(twice.items()) if n > 1]
    staying = config.cells - movers
    used: dict[Cell, int] = {}
    for move in step.moves:
        rule = rule_of(move)
        sub, goal, swept = rule.at(move.src)
        if move.src not in config or config[move.src].id != move.module:
            problems.append(f"module {move.module} is not at {move.src}")
            continue
        if goal != move.dst or sub != move.substrate:
            problems.append(f"module {move.module}: joint {move.joint} {move.direction} "
                            f"does not take {move.src} to {move.dst} over {move.substrate}")
        if sub not in staying:
            problems.append(f"module {move.module}: substrate {sub} is empty or moving")
        for cell in (goal, *swept):
            if cell in config.cells and cell not in movers:
                problems.append(f"module {move.module}: cell {cell} is occupied")
        for cell in (move.src, goal, *swept):
            if cell in used and used[cell] != move.module:
                problems.append(f"modules {used[cell]} and {move.module} both need cell {cell}")
            used[cell] = move.module
    if step.moves and not is_connected(staying):
        problems.append("the modules that stay put are not connected during the step")
    after = set(staying) | {m.dst for m in step.moves}
    if not is_connected(after):
        problems.append("the configuration is disconnected after the step")
    return problems
