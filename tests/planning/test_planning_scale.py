"""The pieces that make 10,000-module plans fit: strip hops, hop repair, the
dependency-graph schedule and its time budget, the checker's local test."""

import random

import pytest

from hexbot.planning import schedule as scheduling
from hexbot.planning.budget import Deadline
from hexbot.planning.canonical import (
    _hop,
    _hops_from,
    _hops_without,
    replay,
    strip_shape,
    via_strip,
)
from hexbot.planning.checker import check_plan, pieces, still_one_piece
from hexbot.planning.configuration import Configuration, articulation_points, is_connected
from hexbot.planning.generate import random_blob
from hexbot.planning.hexlattice import neighbors
from hexbot.planning.moves import Move
from hexbot.planning.schedule import (
    bottom_levels,
    critical_chain,
    pack_consecutive,
    schedule,
    schedule_parallel,
    stays_connected,
)


@pytest.mark.parametrize("seed", range(6))
def test_hops_repaired_after_a_module_leaves_match_a_new_search(seed):
    rng = random.Random(seed)
    cells = set(random_blob(150, seed, compact=rng.random()))
    root = max(cells)
    hops = _hops_from(cells, [root])
    for _ in range(60):
        cuts = articulation_points(cells)
        free = sorted(c for c in cells if c != root and c not in cuts)
        gone = rng.choice(free)
        cells.discard(gone)
        grown = _hops_without(cells, hops, gone)
        fresh = _hops_from(cells, [root])
        assert hops == fresh
        assert all(fresh[c] > 0 for c in grown)


@pytest.mark.parametrize("direction", range(6))
def test_a_strip_hops_one_cell_in_any_direction_with_legal_moves(direction):
    count, width, start = 60, 4, (0, 0)
    end = neighbors(start)[direction]
    strip = Configuration.from_cells(strip_shape(start, count, width))
    moves = _hop(strip, start, end, width, Deadline(None))
    assert moves is not None
    goal = strip_shape(end, count, width)
    assert replay(strip, moves).cells == goal
    report = check_plan(strip, goal, schedule_parallel(strip, moves))
    assert report.ok, report.problem


def strip_pair(n=300, seed=0):
    a, b = random_blob(n, 2 * seed, 0.8), random_blob(n, 2 * seed + 1, 0.8)
    start = Configuration.from_cells(a)
    return start, b, via_strip(start, b)


def test_the_schedule_runs_strip_moves_in_parallel_and_the_checker_accepts_it():
    start, goal, serial = strip_pair()
    steps = schedule_parallel(start, serial)
    assert steps is not None
    assert sum(len(s.moves) for s in steps) == len(serial)
    assert len(steps) < len(serial) / 5  # a strip route is a train of modules
    report = check_plan(start, goal, steps)
    assert report.ok, report.problem


def test_a_schedule_out_of_time_runs_one_move_per_step_and_says_so():
    start, goal, serial = strip_pair(100, 1)
    steps, warning = schedule(start, serial, Deadline(0.0))
    assert "time budget" in warning
    assert [s.moves for s in steps] == [[m] for m in serial]
    assert check_plan(start, goal, steps).ok


def test_a_jammed_list_schedule_runs_in_pieces_far_shorter_than_serial_packing(monkeypatch):
    # The journey flow's own serial plan, without its relays: moves that the
    # list schedule runs early leave every ready move a cut vertex.
    from hexbot.bench.planning import make_pair
    from hexbot.planning import journey
    from hexbot.planning.local import FLOWS, forward

    monkeypatch.setattr(journey, "relay", lambda *args: None)
    a, b = make_pair("blob", 100, 2)
    start = Configuration.from_cells(a)
    serial = forward(start, b, FLOWS[0][1], 10**6, None, Deadline(60), "local")
    assert schedule_parallel(start, serial) is None  # the list schedule jams
    steps, warning = schedule(start, serial)
    assert not warning
    assert sum(len(s.moves) for s in steps) == len(serial)
    report = check_plan(start, b, steps)
    assert report.ok, report.problem
    # 338 steps against 704 when a jam packed the serial order (session 13)
    assert 2 * len(steps) < len(pack_consecutive(start, serial))


