"""Pockets in a solid block: why a shape's holes move only by digs."""

from hexbot.planning.bubbles import pocket_shapes, travelling_bubbles, travels


def test_pocket_shapes_are_the_fixed_polyhexes():
    assert [len(pocket_shapes(k)) for k in range(1, 6)] == [1, 3, 11, 44, 186]


def test_no_pocket_of_up_to_six_cells_can_walk_through_a_solid_block():
    assert all(travelling_bubbles(k) == [] for k in range(1, 7))


def test_the_search_sees_a_pocket_come_back_shifted(monkeypatch):
    # a double of the moves that shifts the pocket one cell east: the search
    # must report the walk (so the negative results above are not vacuous)
    from hexbot.planning import bubbles

    monkeypatch.setattr(bubbles, "_moves", lambda p: iter([frozenset((x + 1, y) for x, y in p)]))
    assert travels(frozenset({(0, 0), (1, 0)}))


def test_a_round_pocket_is_rigid_and_one_wrapped_round_a_module_is_not():
    # a module moves into a pocket only with three free sides in a row: on
    # the rim of a round pocket no module has them
    from hexbot.planning.bubbles import _moves
    from hexbot.planning.windows import disc

    assert list(_moves(frozenset(disc((0, 0), 2)))) == []
    wrapped = frozenset({(1, 0), (1, -1), (0, -1)})  # three sides of (0, 0) in a row
    assert not travels(wrapped) and any(True for _ in _moves(wrapped | {(2, -1)}))
