"""Edges of the parallel schedule a user notices (mutation audit, session 35).

The makespan of a plan is its schedule's number of time steps; no schedule
of a serial plan is shorter than its longest chain of dependent moves
(:func:`~hexbot.planning.schedule.critical_chain`), and the list schedule
reaches it when nothing waits for a cut vertex. A schedule that runs out of
time falls back to one move per step and says so.
"""

import pytest

from hexbot.planning.budget import Deadline
from hexbot.planning.checker import check_plan
from hexbot.planning.robust import plan_robust
from hexbot.planning.schedule import bottom_levels, critical_chain, schedule, schedule_parallel
from tests.planning.test_robust_edges import pair


@pytest.mark.parametrize(("family", "n", "seed", "steps"), [
    ("scramble", 30, 0, 9), ("scramble", 60, 1, 9), ("scramble", 30, 1, 8)])
def test_the_makespan_is_the_longest_chain_of_dependent_moves(family, n, seed, steps):
    # on these pairs nothing waits but for the moves it depends on: the list
    # schedule, longest chain first, reaches the critical chain exactly
    initial, goal = pair(family, n, seed)
    plan = plan_robust(initial, goal)
    serial = [m for step in plan.steps for m in step.moves]
    assert plan.time_steps == critical_chain(serial)[0] == steps


def test_the_thesis_s02_schedule_is_its_longest_chain(s02):
    initial, goal = s02
    plan = plan_robust(initial, goal)
    assert check_plan(initial, goal, plan.steps).ok
    assert plan.method == "direct" and plan.move_count <= 18
    serial = [m for step in plan.steps for m in step.moves]
    assert plan.time_steps == critical_chain(serial)[0] == 7


def test_a_schedule_out_of_time_runs_one_move_per_step_and_says_so():
    initial, goal = pair("blob", 30, 1)
    serial = [m for step in plan_robust(initial, goal).steps for m in step.moves]
    steps, warning = schedule(initial, serial, Deadline(1e-9))
    assert [s.moves for s in steps] == [[m] for m in serial]
    assert warning == ("parallel schedule: the time budget of 1e-09 s ran out, so the "
                       "plan runs one move per step")
    assert check_plan(initial, goal, steps).ok


@pytest.mark.parametrize(("family", "n", "seed"), [("blob", 30, 0), ("holes", 20, 1),
                                                   ("blob", 60, 0)])
def test_the_longest_chain_is_the_highest_bottom_level(family, n, seed):
    # two walks of one dependency graph, forwards and backwards, must agree;
    # the chain they give is a chain: each move depends on the one before
    initial, goal = pair(family, n, seed)
    serial = [m for step in plan_robust(initial, goal).steps for m in step.moves]
    length, chain = critical_chain(serial)
    assert length == max(bottom_levels(serial)) == len(chain)
    assert chain == sorted(chain, reverse=True)
    steps = schedule_parallel(initial, serial)
    assert len(steps) >= length
    assert check_plan(initial, goal, steps).ok
