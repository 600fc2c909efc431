"""FINDBRIDGECELLS on the bank: the cases of Fig. 5, the placements derived in
docs/traversal.md, 3-bridges covering 1-2 bridges, and Theorem 1 on random
surfaces."""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from hexbot.errors import ScenarioError
from hexbot.planning.traversal.bank import random_surface
from hexbot.planning.traversal.bridges import find_bridge_cells, letters, theorem1_problems
from hexbot.planning.traversal.cli import resolve_map


# no SINGLE pocket of length 2 exists under the deformable model (docs/traversal.md)
@pytest.mark.parametrize(("case", "length"), [
    (case, length) for case in ("single", "basic", "left", "right")
    for length in (1, 2, 3, 5, 8) if (case, length) != ("single", 2)])
def test_each_pocket_is_classified_with_its_length(case, length):
    bmap = find_bridge_cells(resolve_map(f"{case}-{length}"))
    assert [(g.kind, g.pocket_length) for g in bmap.groups] == [(case.upper(), length)]


def test_basic_bridges_both_bi_cells_and_counts_passes_above_them():
    bmap = find_bridge_cells(resolve_map("basic-5"))
    (group,) = bmap.groups
    i, j = group.span
    x, y = bmap.layer1.cells[i], bmap.layer1.cells[j]
    assert group.bridge == (x, y)
    t = letters(x, y)
    assert group.pass_cells == {x: t.b, y: t.c}


def test_left_long_pocket_uses_temp_support_bridge_support():
    bmap = find_bridge_cells(resolve_map("left-5"))
    (group,) = bmap.groups
    i, j = group.span
    inside = bmap.layer1.cells[i + 1: j]
    t = letters(bmap.layer1.cells[i], bmap.layer1.cells[j])
    assert group.temp_support == inside[0]  # cellAt(pn(x) + 1)
    assert group.bridge == (t.g,) == (inside[-1],)  # cellAt(pn(y) - 1)
    assert group.support == inside[-2]


def test_short_left_and_right_pockets_take_one_bridge_cell():
    for name in ("left-2", "right-2"):
        bmap = find_bridge_cells(resolve_map(name))
        (group,) = bmap.groups
        i, j = group.span
        assert group.bridge == (bmap.layer1.cells[j - 1],) and group.temp_support is None


def test_a_three_bridge_covers_the_small_bridges_inside():
    surface = resolve_map("three-deep4")
    with_three = find_bridge_cells(surface)
    assert [g.kind for g in with_three.groups] == ["THREE"]
    assert with_three.groups[0].shape == "straight"
    assert any(g.kind != "THREE" for g in with_three.dropped)
    assert [g.kind for g in find_bridge_cells(surface, three=False).groups] == ["BASIC"]


def test_fig14_surface_has_every_kind():
    kinds = {g.kind for g in find_bridge_cells(resolve_map("fig14")).groups}
    assert kinds == {"SINGLE", "BASIC", "LEFT", "RIGHT", "THREE"}


@settings(max_examples=60, deadline=None)
@given(st.integers(min_value=0, max_value=10**6))
def test_theorem1_holds_for_every_bi_of_random_surfaces(seed):
    surface = random_surface(seed)
    try:
        bmap = find_bridge_cells(surface)
    except ScenarioError:  # digging closed the chain's perimeter: not a surface to test
        return
    for i, j in bmap.bis:
        x, y = bmap.layer1.cells[i], bmap.layer1.cells[j]
        assert theorem1_problems(surface.surface, x, y) == [], (seed, x, y)


@pytest.mark.parametrize(("name", "shape"), [
    ("three-deep4", "straight"), ("three-curved-left", "curved-left"),
    ("three-curved-right", "curved-right"), ("three-curved-symmetric", "curved-symmetric")])
def test_each_three_bridge_shape_is_detected_and_crossed(name, shape):
    from hexbot.planning.traversal.engine import traverse

    surface = resolve_map(name)
    bmap = find_bridge_cells(surface)
    assert [(g.kind, g.shape) for g in bmap.groups] == [("THREE", shape)]
    (group,) = bmap.groups
    # the three cells span the opening: u and v on layer1, w off it
    u, w, v = group.bridge
    assert u in bmap.layer1 and v in bmap.layer1 and w not in bmap.layer1
    result = traverse(bmap)  # every invariant is checked each round
    assert result.status == "reached", result.reason
    assert set(result.final.values()) == set(surface.goals)
    # its three modules stopped there: three Bridge leaves, one per cell
    leaves = [m.src for r in result.rounds for m in r if m.rule == "leave-bridge"]
    assert sorted(leaves) == sorted(group.bridge)
