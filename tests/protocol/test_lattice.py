"""Table 4-1 and Table 3-5 as the protocol defines them."""

from hexbot.protocol import lattice as L
from hexbot.protocol.frames import LocationMessage, encode_location


def test_table_4_1_neighbours_and_facing_sides():
    expected = {1: (-1, 1), 2: (0, 1), 3: (1, 0), 4: (1, -1), 5: (0, -1), 6: (-1, 0)}
    for side, cell in expected.items():
        assert L.neighbor((0, 0), side) == cell
        assert L.side_towards((0, 0), cell) == side
        assert L.neighbor(cell, L.facing(side)) == (0, 0)


def test_msg1_of_figure_4_13_follows_from_the_table():
    # The reference at (0,0) tells its side-1 neighbour "*-01+014".
    x, y = L.neighbor((0, 0), 1)
    assert encode_location(LocationMessage(x, y, L.facing(1))) == b"*-01+014"


def test_orientation_round_trip():
    for o in range(6):
        for side in L.SIDES:
            assert L.to_body(L.to_global(side, o), o) == side


def test_table_3_5_selector():
    assert L.CHANNEL_SIDE[2] == L.CENTRE
    assert sorted(L.SIDE_CHANNEL) == [0, 1, 2, 3, 4, 5, 6]
    assert L.SIDE_CHANNEL[4] == 6  # Y6 drives the side-4 transceiver


def test_distance():
    assert L.distance((0, 0), (2, -1)) == 2
    assert L.distance((0, 0), (1, 1)) == 2


def test_table_3_5_channels_as_printed():
    # Y0 side 1, Y1 side 6, Y2 centre (PC), Y3 side 2, Y4 side 5, Y5 side 3, Y6 side 4.
    assert L.CHANNEL_SIDE == {0: 1, 1: 6, 2: L.CENTRE, 3: 2, 4: 5, 5: 3, 6: 4, 7: None}


def test_turning_a_cell_turns_every_side_offset_to_the_next_sides():
    for side, offset in L.SIDE_OFFSETS.items():
        for k in range(-7, 8):
            assert L.turn(offset, k) == L.SIDE_OFFSETS[L.wrap(side + k)]
    cell = (3, -5)
    assert L.turn(cell, 6) == cell == L.turn(L.turn(cell, 2), -2)
    assert all(L.distance((0, 0), L.turn(cell, k)) == 5 for k in range(6))
