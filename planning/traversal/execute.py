"""``hexbot traverse MAP --execute``: the rounds on a cluster, through the same
executor as ``hexbot plan --execute``.

The map becomes a cluster: the movers keep the engine's ids 1..n, the
surface modules follow in cell order. The central surface cell (fewest
hops to the farthest module: localization is a wave from it, and the
firmware gives up on modules it does not reach in time) is the reference
(it becomes (0, 0) when the cluster is localized, so the map is shifted
there) and the scenario's base: it never moves. The rounds become a
:class:`~hexbot.planning.plan.Plan` (one step per round) that
:func:`hexbot.planning.execute.execute` runs move by move with the host's
rotation workflow, each move verified against the plant. With neither
``--port`` nor ``--scenario`` the scenario is written from the map.
"""

from __future__ import annotations

from dataclasses import dataclass

from hexbot.errors import ScenarioError
from hexbot.planning.configuration import Configuration, Module
from hexbot.planning.moves import Move
from hexbot.planning.plan import Plan, Step
from hexbot.planning.traversal.engine import Result
from hexbot.planning.traversal.surface import Surface, shifted
from hexbot.protocol.lattice import Cell, distance

#: The legacy Select frame addresses modules 1..63 (wire.MAX_MODULE_ID is the DIP range).
MAX_MODULES = 63


@dataclass(frozen=True)
class Cluster:
    """The map as modules: ids by cell, the reference, the shifted map."""

    surface: Surface  # shifted: the reference cell is (0, 0)
    ids: dict[Cell, int]  # surface cells only; movers are the engine's 1..n
    reference: int


def cluster_of(surface: Surface) -> Cluster:
    total = len(surface.surface) + surface.n
    if total > MAX_MODULES:
        raise ScenarioError(f"{surface.name}: {total} modules (surface + movers); a cluster "
                            f"addressed by legacy Select frames holds at most {MAX_MODULES}")
    everyone = surface.surface | surface.modules
    ref_x, ref_y = min(surface.surface,
                       key=lambda c: (max(distance(c, o) for o in everyone), c))
    moved = shifted(surface, -ref_x, -ref_y)
    ids = {cell: surface.n + k for k, cell in enumerate(sorted(moved.surface), start=1)}
    return Cluster(moved, ids, ids[(0, 0)])


def scenario_toml(cluster: Cluster, movers: dict[int, Cell]) -> str:
    """A scenario file of the cluster (all orientations 0, the reference fixed)."""
    lines = [f'name = "traverse-{cluster.surface.name}"',
             f'description = "hexbot traverse {cluster.surface.name} --execute"',
             f"base = {cluster.reference}", ""]
    modules = sorted([*movers.items(), *((i, c) for c, i in cluster.ids.items())])
    for ident, (x, y) in modules:
        lines += ["[[module]]", f"id = {ident}", f"position = [{x}, {y}]", ""]
    return "\n".join(lines)


def rounds_plan(cluster: Cluster, result: Result) -> Plan:
    """The rounds as a plan over the whole cluster, one step per round."""
    cells = {cell: Module(i, 0) for cell, i in cluster.ids.items()}
    cells.update({cell: Module(i, 0) for i, cell in result.initial.items()})
    goal = frozenset(cluster.ids) | frozenset(result.final.values())
    steps = [Step([Move(r.module, r.src, r.dst, r.joint, r.direction,  # type: ignore[arg-type]
                        r.substrate, cluster.ids[r.substrate] if r.substrate_module is None
                        else r.substrate_module)
                   for r in moves])
             for moves in result.rounds if moves]
    return Plan("traverse", Configuration(cells), goal, steps,
                reached=result.status == "reached", reason=result.reason)
