"""The small bank: reconfiguration pairs small enough for the exact mode.

The thesis' examples (shipped in ``planning/examples``) both ways, and seeded
random pairs of 6 to 10 modules from the benchmark's three families, with and
without the module at (0, 0) fixed to the base. The benchmark (``hexbot bench
planning --small``) and the tests measure the robust mode's optimality gap on
them against :mod:`hexbot.planning.exact`.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from hexbot.planning.config_io import load_configuration
from hexbot.planning.configuration import Configuration
from hexbot.planning.generate import blob_pair, holes_pair, scramble
from hexbot.planning.hexlattice import Cell

EXAMPLES = Path(__file__).resolve().parent / "examples"

#: (name, initial file, goal file) of the thesis' examples
THESIS_PAIRS = (
    ("Test_All_P01", "test_all_p01_initial.txt", "test_all_p01_goal.txt"),
    ("Test_All_P02 (P01 swapped)", "test_all_p01_goal.txt", "test_all_p01_initial.txt"),
    ("Test_All_S02", "test_all_s02_initial.txt", "test_all_s02_goal.txt"),
    ("Test_All_S02 reversed", "test_all_s02_goal.txt", "test_all_s02_initial.txt"),
    ("Test_VP (Fig. 4-24)", "test_vp_initial.txt", "test_vp_goal.txt"),
    ("chapter 4 (Figs. 4-13..4-17)", "chapter4_initial.toml", "chapter4_goal.toml"),
)


@dataclass(frozen=True)
class Case:
    name: str
    initial: Configuration
    goal: frozenset[Cell]
    fixed: Cell | None = None


def small_cases(random_pairs: int = 4) -> list[Case]:
    """The bank: thesis examples, then ``random_pairs`` blob and scramble pairs
    each of 6, 8 and 10 modules, and holes pairs of 8 and 10 (a hole needs
    six modules round it), free and with (0, 0) fixed."""
    cases = []
    for name, a, b in THESIS_PAIRS:
        initial = load_configuration(EXAMPLES / a)
        cases.append(Case(name, initial, load_configuration(EXAMPLES / b).cells))
    for n in (6, 8, 10):
        for seed in range(random_pairs):
            a, b = blob_pair(n, seed)
            pairs = {"blob": (a, b), "scramble": (a, scramble(a, 3 * n, seed))}
            if n >= 7:
                pairs["holes"] = holes_pair(n, seed)
            for family, (start, goal) in pairs.items():
                for fixed in (None, (0, 0)):
                    label = f"{family} {n} seed {seed}" + (" fixed" if fixed else "")
                    cases.append(Case(label, Configuration.from_cells(start), goal, fixed))
    return cases
