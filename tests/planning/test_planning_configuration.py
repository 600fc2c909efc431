"""Connectivity and articulation points: the breadth-first search agrees with the thesis'
Laplacian test."""

from hypothesis import given, settings
from hypothesis import strategies as st

from hexbot.planning.configuration import (
    Configuration,
    articulation_points,
    components,
    contact_hops,
    is_connected,
    laplacian_articulation_points,
    laplacian_components,
)
from hexbot.planning.generate import random_blob


@settings(max_examples=40, deadline=None)
@given(size=st.integers(1, 25), seed=st.integers(0, 10**6), compact=st.floats(0, 1))
def test_articulation_points_match_the_laplacian_criterion(size, seed, compact):
    cells = random_blob(size, seed, compact)
    assert is_connected(cells) and laplacian_components(cells) == 1
    assert articulation_points(cells) == laplacian_articulation_points(cells)


def test_laplacian_counts_components():
    assert laplacian_components({(0, 0), (1, 0), (5, 5), (9, 9), (9, 10)}) == 3
    assert not is_connected({(0, 0), (2, 0)})


def test_pieces_hops_and_cut_vertices_of_a_disconnected_set():
    cells = {(0, 0), (1, 0), (2, 0), (9, 9), (9, 10)}
    assert components(cells) == laplacian_components(cells) == 2 and components(set()) == 0
    assert contact_hops(cells, (0, 0)) == {(0, 0): 0, (1, 0): 1, (2, 0): 2}
    # only a removal that splits a piece counts; an end of a line or a lone pair does not
    assert articulation_points(cells) == laplacian_articulation_points(cells) == {(1, 0)}


def test_configuration_moves_and_numbering():
    config = Configuration.from_cells({(0, 0), (1, 0), (0, 1)})
    assert config[(0, 1)].id == 1  # reading order: top row first
    moved = config.moved((1, 0), (1, -1), orientation=2)
    assert moved.cells == {(0, 0), (0, 1), (1, -1)} and moved[(1, -1)].orientation == 2
    assert moved != config and hash(moved) != hash(config)
