"""The thesis' layers at their edges (Chapter 4, Appendix C): the criteria of
the text and the listing's order and ties, each on a small configuration."""

import math

from hexbot.planning.configuration import Configuration
from hexbot.planning.hexlattice import matrix_to_cells, neighbors, rotations_to
from hexbot.planning.thesis.actuation import hex_actuate
from hexbot.planning.thesis.layers import find_ve, mobile_electrons, potential_voids
from hexbot.planning.thesis.mdp import (
    DISCOUNT,
    mdp_actions,
    mdp_reward,
    mdp_states,
    next_location,
    value_iteration,
)
from hexbot.planning.thesis.planner import FaithfulOptions, plan_faithful
from hexbot.planning.thesis.voidprop import propagate


def _mobile(current, goal):
    _, electrons = find_ve(current, goal)
    return mobile_electrons(electrons, current)


# --- layer 2 ------------------------------------------------------------------


def test_an_electron_with_four_occupied_neighbours_is_not_mobile():
    # "fewer than four occupied neighbours" (Mobile); (0, 0) is no cut vertex either way
    four = frozenset({(0, 0), *neighbors((0, 0))[:4]})
    three = frozenset({(0, 0), *neighbors((0, 0))[:3]})
    assert mobile_electrons(frozenset({(0, 0)}), four) == []
    assert mobile_electrons(frozenset({(0, 0)}), three) == [(0, 0)]


def test_mobile_electrons_come_in_matlab_find_order_top_first_in_a_column():
    current = frozenset({(-1, 0), (0, 0), (1, 0), (0, 1), (0, -1)})
    goal = frozenset({(-1, 0), (0, 0), (1, 0), (2, 0), (-2, 0)})
    assert _mobile(current, goal) == [(0, 1), (0, -1)]  # column 0: row of (0, 1) is on top


def test_a_void_touching_only_a_mobile_electron_is_not_a_potential_void():
    bar = frozenset({(0, 0), (1, 0), (2, 0)})
    # (2, 0) is a mobile electron; the void (3, 0) touches no other module
    assert _mobile(bar, frozenset({(0, 0), (1, 0), (3, 0)})) == [(2, 0)]
    assert potential_voids(bar, frozenset({(0, 0), (1, 0), (3, 0)})) == []
    assert potential_voids(bar, frozenset({(0, 0), (1, 0), (1, 1)})) == [(1, 1)]


# --- layer 3 ------------------------------------------------------------------


def test_the_wave_travels_only_over_cells_that_touch_an_immobile_module():
    # over the open cells the electron (-2, 4) would be met at step 4
    current = frozenset({(-2, 1), (-2, 2), (-2, 3), (-2, 4), (-1, 1), (0, 0), (1, 0)})
    goal = frozenset({(0, 0), (1, -1), (1, 0), (2, -3), (2, -2), (2, -1), (2, 0)})
    mobile = _mobile(current, goal)
    void = (2, 0)
    assert void in potential_voids(current, goal, mobile)
    assert propagate(current, mobile, void)[0] == ((-2, 4), 5)


def test_electrons_met_in_one_wave_step_come_in_matlab_scan_order():
    current = frozenset({(0, -1), (0, 0), (0, 1), (0, 2), (1, -2)})
    goal = frozenset({(0, -1), (0, 0), (0, 1), (1, -1), (1, 0)})
    mobile = _mobile(current, goal)
    hits = propagate(current, mobile, (1, 0))
    assert [t for _, t in hits[:2]] == [2, 2]
    assert hits[0] == ((0, 2), 2)


# --- layer 4 ------------------------------------------------------------------


def _fig_4_27():
    # MDP_Reward's example (Fig. 4-27), as in test_planning_thesis
    z = [0] * 7
    i = [z, z, [0, 1, 0, 0, 0, 0, 0], [0, 1, 1, 1, 1, 1, 0], z, z]
    g = [z, [0, 1, 1, 0, 0, 0, 0], [0, 1, 0, 1, 0, 0, 0], [0, 0, 1, 1, 0, 0, 0], z, z]
    return (frozenset(matrix_to_cells(i)), frozenset(matrix_to_cells(g)),
            lambda r, c: (c - 1, 6 - r))


