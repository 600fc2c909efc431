"""pytest plugin: hardware-in-the-loop regressions on the simulated cluster.

Installed with the ``hexbot`` distribution (entry point ``pytest11``:
``hexbot_sim``). A test asks for the ``hexbot_sim`` fixture and gets a
:class:`~hexbot.hil_sim.Simulator` in virtual time, booted from a scenario::

    import pytest

    @pytest.mark.hexbot_scenario("pair", seed=3)
    def test_ack(hexbot_sim):
        hexbot_sim.pc_write(b"*FNNNNNNNN#")
        hexbot_sim.expect(b"ACKF", timeout=5)

Without the marker the scenario is ``--hexbot-scenario`` (default ``single``).
``hexbot_sim_factory(scenario, seed=None)`` builds more simulators in one
test (say, to compare two runs). ``--hexbot-events-dir DIR`` writes each
test's events as JSON lines to ``DIR/<test name>.jsonl``.

The C extension and the firmware images are only touched when a fixture is
used, so this plugin never breaks a test run that does not need them.
"""

from __future__ import annotations

import json
import re
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import pytest


def pytest_addoption(parser: pytest.Parser) -> None:
    group = parser.getgroup("hexbot_sim", "HexBot HIL simulator")
    group.addoption(
        "--hexbot-scenario",
        default="single",
        help="scenario (built-in name or TOML path) for the hexbot_sim fixture",
    )
    group.addoption(
        "--hexbot-events-dir",
        default=None,
        help="write each test's simulator events to DIR/<test>.jsonl",
    )


def pytest_configure(config: pytest.Config) -> None:
    config.addinivalue_line(
        "markers",
        "hexbot_scenario(name, seed=None): scenario and seed of the hexbot_sim fixture",
    )


@pytest.fixture
def hexbot_sim_factory(request: pytest.FixtureRequest) -> Iterator[Callable[..., Any]]:
    """Build simulators: ``factory(scenario, seed=None, **simulator_options)``."""
    from hexbot.hil_sim import Simulator, load_scenario

    built: list[Any] = []

    def factory(scenario: str | Path, seed: int | None = None, **kwargs: Any) -> Any:
        sim = Simulator(load_scenario(scenario), seed, **kwargs)
        built.append(sim)
        return sim

    yield factory
    folder = request.config.getoption("--hexbot-events-dir")
    if folder:
        Path(folder).mkdir(parents=True, exist_ok=True)
        stem = re.sub(r"[^A-Za-z0-9_.-]+", "_", request.node.nodeid)
        for index, sim in enumerate(built):
            suffix = f"-{index}" if index else ""
            with (Path(folder) / f"{stem}{suffix}.jsonl").open("w", encoding="utf-8") as out:
                for event in sim.events:
                    out.write(json.dumps(event) + "\n")


@pytest.fixture
def hexbot_sim(request: pytest.FixtureRequest, hexbot_sim_factory: Callable[..., Any]) -> Any:
    """A booting simulator (t = 0) of the marked scenario."""
    marker = request.node.get_closest_marker("hexbot_scenario")
    scenario = request.config.getoption("--hexbot-scenario")
    seed = None
    if marker is not None:
        if marker.args:
            scenario = marker.args[0]
        seed = marker.kwargs.get("seed")
    return hexbot_sim_factory(scenario, seed)
