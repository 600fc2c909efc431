"""The exact mode at its edges: the bolted module stays, the size limit is inclusive."""

from hexbot.planning.checker import check_plan
from hexbot.planning.configuration import Configuration
from hexbot.planning.exact import EXACT_LIMIT, plan_exact
from hexbot.planning.generate import random_blob

# four modules whose fewest moves (4) move the module at (1, 0); bolted, it takes 5
INITIAL = Configuration.from_cells([(0, 0), (0, 1), (1, 0), (1, 1)])
GOAL = frozenset({(-1, 0), (0, 0), (1, -1), (1, 0)})
FIXED = (1, 0)


def test_the_fixed_module_never_moves_in_an_exact_plan():
    free = plan_exact(INITIAL, GOAL, parallel=False)
    assert free.reached and free.move_count == 4
    assert any(m.module == INITIAL[FIXED].id for s in free.steps for m in s.moves)
    bolted = plan_exact(INITIAL, GOAL, fixed=FIXED, parallel=False)
    assert bolted.reached and bolted.move_count == 5
    assert all(m.module != INITIAL[FIXED].id for s in bolted.steps for m in s.moves)
    assert check_plan(INITIAL, GOAL, bolted.steps, fixed=FIXED).ok


def test_exactly_exact_limit_modules_are_accepted():
    cells = random_blob(EXACT_LIMIT, 0, 0.8)
    plan = plan_exact(Configuration.from_cells(cells), cells)
    assert plan.reached and plan.reason == "" and plan.move_count == 0
