"""Lattice and configuration helpers at their edges: turns either way round,
MATLAB's find order, and a move onto a taken cell."""

import pytest

from hexbot.planning.configuration import Configuration
from hexbot.planning.hexlattice import (
    SIDE_OFFSETS,
    cells_to_matrix,
    column_major_key,
    neighbor,
    rotate_cell,
)


@pytest.mark.parametrize("steps", range(-7, 8))
def test_a_turn_maps_side_s_to_side_s_plus_steps_either_way_round(steps):
    for side, offset in SIDE_OFFSETS.items():
        assert rotate_cell(offset, steps) == neighbor((0, 0), side + steps)
        assert rotate_cell(neighbor((3, -2), side), steps, center=(3, -2)) == neighbor(
            (3, -2), side + steps)
    assert rotate_cell(rotate_cell((2, -5), steps), -steps) == (2, -5)


def test_column_major_order_is_matlab_find_order():
    rows = [[1, 0, 1], [1, 1, 0]]  # find() numbers (1,1), (2,1), (2,2), (1,3)
    cells = {(0, 1), (0, 0), (1, 0), (2, 1)}
    assert cells_to_matrix(cells) == rows
    assert sorted(cells, key=column_major_key) == [(0, 1), (0, 0), (1, 0), (2, 1)]


def test_a_module_cannot_be_moved_onto_a_taken_cell():
    config = Configuration.from_cells([(0, 0), (1, 0), (2, 0)])
    with pytest.raises(ValueError, match=r"cell \(1, 0\) is occupied"):
        config.moved((0, 0), (1, 0))
    with pytest.raises(ValueError, match=r"no module at \(5, 5\)"):
        config.moved((5, 5), (6, 6))


def test_a_moved_module_keeps_an_orientation_of_0_to_5():
    config = Configuration.from_cells([(0, 0), (1, 0)])
    assert config.moved((1, 0), (1, -1), orientation=8)[(1, -1)].orientation == 2
    assert config.moved((1, 0), (1, -1), orientation=-2)[(1, -1)].orientation == 4
