"""Scenarios made to order: blobs and lines of any size, from a seed.

    from_name("blob:50")       50 modules grown at random around module 1
    from_name("line:12:3")     12 modules in a row, seed 3
    generate("blob", 255, seed=1)

A blob grows like a crystal (Eden growth): each new module takes a free cell
next to the cluster, drawn from the seeded generator, so blobs are compact
but irregular, as a cluster assembled by hand; module 1 is at the origin. A
line runs along the x axis (side 3), centred on the origin, ids 1..count
from its -x end. The module at the origin is fixed to the base; the other
orientations are drawn 0..5. The same shape, count and seed give the same
scenario.
"""

from __future__ import annotations

import random

from hexbot.errors import ScenarioError
from hexbot.protocol.wire import LOC_COORD_LIMIT, MAX_MODULE_ID

from .geometry import SIDES, Cell, neighbor
from .scenario import ModuleSpec, Scenario, load_scenario

SHAPES = ("blob", "line")


def _blob(count: int, rng: random.Random) -> list[Cell]:
    cells: list[Cell] = [(0, 0)]
    taken = {cells[0]}
    frontier: list[Cell] = []  # free neighbours, in the order first seen

    def grow_around(cell: Cell) -> None:
        for side in SIDES:
            other = neighbor(cell, side)
            if other not in taken and other not in frontier:
                frontier.append(other)

    grow_around(cells[0])
    while len(cells) < count:
        cell = frontier.pop(rng.randrange(len(frontier)))
        taken.add(cell)
        cells.append(cell)
        grow_around(cell)
    return cells


def _line(count: int) -> list[Cell]:
    cells: list[Cell] = [(-((count - 1) // 2), 0)]
    while len(cells) < count:
        cells.append(neighbor(cells[-1], 3))
    return cells


def generate(shape: str, count: int, seed: int = 1) -> Scenario:
    """``count`` modules in a ``shape`` ("blob" or "line"), drawn from ``seed``."""
    if shape not in SHAPES:
        raise ScenarioError(f"unknown shape {shape!r}: generated shapes are {', '.join(SHAPES)}")
    if not 1 <= count <= MAX_MODULE_ID:
        raise ScenarioError(f"{count} modules: a cluster has 1..{MAX_MODULE_ID} (8 DIP switches)")
    rng = random.Random(seed)
    cells = _blob(count, rng) if shape == "blob" else _line(count)
    far = max(max(abs(x), abs(y)) for x, y in cells)
    if far > LOC_COORD_LIMIT:
        raise ScenarioError(
            f"a {shape} of {count} modules reaches coordinate {far}, beyond +-{LOC_COORD_LIMIT} "
            "(MSG1 carries two decimal digits)"
        )
    firmware = load_scenario("single").modules[0].firmware
    base = cells.index((0, 0)) + 1
    modules = [
        ModuleSpec(i, cell, 0 if i == base else rng.randrange(6), firmware, 0)
        for i, cell in enumerate(cells, 1)
    ]
    return Scenario(f"{shape}:{count}:{seed}", modules, base=base, seed=seed,
                    description=f"generated {shape} of {count} modules, seed {seed}")


def from_name(name: str) -> Scenario:
    """``shape:count`` or ``shape:count:seed`` (seed 1 by default)."""
    parts = name.split(":")
    try:
        if len(parts) not in (2, 3):
            raise ValueError
        count = int(parts[1])
        seed = int(parts[2]) if len(parts) == 3 else 1
    except ValueError:
        raise ScenarioError(
            f"generated scenario {name!r}: write shape:count[:seed], e.g. blob:50 or line:12:3"
        ) from None
    return generate(parts[0], count, seed)
