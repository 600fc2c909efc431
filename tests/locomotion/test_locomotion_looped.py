"""`looped`: a stopper on a cycle leaves only when the cycle survives it,
counting only modules that cannot leave in the same round."""

import pytest

from hexbot.planning.locomotion import Engine, World, load_ruleset
from hexbot.planning.locomotion.engine import (
    LOOP_AHEAD,
    LOOP_ALWAYS,
    LOOP_NEVER,
    LOOP_UNLESS_SIMPLE,
    MODULE_BASE,
    Goal,
)
from hexbot.planning.locomotion.rules import rotate

SALVADOR = load_ruleset("salvador")

# A 3x3 ring round one hole, on a floor: R12 makes three of its modules
# openers at once (left, top, right), each on the same cycle.
RING = """
.sss.
.s.s.
.sss.
#####
"""


def _world(picture: str, turns: int) -> World:
    rows = picture.strip("\n").splitlines()
    cells = {(x, y): ch for y, row in enumerate(reversed(rows)) for x, ch in enumerate(row)}
    modules = [rotate(c, turns) for c, ch in cells.items() if ch == "s"]
    obstacles = [rotate(c, turns) for c, ch in cells.items() if ch == "#"]
    return World(obstacles, modules, SALVADOR.states, extend_axis=None)


@pytest.mark.parametrize("turns", [0, 1, 2, 3])
def test_of_three_openers_on_one_ring_only_one_leaves(turns):
    # Each opener alone is `looped`; counted together they are the cycle. With
    # the flow order only the one behind the others leaves; before, all three left in
    # round 2 and the ring fell apart (`disconnected`).
    engine = Engine(SALVADOR, _world(RING, turns), frame=turns)
    result = engine.run(1, Goal())
    assert result.rule_counts == {"R12 Change state to opener (empty hole)": 3}
    result = engine.run(2, Goal())
    assert result.rule_counts["R14 Opener: activation and convex transition"] == 1
    result = engine.run(12, Goal())
    assert result.violation is None, result.violation


def test_how_a_cycle_may_pass_each_state():
    engine = Engine(SALVADOR, _world(RING, 0))
    how = {s: int(engine.loop_through[MODULE_BASE + i]) for i, s in enumerate(SALVADOR.states)}
    # static never moves; a cork moves only when `simple`; an opener may leave
    # on a cycle (R13, R14, R17, R18: `simple or looped`); active is no carrier.
    assert how == {"static": LOOP_ALWAYS, "cork": LOOP_UNLESS_SIMPLE, "opener": LOOP_AHEAD,
                   "active": LOOP_NEVER}
