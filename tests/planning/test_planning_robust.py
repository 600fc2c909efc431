"""The robust planner: legal, connected, collision-free plans, or a clear reason."""

import random

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from hexbot.planning.bounds import step_bound
from hexbot.planning.budget import PlanningFailure
from hexbot.planning.checker import check_plan
from hexbot.planning.configuration import Configuration, is_connected
from hexbot.planning.generate import parallelogram, random_blob
from hexbot.planning.plan import Step, check_step
from hexbot.planning.robust import is_immobile, plan_robust


def assert_legal(plan):
    configs = plan.configurations()
    for t, (config, step) in enumerate(zip(configs, plan.steps, strict=False), start=1):
        assert check_step(config, step) == [], f"time step {t}"
        assert is_connected(configs[t].cells)
        # no module moves twice in a step and no mover is another's substrate
        movers = [m.module for m in step.moves]
        assert len(movers) == len(set(movers))
        assert not {m.substrate for m in step.moves} & {m.src for m in step.moves}


def test_completes_the_swapped_p02_example_where_the_thesis_stalls(p02_swapped):
    initial, goal = p02_swapped
    plan = plan_robust(initial, goal)
    assert plan.reached, plan.reason
    assert_legal(plan)
    assert plan.move_count >= plan.lower_bound


@pytest.mark.parametrize("fixture", ["p01", "s02"])
def test_thesis_examples_parallel_and_serial(fixture, request):
    initial, goal = request.getfixturevalue(fixture)
    parallel = plan_robust(initial, goal)
    serial = plan_robust(initial, goal, parallel=False)
    for plan in (parallel, serial):
        assert plan.reached, plan.reason
        assert_legal(plan)
    # the shorter schedule of the tidied and the regrouped plan is kept: one
    # move a step, that is the one with fewer moves
    assert serial.move_count <= parallel.move_count
    assert serial.time_steps == serial.move_count
    assert parallel.time_steps <= serial.time_steps
    assert parallel.time_steps >= step_bound(initial.cells, goal).value


def test_reverse_s02_needs_goal_modules_filled_in_order(s02):
    # filling the top row from both ends would trap its middle cell (4 occupied sides)
    initial, goal = s02
    back = plan_robust(Configuration.from_cells(goal), initial.cells)
    assert back.reached, back.reason
    assert_legal(back)


def test_fig_4_6_immobile_configuration_is_detected(example):
    cells = example("test_immobile.txt").cells
    fixed = (3, 3)  # Test_Immobile's blue module, fixed to the base
    assert is_immobile(cells, fixed)
    assert not is_immobile(cells)  # unbolted, the tail end could swing
    goal = (cells - {(1, 10)}) | {(2, 9)}
    assert is_connected(goal) and len(goal) == len(cells)
    plan = plan_robust(Configuration.from_cells(cells), goal, fixed=fixed)
    assert not plan.reached and "immobile" in plan.reason


@pytest.mark.parametrize(
    ("goal", "words"),
    [
        ({(0, 0), (1, 0), (5, 5)}, "not connected"),
        ({(0, 0), (1, 0)}, "3 modules"),
    ],
)
def test_unreachable_goals_are_reported(goal, words):
    plan = plan_robust(Configuration.from_cells({(0, 0), (1, 0), (2, 0)}), frozenset(goal))
    assert not plan.reached and words in plan.reason and not plan.steps


def test_parallelogram_to_parallelogram_is_planned_and_parallel():
    initial = Configuration.from_cells(parallelogram(6, 4))
    plan = plan_robust(initial, parallelogram(8, 3))
    assert plan.reached
    assert_legal(plan)
    assert plan.time_steps < plan.move_count  # some steps move several modules


def test_long_direct_plans_run_many_journeys_at_once():
    # the scheduler looks far ahead: 1,608 moves in 201 steps (269 with a 400-move window)
    plan = plan_robust(Configuration.from_cells(parallelogram(10, 10)), parallelogram(20, 5))
    assert plan.reached and plan.method == "direct"
    assert_legal(plan)
    assert plan.time_steps * 7 < plan.move_count


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(size=st.integers(3, 14), seed_a=st.integers(0, 10**6), seed_b=st.integers(0, 10**6))
def test_random_connected_configurations_give_legal_plans_or_reasons(size, seed_a, seed_b):
    a = random_blob(size, seed_a, compact=random.Random(seed_a).random())
    b = random_blob(size, seed_b, compact=0.6)
    plan = plan_robust(Configuration.from_cells(a), b)
    assert_legal(plan)  # even a failed plan stops without an illegal step
    if plan.reached:
        assert plan.final.cells == b
        assert plan.move_count >= plan.lower_bound
    else:
        # only a provably impossible pair may fail (immobile, or a cell never enterable)
        assert "immobile" in plan.reason or "never be entered" in plan.reason, plan.reason
        assert not plan.steps


