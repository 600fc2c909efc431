"""The strip route's mover pick and path search run in C (planning/_strip.c);
they must give the paths the Python searches gave
(tests/planning/strip_reference.py), search for search: the strip plans of
10,000 modules are compared across sessions by their moves."""

import random

import pytest

from hexbot.bench.planning import make_pair
from hexbot.planning import _strip
from hexbot.planning.canonical import StripGrid, anchor_of, path_to, strip_cells
from hexbot.planning.configuration import articulation_points, contact_hops
from hexbot.planning.hexlattice import neighbors
from tests.planning import strip_reference as reference


def _scene(family: str, seed: int):
    """A random configuration, its strip cells, the empty cells around it, its
    modules farthest from the anchor first (to_strip's order) and how many are
    farthest."""
    cells, _ = make_pair(family, 80, seed)
    occupied = set(cells)
    anchor = anchor_of(occupied)
    targets = strip_cells(anchor, 30, 3)
    empty = sorted({n for c in occupied for n in neighbors(c)} - occupied)
    hops = contact_hops(frozenset(occupied), anchor)
    order = sorted((c for c in occupied if c != anchor), key=lambda c: (-hops[c], c))
    return occupied, targets, empty, order, sum(1 for c in order if hops[c] == hops[order[0]])


@pytest.mark.parametrize("family", ["blob", "scramble"])
@pytest.mark.parametrize("seed", range(3))
def test_the_c_searches_find_what_the_python_searches_found(family, seed, monkeypatch):
    cut_passes = []
    monkeypatch.setattr(reference, "articulation_points",
                        lambda cells: cut_passes.append(1) or articulation_points(cells))
    occupied, targets, empty, order, farthest = _scene(family, seed)
    rng = random.Random(seed)
    grid = StripGrid(occupied, targets + empty)
    picked = missed = 0
    for target in targets[:4] + rng.sample(empty, 12):
        for far in (0, farthest):
            ours = grid.pick(order, target, far)
            assert ours == reference.pick_mover(occupied, order, target, far), (target, far)
            picked += ours is not None
            missed += ours is None
        assert grid.nearest(order, target) == reference.nearest(occupied, order, target)
        for start in rng.sample(order, 6):
            assert grid.path(start, target) == reference.path_to(occupied, start, target)
    # Both outcomes and the cut-vertex pass were exercised, else the comparison
    # proves little.
    assert picked >= 10 and missed >= 1 and cut_passes


def test_the_grid_follows_its_owner():
    """A module put in or taken out changes the paths as it changes the set."""
    occupied, targets, empty, order, _ = _scene("blob", 5)
    grid = StripGrid(occupied, targets + empty)
    start, target = next((s, t) for t in empty for s in order
                         if reference.path_to(occupied, s, t))
    for cell in [c for c in empty if c != target][:8]:
        occupied.add(cell)
        grid.put(cell, True)
        assert grid.path(start, target) == reference.path_to(occupied, start, target)
    for cell in order[:8]:
        if cell != start:
            occupied.discard(cell)
            grid.put(cell, False)
            assert grid.path(start, target) == reference.path_to(occupied, start, target)


def test_a_one_off_path_is_the_reference_path():
    occupied, _, empty, order, _ = _scene("scramble", 4)
    for start, target in zip(order[::7], empty[::5], strict=False):
        assert path_to(occupied, start, target) == reference.path_to(occupied, start, target)


def test_the_c_searches_refuse_cells_off_the_grid():
    occupied, targets, _, order, _ = _scene("blob", 1)
    grid = StripGrid(occupied, targets)
    far = (anchor_of(occupied)[0] + 500, 0)
    with pytest.raises(ValueError, match="outside the grid"):
        grid.put(far, True)
    with pytest.raises(ValueError, match="outside the grid"):
        grid.pick(order, far, 0)
    with pytest.raises(TypeError, match="list of cells"):
        _strip.pick(grid._grid, tuple(order), targets[0], 0, 0)
    with pytest.raises(ValueError, match="size out of range"):
        _strip.grid(0, 0, 3, 3)


def test_a_move_made_in_c_is_the_move_the_dataclass_makes():
    from dataclasses import FrozenInstanceError, dataclass

    from hexbot.planning.hexlattice import ROTATIONS
    from hexbot.planning.moves import Move, new_move

    rule = ROTATIONS[3]
    args = (7, (1, 2), (2, 2), rule.joint, rule.direction, (1, 3), 9)
    made = new_move(*args)
    assert type(made) is Move and made == Move(*args) and hash(made) == hash(Move(*args))
    with pytest.raises(FrozenInstanceError):
        made.module = 8
    with pytest.raises(TypeError, match="7 arguments"):
        new_move(*args[:6])

    @dataclass
    class NoSlots:
        a: int = 0

    with pytest.raises(TypeError, match="slots"):
        _strip.set_move_type(NoSlots, ["a"] * 7)
    new_move(*args)  # the refused type changed nothing
