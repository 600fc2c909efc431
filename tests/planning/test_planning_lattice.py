"""Hex geometry: Table 4-1 neighbours, joints between sides, the Table 4-3 move set."""

import math

import pytest

from hexbot.planning.hexlattice import (
    LETTER_CELLS,
    ROTATIONS,
    SIDE_OFFSETS,
    cartesian,
    cells_to_matrix,
    distance,
    facing_side,
    matrix_to_cells,
    neighbor,
    ring_cell,
    rotate_cell,
    rotations_to,
    side_towards,
    vertices,
    wrap,
)


def close(p, q):
    return math.isclose(p[0], q[0], abs_tol=1e-9) and math.isclose(p[1], q[1], abs_tol=1e-9)


def test_table_4_1_neighbours_and_facing_sides():
    assert SIDE_OFFSETS == {1: (-1, 1), 2: (0, 1), 3: (1, 0), 4: (1, -1), 5: (0, -1), 6: (-1, 0)}
    for side in range(1, 7):
        n = neighbor((2, -3), side)
        assert side_towards((2, -3), n) == side
        assert side_towards(n, (2, -3)) == facing_side(side)
        assert distance((2, -3), n) == 1


def test_joint_j_is_the_corner_shared_with_neighbours_on_sides_j_minus_1_and_j():
    for j in range(1, 7):
        corner = vertices((0, 0))[j - 1]
        for side in (wrap(j - 1), j):
            assert any(close(corner, v) for v in vertices(neighbor((0, 0), side)))
        others = [s for s in range(1, 7) if s not in (wrap(j - 1), j)]
        for side in others:
            assert not any(close(corner, v) for v in vertices(neighbor((0, 0), side)))


def test_side_numbers_run_clockwise_from_the_upper_left():
    centre_angles = [math.atan2(*reversed(cartesian(SIDE_OFFSETS[s]))) for s in range(1, 7)]
    assert centre_angles[0] == pytest.approx(math.radians(150))  # side 1: upper left
    for a, b in zip(centre_angles, centre_angles[1:] + centre_angles[:1], strict=True):
        assert (a - b) % (2 * math.pi) == pytest.approx(math.pi / 3)


def test_matrix_rows_map_to_axial_cells_as_the_thesis_does():
    # row r, column c of an R-row matrix is the axial cell (c - 1, R - r), row 1 on top
    rows = [[0, 0, 0, 0], [0, 0, 0, 1], [0, 1, 1, 1]]  # Fig. 4-10, C1 of section 4.3.2
    assert matrix_to_cells(rows) == {(1, 0), (2, 0), (3, 0), (3, 1)}
    assert cells_to_matrix({(1, 0), (2, 0), (3, 0), (3, 1)}, shape=(3, 4)) == rows


def test_hexactuate_offsets_match_fig_4_30_letters():
    # HexActuate's MATLAB (row, column) offsets; axial = (column, -row)
    matlab = {"A": (-1, -1), "B": (-1, 0), "C": (0, 1), "D": (1, 1), "E": (1, 0), "F": (0, -1),
              "G": (-2, -1), "H": (-1, 1), "I": (1, 2), "J": (2, 1), "K": (1, -1), "L": (-1, -2)}
    for letter, (dr, dc) in matlab.items():
        assert LETTER_CELLS[letter] == (dc, -dr), letter


def test_table_4_3_is_the_rotation_of_one_row_and_follows_the_substrate_goal_rule():
    for rule in ROTATIONS:
        j = rule.joint
        if rule.direction == "CW":
            assert (rule.substrate_side, rule.goal_side) == (j, wrap(j - 1))
            expected = {neighbor((0, 0), j + 3), neighbor((0, 0), j + 4), ring_cell((0, 0), j + 4)}
        else:
            assert (rule.substrate_side, rule.goal_side) == (wrap(j - 1), j)
            expected = {neighbor((0, 0), j + 2), neighbor((0, 0), j + 1), ring_cell((0, 0), j)}
        assert set(rule.swept) == expected
        first = next(r for r in ROTATIONS if r.joint == 1 and r.direction == rule.direction)
        turns = j - 1
        assert rule.substrate == rotate_cell(first.substrate, turns)
        assert {rotate_cell(c, turns) for c in first.swept} == set(rule.swept)


def test_every_rotation_can_be_undone_over_the_same_cells():
    for rule in ROTATIONS:
        sub, goal, swept = rule.at((0, 0))
        back = [r for r in rotations_to(side_towards(goal, (0, 0))) if r.at(goal)[0] == sub]
        assert len(back) == 1
        assert set(back[0].at(goal)[2]) == set(swept)
        assert back[0].direction != rule.direction


def test_two_rotations_reach_each_neighbour():
    for side in range(1, 7):
        joints = sorted((r.joint, r.direction) for r in rotations_to(side))
        assert joints == sorted([(wrap(side + 1), "CW"), (side, "CCW")])


@pytest.mark.parametrize("seed", range(3))
def test_the_open_rotations_table_matches_table_4_3_row_by_row(seed):
    # the planners look the open rotations up by the occupancy of the twelve
    # cells around a module; each row of Table 4-3 checked on its own must agree
    import random

    from hexbot.planning.robust import _moves_from

    rng = random.Random(seed)
    around = [(x, y) for x in range(-3, 4) for y in range(-3, 4)]
    for _ in range(400):
        occupied = {c for c in around if rng.random() < 0.45}
        cell = (0, 0)
        mover = rng.choice(around)  # where the traveller started: counts as empty
        taken = occupied - {mover}
        expected = set()
        for rule in ROTATIONS:
            substrate, goal, swept = rule.at(cell)
            if substrate in taken and goal not in taken and not set(swept) & taken:
                expected.add((rule, substrate, goal))
        assert set(_moves_from(cell, occupied, mover)) == expected
