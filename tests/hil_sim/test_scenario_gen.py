"""Generated scenarios: blobs and lines of any size, the same for the same seed."""

import pytest

from hexbot.errors import ScenarioError
from hexbot.hil_sim.geometry import SIDES, neighbor
from hexbot.hil_sim.scenario import load_scenario
from hexbot.hil_sim.scenario_gen import generate
from hexbot.protocol.wire import MAX_MODULE_ID


def connected(cells) -> bool:
    cells = set(cells)
    seen, todo = set(), [next(iter(cells))]
    while todo:
        cell = todo.pop()
        if cell in seen:
            continue
        seen.add(cell)
        todo += [n for n in (neighbor(cell, s) for s in SIDES) if n in cells]
    return seen == cells


@pytest.mark.parametrize("count", [1, 7, 50, MAX_MODULE_ID])
def test_blob_is_connected_with_ids_one_to_count(count):
    scenario = generate("blob", count, seed=4)
    cells = [m.position for m in scenario.modules]
    assert sorted(m.id for m in scenario.modules) == list(range(1, count + 1))
    assert len(set(cells)) == count and connected(cells)
    assert scenario.modules[0].position == (0, 0) and scenario.base == 1


def test_same_seed_same_blob_other_seed_other_blob():
    a, b, c = (load_scenario(n) for n in ("blob:40:2", "blob:40:2", "blob:40:3"))
    assert a.modules == b.modules
    assert [m.position for m in a.modules] != [m.position for m in c.modules]


def test_line_is_centred_with_the_base_at_the_origin():
    scenario = load_scenario("line:199")
    xs = [m.position[0] for m in scenario.modules]
    assert xs == list(range(-99, 100))
    base = next(m for m in scenario.modules if m.id == scenario.base)
    assert base.position == (0, 0) and base.orientation == 0


@pytest.mark.parametrize("name,problem", [
    ("line:200", "beyond +-99"),
    ("blob:256", "1..255"),
    ("blob:x", "shape:count"),
    ("ring:5", "unknown scenario"),
])
def test_bad_generated_names_are_clear_errors(name, problem):
    with pytest.raises(ScenarioError, match=problem.replace("+", r"\+")):
        load_scenario(name)


def test_clock_spread_is_seeded_and_explicit_clocks_win():
    scenario = generate("blob", 5, seed=1)
    scenario.clock_spread_ppm = 20_000
    first, again = scenario.clocks(7), scenario.clocks(7)
    assert first == again and first != scenario.clocks(8)
    assert all(abs(ppm) <= 20_000 for ppm in first.values())
    assert len(set(first.values())) == 10  # each board its own oscillator
