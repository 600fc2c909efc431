"""``hexbot traverse --execute``: the cluster a map becomes (its size limit,
its reference module) and the plan of a run that did not reach the goal."""

from __future__ import annotations

from hexbot.planning.traversal.bridges import find_bridge_cells
from hexbot.planning.traversal.cli import resolve_map
from hexbot.planning.traversal.engine import traverse
from hexbot.planning.traversal.execute import MAX_MODULES, Cluster, cluster_of, rounds_plan
from hexbot.planning.traversal.surface import parse_map
from hexbot.protocol.lattice import distance


def test_a_cluster_of_exactly_63_modules_is_accepted():
    # legacy Select frames address modules 1..63: 61 surface modules and two
    # movers fit, the limit itself included
    width = MAX_MODULES - 2
    top = "M M " + ". " * (width - 4) + "G G"
    surface = parse_map(f"{top}\n{' '.join('S' * width)}\n", "wide.txt")
    assert len(surface.surface) + surface.n == 63
    cluster = cluster_of(surface)
    assert sorted(cluster.ids.values()) == list(range(3, 64))


def test_the_reference_is_the_surface_cell_with_the_fewest_hops_to_the_farthest_module():
    # localization is a wave from the reference and the firmware gives up on
    # modules it does not reach in time: the reference minimises the farthest
    # hop count (for hil-basic-2 and hil-three not the cell of least total)
    for name in ("hil-basic-2", "hil-three"):
        cluster = cluster_of(resolve_map(name))
        everyone = cluster.surface.surface | cluster.surface.modules

        farthest = {cell: max(distance(cell, other) for other in everyone)
                    for cell in cluster.surface.surface}
        assert farthest[(0, 0)] == min(farthest.values()), name


def test_the_plan_of_a_run_that_breaks_an_invariant_is_not_reached():
    # basic-5 without bridges: two modules meet in the narrow pocket. Its
    # rounds as a plan (ids as --execute gives them, without the size limit)
    # must not claim the goal.
    surface = resolve_map("basic-5")
    result = traverse(find_bridge_cells(surface, bridges=False))
    assert result.status == "violation"
    ids = {cell: surface.n + k for k, cell in enumerate(sorted(surface.surface), start=1)}
    plan = rounds_plan(Cluster(surface, ids, min(ids.values())), result)
    assert not plan.reached and plan.reason == result.reason
