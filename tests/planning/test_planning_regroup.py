"""Runs of moves in a small area re-planned together, checked by the independent checker."""

import pytest
from test_planning_tidy import _Countdown, _random_walk, checked

from hexbot.bench.planning import make_pair
from hexbot.planning import regroup as regroup_module
from hexbot.planning.canonical import replay
from hexbot.planning.checker import check_plan
from hexbot.planning.configuration import Configuration
from hexbot.planning.generate import random_blob
from hexbot.planning.moves import Move
from hexbot.planning.regroup import regroup
from hexbot.planning.robust import _moves_from, is_cut, plan_robust
from hexbot.planning.tidy import shorten


def _move(where: dict, cell, rule, sub, dst) -> Move:
    move = Move(where[cell], cell, dst, rule.joint, rule.direction, sub, where[sub])
    where[dst] = where.pop(cell)
    return move


def _roll(cells: set, start, target, most: int = 4) -> list | None:
    """The fewest rotations (at most ``most``) taking the module at ``start``
    to ``target``, the others fixed: [(cell, rule, substrate, goal), ...]."""
    paths = {start: []}
    frontier = [start]
    for _ in range(most):
        reached = []
        for cell in frontier:
            for rule, sub, dst in _moves_from(cell, cells, start):
                if dst not in paths:
                    paths[dst] = paths[cell] + [(cell, rule, sub, dst)]
                    if dst == target:
                        return paths[dst]
                    reached.append(dst)
        frontier = reached
    return None


def _swap_places(cells: set) -> tuple[Configuration, list[Move]]:
    """Module A steps aside from cell a, its neighbour B takes a, and A rolls
    into B's old cell: rotations that change nothing in the cells taken.
    Tidy keeps them (with A kept home, B cannot enter a)."""
    start = Configuration.from_cells(cells)
    for a in sorted(cells):
        if is_cut(set(cells), a):
            continue
        for rule, sub, aside in _moves_from(a, set(cells), a):
            after = set(cells) - {a} | {aside}
            for b in sorted(after):
                if b in (aside, sub) or is_cut(after, b):
                    continue
                for rule_b, sub_b, dst_b in _moves_from(b, after, b):
                    if dst_b != a:
                        continue
                    later = after - {b} | {a}
                    back = _roll(later, aside, b) if not is_cut(later, aside) else None
                    if back:
                        where = {c: m.id for c, m in start.items()}
                        plan = [_move(where, a, rule, sub, aside),
                                _move(where, b, rule_b, sub_b, a)]
                        plan += [_move(where, *hop) for hop in back]
                        return start, plan
    raise AssertionError("no such swap in this configuration")


def test_a_swap_of_places_that_changes_nothing_goes_and_tidy_alone_keeps_it():
    start, plan = _swap_places(set(random_blob(12, 3)))
    checked(start, start.cells, plan)
    assert replay(start, plan).cells == start.cells
    assert len(shorten(start, plan)) == len(plan)
    assert regroup(start, plan) == []


def test_the_modules_of_a_replaced_run_are_the_ones_standing_there():
    start, plan = _swap_places(set(random_blob(12, 3)))
    # one more move after the swap: it names the module the replay leaves in
    # its cell, whatever module the plan had sent there
    where = {c: m.id for c, m in replay(start, plan).items()}
    cells = set(where)
    cell = next(c for c in sorted(cells) if not is_cut(cells, c) and _moves_from(c, cells, c))
    plan.append(_move(where, cell, *_moves_from(cell, cells, cell)[0]))
    ours = regroup(start, plan)
    assert len(ours) == 1 and ours[0].src == cell
    checked(start, replay(start, plan).cells, ours)


@pytest.mark.parametrize("seed", range(6))
def test_random_walks_get_shorter_than_tidy_alone_and_stay_legal(seed):
    # random rotations of any module that is no cut vertex, over blobs big
    # enough that a run's area is not the whole configuration
    start, plan = _random_walk(20, 400, seed)
    goal = replay(start, plan).cells
    tidy = shorten(start, plan)
    ours = regroup(start, tidy)
    checked(start, goal, ours)
    assert len(ours) < len(tidy)


def test_the_backwards_pass_finds_what_the_forward_one_left_and_keeps_the_ids_right():
    # backwards, a run may end with other modules where the plan started
    # them: the ids are replayed from the start (the checker checks them)
    saved = 0
    for seed in range(3):
        start, plan = _random_walk(20, 400, seed)
        forward = shorten(start, regroup_module.one_pass(start, shorten(start, plan)))
        ours = regroup_module.backwards_pass(start, forward)
        checked(start, replay(start, plan).cells, ours)
        assert len(ours) <= len(forward)
        saved += len(forward) - len(ours)
    assert saved > 0


def test_the_bolted_module_never_moves():
    start, plan = _random_walk(24, 400, 7)
    moved = {m.src for m in plan}
    bolted = next(c for c in sorted(start.cells) if c not in moved)
    goal = replay(start, plan).cells
    ours = regroup(start, shorten(start, plan), fixed=bolted)
    assert ours and all(m.src != bolted for m in ours)
    checked(start, goal, ours, fixed=bolted)


def test_a_deadline_that_has_come_changes_nothing():
    start, plan = _random_walk(20, 200, 1)
    assert regroup_module.one_pass(start, plan, deadline=_Countdown(0)) == plan


def test_bad_moves_are_refused_with_a_reason():
    start, plan = _random_walk(20, 10, 2)
    bad = plan[0]
    wrong_joint = Move(bad.module, bad.src, bad.dst, 9, bad.direction, bad.substrate,
                       bad.substrate_module)
    with pytest.raises(ValueError, match="no rotation about joint 9"):
        regroup(start, [wrong_joint, *plan[1:]])
    x, y = bad.substrate
    elsewhere = Move(bad.module, bad.src, bad.dst, bad.joint, bad.direction, (x + 1, y),
                     bad.substrate_module)
    with pytest.raises(ValueError, match="substrate is not its rotation's"):
        regroup(start, [elsewhere, *plan[1:]])


def test_plan_robust_regroups_its_plans_into_fewer_moves_and_steps(monkeypatch):
    # measured on this pair: see docs/planning.md, *Moves re-planned together*
    a, b = make_pair("blob", 300, 1)
    start = Configuration.from_cells(a)
    plan = plan_robust(start, b)
    assert plan.reached and plan.method == "local", plan.reason
    report = check_plan(start, b, plan.steps)
    assert report.ok, report.problem
    monkeypatch.setattr(regroup_module, "regroup", lambda i, moves, f=None, d=None: moves)
    alone = plan_robust(start, b)
    assert alone.method == "local"
    assert plan.move_count < 0.95 * alone.move_count
    assert len(plan.steps) < len(alone.steps)


def test_plans_above_the_limit_are_left_as_they_are(monkeypatch):
    start, plan = _random_walk(20, 50, 3)
    monkeypatch.setattr(regroup_module, "REGROUP_MOVES", 49)
    assert regroup(start, plan) is plan