@pytest.mark.parametrize(("size", "seed"), [(10, s) for s in range(5)] + [(30, s) for s in range(5)]
                         + [(100, 0)])
def test_random_blob_pairs_are_completed(size, seed):
    # the benchmark's pairs: the direct method stalls on many of them (notched goals)
    a, b = random_blob(size, 2 * seed, 0.8), random_blob(size, 2 * seed + 1, 0.8)
    plan = plan_robust(Configuration.from_cells(a), b)
    assert plan.reached, plan.reason
    assert plan.method in ("direct", "direct, backwards", "local", "middle ball", "canonical strip")
    assert_legal(plan)
    assert plan.final.cells == b


def test_canonical_strip_goes_through_the_strip_and_keeps_the_anchor():
    from hexbot.planning.canonical import anchor_of, replay, strip_shape, to_strip

    cells = random_blob(40, 7, 0.8)
    config = Configuration.from_cells(cells)
    moves = to_strip(config, 3)
    strip = replay(config, moves)
    anchor = anchor_of(cells)
    assert strip.cells == strip_shape(anchor, 40, 3)
    assert strip[anchor] == config[anchor]  # the anchor module never moved
    assert anchor not in {m.src for m in moves}


def test_canonical_plan_is_legal_when_the_strip_grows_in_a_turned_frame():
    from hexbot.planning.canonical import replay, via_strip

    # the first pair found where the strip to the right cannot be built (a spindly start)
    a = random_blob(12, 188553, compact=random.Random(188553).random())
    b = random_blob(12, 774397, compact=0.6)
    config = Configuration.from_cells(a)
    moves = via_strip(config, b)
    for move in moves:
        assert check_step(config, Step([move])) == []
        config = replay(config, [move])
    assert config.cells == b


def test_a_fixed_module_extreme_in_no_direction_stays_put_on_the_strip_route():
    a, b = random_blob(100, 0, 0.8), random_blob(100, 1, 0.8)
    fixed = (0, 0)  # both blobs grow from it; it is extreme in no direction
    plan = plan_robust(Configuration.from_cells(a), b, fixed=fixed)
    assert plan.reached, plan.reason
    assert_legal(plan)
    report = check_plan(Configuration.from_cells(a), b, plan.steps, fixed=fixed)
    assert report.ok, report.problem
    assert all(m.src != fixed for s in plan.steps for m in s.moves)


def test_the_spine_route_ends_in_the_strip_at_the_fixed_module():
    from hexbot.planning.canonical import replay, strip_shape, to_fixed_strip
    from hexbot.planning.hexlattice import rotate_cell

    config = Configuration.from_cells(random_blob(40, 3, 0.5))
    fixed = (0, 0)
    moves, turn = to_fixed_strip(config, fixed, 0, 3)
    assert all(m.src != fixed for m in moves)
    for move in moves:
        assert check_step(config, Step([move])) == []
        config = replay(config, [move])
    strip = {rotate_cell(c, turn) for c in strip_shape(rotate_cell(fixed, -turn), 40, 3)}
    assert config.cells == strip


def test_the_spine_route_gives_up_on_the_move_ceiling_before_the_goal_side(monkeypatch):
    """At 10,000 modules each side takes half a minute: a direction whose first
    side already passes the ceiling must not gather the goal too."""
    from hexbot.planning import canonical

    a, b = random_blob(60, 0, 0.8), random_blob(60, 1, 0.8)
    gathered = []
    real = canonical.to_fixed_strip

    def counting(config, *args, **kwargs):
        gathered.append(len(config))
        return real(config, *args, **kwargs)

    monkeypatch.setattr(canonical, "to_fixed_strip", counting)
    with pytest.raises(PlanningFailure, match="more than 50 moves needed"):
        canonical.via_strip(Configuration.from_cells(a), b, max_moves=50, widths=[3],
                            fixed=(0, 0))
    assert len(gathered) == 6  # one side per direction, never the goal's


def test_fixed_module_at_the_extreme_of_both_keeps_still_on_the_strip_route():
    from hexbot.planning.canonical import anchor_of

    a, b = random_blob(100, 0, 0.8), random_blob(100, 1, 0.8)
    # shift the goal so that both share their rightmost (topmost) cell
    (ax, ay), (bx, by) = anchor_of(a), anchor_of(b)
    b = frozenset((x + ax - bx, y + ay - by) for x, y in b)
    plan = plan_robust(Configuration.from_cells(a), b, fixed=(ax, ay))
    assert plan.reached, plan.reason
    assert_legal(plan)
    assert all(m.src != (ax, ay) for s in plan.steps for m in s.moves)
