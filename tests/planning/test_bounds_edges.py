"""The lower bounds at their edges: the exact bound up to its limit inclusive,
and the nearest-cell fallback taking the stronger of its two sides."""

from hexbot.planning import bounds
from hexbot.planning.bounds import move_lower_bound

# cells to leave (1, 0) (2, 0); cells to fill (5, 0) (9, 0): each way round to the
# nearest cell, 4 + 3 = 7 from the cells to leave and 3 + 7 = 10 from the cells to
# fill; any assignment costs 11
CURRENT = frozenset({(0, 0), (1, 0), (2, 0)})
GOAL = frozenset({(0, 0), (5, 0), (9, 0)})


def _with_limit(limit):
    old = bounds.ASSIGNMENT_LIMIT
    try:
        bounds.ASSIGNMENT_LIMIT = limit
        return move_lower_bound(CURRENT, GOAL)
    finally:
        bounds.ASSIGNMENT_LIMIT = old


def test_the_assignment_bound_holds_up_to_its_limit_inclusive():
    assert _with_limit(2) == bounds.Bound(11, "assignment")  # two cells to leave


def test_the_nearest_fallback_takes_the_stronger_side():
    assert _with_limit(1) == bounds.Bound(10, "nearest")


def test_a_pair_of_different_sizes_has_no_move_bound_rather_than_an_error():
    # (the planners say why; plan_faithful asks for the bound before it does)
    assert move_lower_bound(CURRENT, frozenset({(0, 0), (1, 0)})) == bounds.Bound(0, "assignment")
    assert move_lower_bound(frozenset({(0, 0)}), CURRENT) == bounds.Bound(0, "assignment")
