"""Lattice geometry against the thesis' tables (written out here, not imported)."""

import pytest

from hexbot.hil_sim.geometry import (
    CHANNEL_SIDE,
    Pivot,
    facing,
    joint_between,
    neighbor,
    side_towards,
    to_body,
    to_global,
)

# Table 4-3 as printed: joint, direction, substrate, empty cells, goal (letters of Fig. 4-30).
TABLE_4_3 = [
    (1, "CW", "A", "DEK", "F"), (2, "CW", "B", "EFL", "A"), (3, "CW", "C", "FAG", "B"),
    (4, "CW", "D", "ABH", "C"), (5, "CW", "E", "BCI", "D"), (6, "CW", "F", "CDJ", "E"),
    (1, "CCW", "F", "CBG", "A"), (2, "CCW", "A", "DCH", "B"), (3, "CCW", "B", "EDI", "C"),
    (4, "CCW", "C", "FEJ", "D"), (5, "CCW", "D", "AFK", "E"), (6, "CCW", "E", "BAL", "F"),
]
# A..F: neighbours on sides 1..6; G..L: second ring, G beyond A and B, ..., L beyond F and A.
NEAR = {"A": (-1, 1), "B": (0, 1), "C": (1, 0), "D": (1, -1), "E": (0, -1), "F": (-1, 0)}
RING = {"G": (-1, 2), "H": (1, 1), "I": (2, -1), "J": (1, -2), "K": (-1, -1), "L": (-2, 1)}
LETTERS = {**NEAR, **RING}


def test_table_4_1_neighbours_and_facing_sides():
    assert [neighbor((0, 0), s) for s in range(1, 7)] == list(NEAR.values())
    for side in range(1, 7):
        there = neighbor((3, -2), side)
        assert side_towards(there, (3, -2)) == facing(side)


@pytest.mark.parametrize("joint,direction,substrate,empty,goal", TABLE_4_3)
def test_pivots_reproduce_table_4_3(joint, direction, substrate, empty, goal):
    pivot = Pivot(joint, direction)
    origin = (0, 0)
    assert pivot.substrate(origin) == LETTERS[substrate]
    assert pivot.goal(origin) == LETTERS[goal]
    assert set(pivot.swept(origin)) == {LETTERS[c] for c in empty}


def test_orientation_maps_body_sides_onto_global_sides():
    # o = 2: body side 1 looks along global side 3; Yref = (S - j) mod 6.
    assert to_global(1, 2) == 3
    assert to_global(5, 2) == 1
    for o in range(6):
        for b in range(1, 7):
            assert to_body(to_global(b, o), o) == b
            assert (to_global(b, o) - b) % 6 == o


def test_joint_between_adjacent_sides_only():
    assert joint_between(3, 4) == 4
    assert joint_between(6, 1) == 1
    with pytest.raises(ValueError):
        joint_between(1, 3)


def test_selector_channels_of_table_3_5():
    assert CHANNEL_SIDE == {0: 1, 1: 6, 2: 0, 3: 2, 4: 5, 5: 3, 6: 4, 7: None}
