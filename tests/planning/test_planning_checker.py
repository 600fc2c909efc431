"""The independent plan checker: accepts the planners' plans, rejects what breaks a rule."""

import random

import pytest

from hexbot.planning.checker import check_plan, pieces, still_one_piece
from hexbot.planning.configuration import (
    Configuration,
    articulation_points,
    articulation_points_by_removal,
    components,
)
from hexbot.planning.generate import random_blob
from hexbot.planning.moves import Move
from hexbot.planning.plan import Step
from hexbot.planning.robust import plan_robust
from hexbot.protocol.rotation_geometry import ROTATIONS

# a bar of three on the x axis: (0,0) (1,0) (2,0), ids 1, 2, 3 (reading order)
BAR = Configuration.from_cells([(0, 0), (1, 0), (2, 0)])


def legal_moves(config: Configuration, cell):
    """Every Table 4-3 rotation of the module at ``cell`` that fits the cells (not connectivity)."""
    for rule in ROTATIONS:
        sub, goal, swept = rule.at(cell)
        if sub in config and goal not in config and not any(c in config for c in swept):
            yield Move(config[cell].id, cell, goal, rule.joint, rule.direction, sub,
                       config[sub].id)


def test_accepts_robust_plans_on_random_pairs():
    for seed in range(4):
        a, b = random_blob(25, 2 * seed, 0.7), random_blob(25, 2 * seed + 1, 0.7)
        plan = plan_robust(Configuration.from_cells(a), b)
        assert plan.reached
        report = check_plan(plan.initial, b, plan.steps)
        assert report.ok, report.problem
        assert report.moves == plan.move_count


def test_rejects_a_move_that_disconnects():
    # a bent chain (0,0) (1,0) (1,1): the middle module, with free sides 3, 4, 5,
    # rolls away over (1,1) and (0,0) is left alone
    chain = Configuration.from_cells([(0, 0), (1, 0), (1, 1)])
    middle = next(legal_moves(chain, (1, 0)))
    end = chain.moved(middle.src, middle.dst).cells
    report = check_plan(chain, end, [Step([middle])])
    assert not report.ok and "fall apart" in report.problem


def test_rejects_wrong_geometry_occupied_sweep_and_shared_cells():
    move = next(legal_moves(BAR, (2, 0)))
    bad_end = Move(move.module, move.src, (5, 5), move.joint, move.direction, move.substrate,
                   move.substrate_module)
    assert "ends in" in check_plan(BAR, frozenset(), [Step([bad_end])]).problem
    # the same rotation with an obstacle on a swept cell
    obstacle = Configuration.from_cells([*BAR.cells, move.swept()[0]])
    ids = {c: m.id for c, m in obstacle.items()}
    blocked = Move(ids[move.src], move.src, move.dst, move.joint, move.direction,
                   move.substrate, ids[move.substrate])
    assert "occupied" in check_plan(obstacle, frozenset(), [Step([blocked])]).problem
    # two modules of a blob that would sweep the same cell in one step
    blob = Configuration.from_cells(random_blob(12, 4, 0.3))
    moves = [m for c in sorted(blob.cells) for m in legal_moves(blob, c)]
    clash = [(a, b) for a in moves for b in moves
             if a.module < b.module and {a.src, b.src}.isdisjoint({a.substrate, b.substrate})
             and {a.src, a.dst, *a.swept()} & {b.src, b.dst, *b.swept()}]
    assert clash
    report = check_plan(blob, frozenset(), [Step(list(clash[0]))])
    assert "both need" in report.problem


def test_rejects_moving_the_fixed_module_and_a_short_plan():
    move = next(legal_moves(BAR, (2, 0)))
    end = BAR.moved(move.src, move.dst).cells
    assert check_plan(BAR, end, [Step([move])]).ok
    assert "fixed" in check_plan(BAR, end, [Step([move])], fixed=(2, 0)).problem
    assert "short of the goal" in check_plan(BAR, end, []).problem


@pytest.mark.parametrize("seed", range(6))
def test_cut_vertices_and_pieces_agree_with_removal(seed):
    rng = random.Random(seed)
    cells = random_blob(rng.randint(5, 60), seed, compact=rng.random())
    assert articulation_points(cells) == articulation_points_by_removal(cells)
    loose = set(rng.sample(sorted(cells), len(cells) // 2))
    assert pieces(loose) == components(loose)


@pytest.mark.parametrize("seed", range(40))
def test_the_local_connectivity_test_agrees_with_counting_pieces(seed):
    # blobs with holes and thin parts; remove 1-4 modules, near each other or apart
    rng = random.Random(seed)
    cells = set(random_blob(rng.randint(5, 120), seed, compact=rng.random()))
    for _ in range(30):
        some = rng.sample(sorted(cells), rng.randint(1, min(4, len(cells) - 1)))
        removed = set(some)
        assert still_one_piece(cells, removed) == (pieces(cells - removed) == 1), removed


def test_a_step_that_cuts_a_chain_far_from_the_rest_is_caught():
    # a long chain: removing its middle splits it, though both halves are big
    chain = {(x, 0) for x in range(60)}
    assert not still_one_piece(chain, {(30, 0)})
    assert still_one_piece(chain, {(59, 0)})
    assert still_one_piece(chain | {(x, 1) for x in range(60)}, {(30, 0)})
