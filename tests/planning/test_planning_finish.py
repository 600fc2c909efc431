"""The finish of a stalled flow: ends carried to far voids in legs, legal moves only."""

from collections import deque
from functools import partial

import numpy as np
import pytest
from test_planning_tidy import checked

from hexbot.bench.planning import make_pair
from hexbot.planning import _regroup, dig
from hexbot.planning import finish as finish_module
from hexbot.planning import journey as journey_module
from hexbot.planning.budget import NO_DEADLINE, Deadline, PlanningFailure
from hexbot.planning.configuration import Configuration
from hexbot.planning.finish import finish, move_in_area, outside_components, surface_path
from hexbot.planning.generate import random_blob
from hexbot.planning.journey import CROSSING_STATES, journey, journey_flow
from hexbot.planning.local import forward
from hexbot.planning.robust import _moves_from
from hexbot.planning.tracker import Tracker
from hexbot.planning.windows import disc
from hexbot.protocol.lattice import distance, neighbor


def _finished(cells, goal, fixed=None):
    """Run the finish, roll its rotations on a tracker, check them independently."""
    start = Configuration.from_cells(cells)
    tracker = Tracker(start, 10_000)
    hops = finish(set(cells), frozenset(goal), fixed, Deadline(60.0))
    tracker.roll(hops)
    checked(start, frozenset(tracker.occupied), list(tracker.moves), fixed=fixed)
    return tracker


def test_an_end_is_carried_twelve_cells_where_the_journey_finds_no_way():
    # a rough blob: the free end at (-1, -5) and the cell (4, 2) on the far side
    cells = set(random_blob(60, 20, 0.2))
    end, void = (-1, -5), (4, 2)
    goal = cells - {end} | {void}
    assert not journey(set(cells), end, void, None, CROSSING_STATES)
    tracker = _finished(cells, goal)
    assert tracker.occupied == goal
    assert len(tracker.moves) < 40  # 12 cells apart: legs, not a rebuild


def test_every_end_of_several_is_carried_and_the_bolted_module_stays():
    cells = set(random_blob(60, 29, 0.2))
    goal = cells - {(2, -4)} | {(-1, 8)}
    bolted = (0, 0)
    tracker = _finished(cells, goal, fixed=bolted)
    assert tracker.occupied == goal
    assert all(m.src != bolted for m in tracker.moves)


def test_an_expired_deadline_carries_nothing():
    cells = set(random_blob(60, 20, 0.2))
    goal = frozenset(cells - {(-1, -5)} | {(4, 2)})
    assert finish(set(cells), goal, None, Deadline(1e-9)) == []


def _arm_and_loop(loop: bool):
    """A module at (0, 0) with neighbours on sides 1 and 3 only (two arcs, side 2
    free between them); with ``loop`` the two are joined round the outside."""
    centre = (0, 0)
    a, b = neighbor(centre, 1), neighbor(centre, 3)
    cells = {centre, a, b}
    # a's and b's neighbours away from the centre, then a bridge between them
    far_a, far_b = neighbor(a, 1), neighbor(b, 3)
    cells |= {far_a, far_b}
    if loop:  # the shortest way from far_a to far_b that keeps off the centre's ring
        keep_off = disc(centre, 1)
        parent = {far_a: None}
        queue = deque([far_a])
        while far_b not in parent:
            cell = queue.popleft()
            for side in range(1, 7):
                n = neighbor(cell, side)
                if n not in parent and n not in keep_off and distance(n, centre) <= 4:
                    parent[n] = cell
                    queue.append(n)
        cell = far_b
        while cell is not None:
            cells.add(cell)
            cell = parent[cell]
    return cells, centre


def test_a_module_with_two_arcs_moves_only_when_the_outside_joins_them():
    for loop in (True, False):
        cells, centre = _arm_and_loop(loop)
        rolls = _moves_from(centre, cells, centre)
        assert rolls, "the centre has three free sides in a row"
        dst = rolls[0][2]
        area = disc(centre, 1) | {dst}
        target = (cells & area) - {centre} | {dst}
        hops = move_in_area(cells, area, target, None, limit=2)  # fewer than 2
        if loop:  # the arcs stay joined outside the area: one rotation
            assert hops is not None and len(hops) == 1 and hops[0][0] == centre
            assert len(set(outside_components(cells, area).values())) == 1
        else:  # the centre is a cut vertex: it may not leave
            assert hops is None
            assert len(set(outside_components(cells, area).values())) == 2
        # bolted, it never moves
        assert move_in_area(cells, area, target, centre, limit=2) is None


def test_the_surface_path_goes_to_the_nearest_cell_of_a_walled_in_void():
    # a ring of six around an empty cell: the hole touches no free cell outside
    centre = (10, 10)
    ring = {neighbor(centre, s) for s in range(1, 7)}
    cells = ring | {neighbor(neighbor(centre, 1), 1)}
    end = neighbor(neighbor(centre, 1), 1)
    path = surface_path(cells, end, centre)
    assert path and centre not in path
    assert all(c not in cells for c in path)


def test_long_legs_and_short_ones(monkeypatch):
    # legs of at most four cells still carry the end, in more legs
    cells = set(random_blob(60, 20, 0.2))
    goal = cells - {(-1, -5)} | {(4, 2)}
    monkeypatch.setattr(finish_module, "LEG", 4)
    monkeypatch.setattr(finish_module, "ACROSS", 4)
    tracker = _finished(cells, goal)
    assert tracker.occupied == goal


def test_a_stalled_flow_is_finished_and_its_plan_is_legal(monkeypatch):
    # blob 300 seed 1 with one park depth: the journey flow stalls without the
    # finish (test_planning_dig), and plans with it
    a, b = make_pair("blob", 300, 1)
    start, goal = Configuration.from_cells(a), frozenset(b)
    monkeypatch.setattr(dig, "PARK_DEPTHS", (10,))
    flow = partial(journey_flow, digs=True)
    calls = []
    original = finish_module.finish

    def counted(*args):
        calls.append(1)
        return original(*args)

    monkeypatch.setattr(finish_module, "finish", counted)  # the flow imports it when it runs
    plan = forward(start, goal, flow, 10**6, None, NO_DEADLINE, "local")
    assert calls, "the flow planned without the finish: this test no longer tests it"
    checked(start, goal, plan)
    monkeypatch.setattr(journey_module, "FINISHES", 0)
    with pytest.raises(PlanningFailure):
        forward(start, goal, flow, 10**6, None, NO_DEADLINE, "local")


def test_a_grid_of_the_wrong_size_is_refused_with_the_reason():
    ints = np.zeros(17 * 17, dtype=np.intc)
    with pytest.raises(ValueError, match="search_area: grid must be width \\* height bytes"):
        _regroup.search_area(9, 9, bytearray(10), ints, ints[:1], ints[:1],
                             np.full(81, -1, dtype=np.intc), 0, 10, 5)
    with pytest.raises(ValueError, match="one_pass: grid must be width \\* height bytes"):
        _regroup.one_pass(9, 9, bytearray(10), ints[:2], ints, 8, 30, 1, 5, 100, None)
    with pytest.raises(ValueError, match="improve_area: grid must be width \\* height bytes"):
        _regroup.improve_area(9, 9, bytearray(10), ints, ints[:1], ints[:1], None, 0, 10, 5)
    # the right grid, an area cell on its edge: refused too, by name
    with pytest.raises(ValueError, match="improve_area: area cell 0 is off the grid's inside"):
        _regroup.improve_area(9, 9, bytearray(81), ints, ints[:1], ints[:1], None, 0, 10, 5)
