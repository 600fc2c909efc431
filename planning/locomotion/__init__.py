"""Distributed locomotion on the square lattice: a synchronous rule engine and
the rule sets of Salvador (2019, sliding cubes) and Otero (2016, caterpillar).

    from hexbot.planning.locomotion import load_ruleset, flat_scenario, simulate
    result = simulate(load_ruleset("salvador-free"), flat_scenario(20), until_advance=5)
"""

from hexbot.planning.locomotion.engine import Engine, Goal, RunResult, Violation, World
from hexbot.planning.locomotion.rulefile import load, loads
from hexbot.planning.locomotion.scenarios import (
    Scenario,
    flat_scenario,
    load_ruleset,
    load_scenario,
    ruleset_names,
    scenario_names,
    simulate,
)

__all__ = [
    "Engine",
    "Goal",
    "RunResult",
    "Scenario",
    "Violation",
    "World",
    "flat_scenario",
    "load",
    "load_ruleset",
    "load_scenario",
    "loads",
    "ruleset_names",
    "scenario_names",
    "simulate",
]