def test_the_values_solve_the_bellman_equation_with_staying_put_an_action():
    # eq. (4.11): U(s) = R(s) + gamma max_a U(a), the actions being the
    # neighbouring states and staying; the values are normalised by their maximum
    current, goal, cell = _fig_4_27()
    electron, void = cell(4, 2), cell(2, 2)
    values, _ = value_iteration(current, goal, electron, void)
    states = mdp_states(current, goal)
    reward = mdp_reward(current, goal, electron, void)
    assert mdp_actions(void, states)[-1] == void
    # the void's best action is to stay: U = 1 / (1 - gamma) before normalising
    top = 1 / (1 - DISCOUNT)
    for s in states:
        best = max(values[a] for a in mdp_actions(s, states))
        assert math.isclose(values[s], reward.get(s, 0.0) / top + DISCOUNT * best,
                            abs_tol=0.01), s


def test_an_unreachable_reward_leaves_the_electron_where_it_is():
    # the "void" (0, 0) touches six immobile modules: it is no MDP state, every
    # value stays negative, the listing's first sweep shows no increase and
    # stops, and its division by a zero maximum leaves the electron in place
    ring = frozenset(neighbors((0, 0)))
    current = ring | {(2, 0)}
    goal = ring | {(0, 0)}
    electron = (2, 0)  # on the ring's side 3, a state itself
    assert (0, 0) not in mdp_states(current, goal) and electron in mdp_states(current, goal)
    values, sweeps = value_iteration(current, goal, electron, (0, 0))
    assert sweeps == 1 and values and all(v != v for v in values.values())  # NaN
    assert next_location(current, goal, electron, (0, 0)) == electron


def test_equal_neighbour_values_go_to_the_first_side():
    # MDP_NRL takes a neighbour only when its value is higher than the best so
    # far, in side order 1..6: of two equal ones, the first
    current = frozenset({(-1, 0), (0, -1), (0, 0), (1, -1), (1, 0)})
    goal = frozenset({(-2, 1), (-1, 0), (-1, 1), (0, 0), (0, 1)})
    electron, void = (1, -1), (-2, 1)
    values, _ = value_iteration(current, goal, electron, void)
    around = [values.get(n, 0.0) for n in neighbors(electron)]
    best = max(around)
    assert around.count(best) == 2 and best > values.get(electron, 0.0)
    assert next_location(current, goal, electron, void) == neighbors(electron)[around.index(best)]


# --- layer 5 ------------------------------------------------------------------


def test_hexactuate_needs_the_substrate_and_the_swept_cells_of_a_row():
    src = (0, 0)
    for side in range(1, 7):
        dst = neighbors(src)[side - 1]
        for rule in rotations_to(side):  # the two rows of Table 4-3 that end on dst
            sub, _, swept = rule.at(src)
            assert hex_actuate(src, dst, frozenset({sub})) == (rule, sub)
            for cell in swept:
                assert hex_actuate(src, dst, frozenset({sub, cell})) is None
        # each row's substrate lies on a swept cell of the other: neither fits
        both = frozenset(rule.at(src)[0] for rule in rotations_to(side))
        assert hex_actuate(src, dst, both) is None


# --- the planner loop -------------------------------------------------------------


def test_max_steps_is_the_most_time_steps_a_faithful_plan_takes(p01):
    initial, goal = p01  # five parallel time steps
    short = plan_faithful(initial, goal, True, FaithfulOptions(max_steps=4))
    assert not short.reached and short.time_steps == 4
    assert short.reason == "goal not reached after 4 time steps"
    assert plan_faithful(initial, goal, True, FaithfulOptions(max_steps=5)).reached


def test_a_goal_with_fewer_cells_than_modules_is_refused_up_front():
    initial = Configuration.from_cells([(0, 0), (1, 0), (2, 0)])
    plan = plan_faithful(initial, frozenset({(0, 0), (1, 0)}), parallel=False)
    assert not plan.reached and plan.steps == []
    assert plan.reason == "the goal has 2 cells for 3 modules"


def test_a_move_into_a_cell_left_earlier_in_the_same_step_is_no_merge():
    # HexAll_P moves the pairs one after the other on the matrix (Hexmove):
    # module 4 enters (1, -1), which module 3 left in the same step; the
    # faithful plan goes on (and records what the robot would break)
    initial = Configuration.from_cells([(0, 0), (1, -1), (1, 0), (2, -1)])
    goal = frozenset({(-1, 0), (0, -1), (0, 0), (0, 1)})
    plan = plan_faithful(initial, goal, parallel=True)
    assert plan.reached and plan.reason == ""
    first = {m.module: (m.src, m.dst) for m in plan.steps[0].moves}
    assert first[3][0] == first[4][1] == (1, -1)
    assert any("both need cell (1, -1)" in w for w in plan.warnings)

