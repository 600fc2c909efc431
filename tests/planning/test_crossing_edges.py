"""The crossing search (planning/_crossing.c) at its edges (mutation audit, session 37).

The random blobs of test_planning_crossing.py compare the C search with the
Python one (crossing_reference.py) on many crossings, but never on these:
a fixed module inside the window, two equally good ends of one rotation, an
end on the first or last cell of the window, a state budget just big enough,
and the module's own guards (a disc it does not have, rules not set, the
table limits). Each case is a straight row of modules with a traveller on
top, small enough to follow by hand; the guards that change the module's
tables run in a fresh interpreter, so this process keeps the planner's.
"""

import json
import subprocess
import sys
import textwrap

import pytest

from hexbot.planning import _crossing
from hexbot.planning.checker import check_plan
from hexbot.planning.configuration import Configuration
from hexbot.planning.journey import _DISCS, crossing
from hexbot.planning.plan import Step
from hexbot.planning.tracker import Tracker
from tests.planning.crossing_reference import reference_crossing

# a row of eleven modules on the x axis, the traveller on top of (0, 0) and (1, 0)
ROW = frozenset((x, 0) for x in range(-5, 6))
TRAVELLER = (0, 1)


def legal(occupied, hops, fixed=None):
    """The hops replayed one move a step under the independent checker."""
    start = Configuration.from_cells(occupied)
    tracker = Tracker(start, len(hops))
    tracker.roll(hops)
    end = set(occupied)
    for src, dst, _, _ in hops:
        end.discard(src)
        end.add(dst)
    report = check_plan(start, frozenset(end), [Step([m]) for m in tracker.moves], fixed)
    return report.ok, report.problem


def test_of_two_nearer_cells_the_first_rotation_found_is_taken():
    # the traveller rolls right or left in one rotation, both ends nearer: the
    # search stops at the first state it accepts (right: the _OPEN12 order)
    occupied = ROW | {TRAVELLER}
    steps = {(1, 1): 0, (-1, 1): 0}
    found = crossing(occupied, TRAVELLER, 2, steps, None, 300)
    assert found == reference_crossing(occupied, TRAVELLER, 2, steps, None, 300)
    hops, arrived = found
    assert arrived == (1, 1) and [(src, dst) for src, dst, _, _ in hops] == [((0, 1), (1, 1))]


@pytest.mark.parametrize("radius", [2, 3])
@pytest.mark.parametrize("side", [1, -1])
def test_a_crossing_may_end_on_the_first_or_last_cell_of_its_window(radius, side):
    # the window's cells in sorted order run from (-r, 0) to (r, 0) around the
    # traveller: the lowest and the highest bit of a state
    offset = (side * radius, 0)
    assert offset == _DISCS[radius].cells[0 if side < 0 else _DISCS[radius].size - 1]
    end = (side * radius, 1)
    occupied = ROW | {TRAVELLER}
    steps = {end: 0}  # the only cell nearer the target
    found = crossing(occupied, TRAVELLER, radius, steps, None, 300)
    assert found == reference_crossing(occupied, TRAVELLER, radius, steps, None, 300)
    hops, arrived = found
    assert arrived == end and len(hops) == radius  # one roll a cell along the row
    assert legal(occupied, hops) == (True, "")


def test_a_fixed_module_beside_the_traveller_is_climbed_over_not_moved():
    # (1, 1) sits between the traveller and its end (3, 1); free, it steps on
    # to (2, 1) and the traveller follows (3 rotations); fixed, the traveller
    # climbs over it (4 rotations) and it never moves, not even first
    occupied = ROW | {TRAVELLER, (1, 1)}
    steps = {(3, 1): 0}
    free = crossing(occupied, TRAVELLER, 3, steps, None, 4000)
    assert [src for src, _, _, _ in free[0]] == [(1, 1), (0, 1), (2, 1)]
    found = crossing(occupied, TRAVELLER, 3, steps, (1, 1), 4000)
    assert found == reference_crossing(occupied, TRAVELLER, 3, steps, (1, 1), 4000)
    hops, arrived = found
    assert arrived == (3, 1) and len(hops) == 4
    assert all(src != (1, 1) for src, _, _, _ in hops)
    assert legal(occupied, hops, fixed=(1, 1)) == (True, "")