def test_two_rolls_sweeping_one_empty_cell_keep_no_order_but_never_share_a_step(monkeypatch):
    # Module a rolls before module b in the serial plan and both sweep the
    # empty cell (-2, 1): neither changes what the other needs, so b, whose
    # chain is longer, goes first and a rolls beside b's second move. When
    # swept cells counted as changed, a held b back: three steps.
    start = Configuration.from_cells(frozenset(
        [(-1, 0), (-1, 1), (0, -1), (0, 0), (0, 1), (1, -2), (1, -1), (1, 0)]))
    ids = {cell: module.id for cell, module in start.items()}

    def move(src, dst, joint, direction, substrate, who=None):
        return Move(ids[who or src], src, dst, joint, direction, substrate, ids[substrate])

    a = move((-1, 0), (-1, -1), 5, "CCW", (0, -1))
    b = move((-1, 1), (-1, 2), 3, "CW", (0, 1))
    b_again = move((-1, 2), (0, 2), 4, "CW", (0, 1), who=(-1, 1))
    assert set(a.swept()) & set(b.swept())  # the cell both need empty
    serial = [a, b, b_again]
    steps = schedule_parallel(start, serial)
    assert [step.moves for step in steps] == [[b], [a, b_again]]
    goal = frozenset(start.cells - {(-1, 0), (-1, 1)} | {(-1, -1), (0, 2)})
    assert check_plan(start, goal, steps).ok
    assert list(bottom_levels(serial)) == [1, 2, 1]
    assert critical_chain(serial) == (2, [2, 1])
    # a plan too long for the fine schedule gets the coarse one: in order
    monkeypatch.setattr(scheduling, "FINE_MOVES", 2)
    steps = schedule_parallel(start, serial)
    assert [step.moves for step in steps] == [[a], [b], [b_again]]
    assert check_plan(start, goal, steps).ok


@pytest.mark.parametrize("seed", range(3))
def test_no_schedule_beats_the_longest_chain_and_both_passes_agree_on_it(seed):
    start, goal, serial = strip_pair(100, seed)
    length, chain = critical_chain(serial)
    assert length == max(bottom_levels(serial)) == len(chain)
    assert chain == sorted(chain, reverse=True)  # a chain runs forward in the plan
    steps = schedule_parallel(start, serial)
    assert len(steps) >= length
    assert check_plan(start, goal, steps).ok


@pytest.mark.parametrize("seed", range(20))
def test_the_schedules_local_cut_test_agrees_with_a_search(seed):
    rng = random.Random(seed)
    cells = set(random_blob(rng.randint(5, 120), seed, compact=rng.random()))
    for cell in sorted(cells):
        assert stays_connected(cells, cell) == is_connected(cells - {cell}), cell


def test_the_checker_catches_movers_far_apart_that_split_a_ring_together():
    # a ring of 60 cells: removing any one cell keeps it whole, two opposite ones split it
    ring = {(x, 0) for x in range(30)} | {(29, 1)} | {(x, 2) for x in range(28, -2, -1)} \
        | {(-1, 1)}
    assert pieces(ring) == 1
    assert still_one_piece(ring, {(10, 0)})
    assert not still_one_piece(ring, {(10, 0), (10, 2)})
    assert still_one_piece(ring, {(10, 0), (11, 0)})  # one cluster, the rest is a path


@pytest.mark.parametrize(("seed", "n", "width"), [(0, 79, 4), (5, 109, 5), (6, 103, 5)])
def test_the_lead_in_line_lets_the_strip_gather_where_a_corridor_stopped_it(
        seed, n, width, monkeypatch):
    import hexbot.planning.canonical as canonical

    rng = random.Random(seed)
    rng.randint(30, 120)  # the same draws as the search that found these blobs
    cells = random_blob(n, seed, compact=rng.random())
    config = Configuration.from_cells(cells)
    moves = canonical.to_strip(config, width)
    anchor = canonical.anchor_of(cells)
    assert replay(config, moves).cells == strip_shape(anchor, n, width)
    monkeypatch.setattr(canonical, "LEAD", 0)  # the strip right beside the anchor
    with pytest.raises(canonical.PlanningFailure, match="no module can reach strip cell"):
        canonical.to_strip(config, width)
