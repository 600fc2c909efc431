"""Table 4-3 against the thesis: the table as printed (seed 002, lines
2500-2513) and the letters of Fig. 4-30, written out here, not imported."""

import pytest

from hexbot.protocol.rotation_geometry import (
    ROTATION_BY_KEY,
    ROTATIONS,
    Rotation,
    joint_between,
    rotations_to,
)

# Table 4-3 as printed: joint, direction, substrate, empty cells, goal.
TABLE_4_3 = [
    (1, "CW", "A", "DEK", "F"), (2, "CW", "B", "EFL", "A"), (3, "CW", "C", "FAG", "B"),
    (4, "CW", "D", "ABH", "C"), (5, "CW", "E", "BCI", "D"), (6, "CW", "F", "CDJ", "E"),
    (1, "CCW", "F", "CBG", "A"), (2, "CCW", "A", "DCH", "B"), (3, "CCW", "B", "EDI", "C"),
    (4, "CCW", "C", "FEJ", "D"), (5, "CCW", "D", "AFK", "E"), (6, "CCW", "E", "BAL", "F"),
]
# Fig. 4-30 around the mobile module at (0, 0), in Table 4-1 coordinates:
# A..F the neighbours on sides 1..6; G..L the second ring, G beyond A and B,
# ..., L beyond F and A (HexActuate's MATLAB offsets, axial = (column, -row)).
LETTERS = {"A": (-1, 1), "B": (0, 1), "C": (1, 0), "D": (1, -1), "E": (0, -1), "F": (-1, 0),
           "G": (-1, 2), "H": (1, 1), "I": (2, -1), "J": (1, -2), "K": (-1, -1), "L": (-2, 1)}


@pytest.mark.parametrize("joint,direction,substrate,empty,goal", TABLE_4_3)
def test_rotations_reproduce_table_4_3(joint, direction, substrate, empty, goal):
    rotation = ROTATION_BY_KEY[(joint, direction)]
    assert rotation.substrate == LETTERS[substrate]
    assert rotation.goal == LETTERS[goal]
    assert set(rotation.swept) == {LETTERS[c] for c in empty}


def test_rows_in_the_order_of_the_table():
    assert [(r.joint, r.direction) for r in ROTATIONS] == [(j, d) for j, d, *_ in TABLE_4_3]


def test_cells_move_with_the_mobile_module():
    rotation = Rotation(3, "CCW")
    sub, goal, swept = rotation.at((4, -2))
    assert sub == (4 + LETTERS["B"][0], -2 + LETTERS["B"][1])
    assert goal == (4 + LETTERS["C"][0], -2 + LETTERS["C"][1])
    assert set(swept) == {(4 + x, -2 + y) for x, y in (LETTERS[c] for c in "EDI")}


def test_two_moves_end_in_each_neighbour():
    # Thesis: "two moves that end in location A: joint 2 clockwise and joint 1
    # counterclockwise".
    assert {(r.joint, r.direction) for r in rotations_to(1)} == {(2, "CW"), (1, "CCW")}
    for side in range(1, 7):
        assert len(rotations_to(side)) == 2


def test_a_clockwise_move_turns_the_module_clockwise():
    assert Rotation(1, "CW").turn == 2
    assert Rotation(1, "CCW").turn == -2


def test_joint_between_adjacent_sides_only():
    assert joint_between(3, 4) == 4
    assert joint_between(6, 1) == 1
    with pytest.raises(ValueError):
        joint_between(1, 3)