@pytest.mark.parametrize("fixed, needed", [(None, 16), ((1, 1), 8)])
def test_a_crossing_is_found_with_exactly_the_states_it_needs(fixed, needed):
    # the search stops when it holds max_states states: the crossing above
    # needs 16 of them free (8 with (1, 1) fixed, fewer moves to try); one
    # fewer finds nothing, in both searches
    occupied = ROW | {TRAVELLER, (1, 1)}
    steps = {(3, 1): 0}
    for states in (needed - 1, needed):
        ours = crossing(occupied, TRAVELLER, 3, steps, fixed, states)
        assert ours == reference_crossing(occupied, TRAVELLER, 3, steps, fixed, states)
        assert (ours is not None) == (states == needed), states


@pytest.mark.parametrize("disc", [-1, len(_DISCS)])
def test_the_c_search_refuses_a_disc_it_was_not_given(disc):
    with pytest.raises(ValueError, match="bad arguments"):
        _crossing.search(disc, 1, 0, 0, 0, 0, 100)


_REFUSED = """
import json


def refused(call, *args):
    try:
        call(*args)
    except ValueError as error:
        return str(error)
    return None
"""


def _fresh(script: str):
    """Run ``script`` in a new interpreter (its own _crossing tables), with
    ``refused(call, *args)`` (the ValueError's text, or None) and ``json``
    at hand, and return the JSON it prints last."""
    done = subprocess.run([sys.executable, "-c", _REFUSED + textwrap.dedent(script)],
                          capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr[-2000:]
    return json.loads(done.stdout.strip().splitlines()[-1])


def test_the_c_search_refuses_to_run_before_its_rules_are_set():
    # a disc of one cell is there, the rules are not
    result = _fresh("""
    from hexbot.planning import _crossing
    assert _crossing.add_disc(1, 1, 0, [0] * 6, [0] * 12, [0], [-1], 1) == 0
    print(json.dumps(refused(_crossing.search, 0, 1, 0, 0, 0, 0, 100)))
    """)
    assert "tables not set up" in result


def test_add_disc_takes_64_cells_and_16_goals_at_most():
    result = _fresh("""
    from hexbot.planning import _crossing

    def add(size, goals, center=0):
        return refused(_crossing.add_disc, size, size, center, [0] * size * 6,
                       [0] * size * 12, [0] * size, [-1] * size * goals, goals)

    print(json.dumps({"64/16": add(64, 16), "65": add(65, 1), "17 goals": add(1, 17),
                      "centre 1 of 1": add(1, 1, center=1), "centre 0 of 1": add(1, 1)}))
    """)
    assert result["64/16"] is None and result["centre 0 of 1"] is None
    assert all("disc too large" in result[k] for k in ("65", "17 goals", "centre 1 of 1"))


def test_set_rules_refuses_tables_beyond_its_limits_and_keeps_the_old_ones():
    # the planner's own tables with one mask given 16 rotations (the most) or
    # 17, or a goal code of 16 (codes are 0..15); a refused table changes
    # nothing: the same crossing is found after it as before
    result = _fresh("""
    from hexbot.planning import _crossing
    from hexbot.planning.journey import _GOALS, crossing
    from hexbot.planning.robust import _OPEN12
    from hexbot.planning.windows import _LEAVABLE

    ours = [[_GOALS.index(goal) for _, _, goal in options] for options in _OPEN12]
    row = {(x, 0) for x in range(-5, 6)} | {(0, 1)}

    def cross():
        return repr(crossing(row, (0, 1), 2, {(2, 1): 0}, None, 300))

    before = cross()
    out = {"17": refused(_crossing.set_rules, _LEAVABLE, ours[:-1] + [[0] * 17]),
           "code 16": refused(_crossing.set_rules, _LEAVABLE, ours[:-1] + [[16]]),
           "no leaving": refused(_crossing.set_rules, [0] * 64, ours[:-1]),
           "no rotations": refused(_crossing.set_rules, _LEAVABLE, [[]] * 4095 + [[16]])}
    out["kept"] = cross() == before and before != "None"
    out["16"] = refused(_crossing.set_rules, _LEAVABLE, ours[:-1] + [[15] * 16])
    print(json.dumps(out))
    """)
    assert "too many rotations" in result["17"]
    assert "out of range" in result["code 16"] and "out of range" in result["no rotations"]
    assert "4096 masks" in result["no leaving"]
    assert result["kept"] is True
    assert result["16"] is None
