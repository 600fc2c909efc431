"""pytest plugin: hardware-in-the-loop regressions on the simulated cluster.

Installed with the ``hexbot`` distribution (entry point ``pytest11``:
``hexbot_sim``). A test asks for the ``hexbot_sim`` fixture and gets a
:class:`~hexbot.hil_sim.Simulator` in virtual time, booted from a scenario::

    import pytest

    @pytest.mark.hexbot_scenario("pair", seed=3)
    def test_ack(hexbot_sim):
        hexbot_sim.expect(b"COMM. LISTENING ID=02", timeout=30)  # booted
        hexbot_sim.pc_write(b"*E\x01NNNNNNN#")  # Select(1)
        hexbot_sim.expect(b"M01: ACKE", timeout=5)

A test that talks to the modules the way a PC does asks for
``hexbot_session`` instead: a :class:`~hexbot.host.session.Session` on a
stepped ``hexbot-sim://`` port (virtual time), the cluster booted (every
module's ``COMM. LISTENING`` heard), closed after the test::

    from hexbot.host.session import select
    from hexbot.protocol.frames import make

    @pytest.mark.hexbot_scenario("pair", seed=3)
    def test_status(hexbot_session):
        hexbot_session.request(select(2))
        (reply,) = hexbot_session.request(make("Status")).replies
        assert reply.event.module_id == 2

What only the simulator knows (pins, positions, debug ports) is behind
``hexbot_session.host.simulator`` (its ``.simulator`` is the
:class:`~hexbot.hil_sim.Simulator`).

Without the marker the scenario is ``--hexbot-scenario`` (default ``single``).
A HexBot script named ``test_*.hbs`` is collected as a test file: one
test per step (``line 12: Localize``), run in order on one booted session of
the scenario its ``# scenario: NAME`` line names (else
``--hexbot-scenario``); after a failed step the rest are skipped. pytest's
``--junitxml`` then lists every step with its time, as ``hexbot run
--junit`` does.

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
from contextlib import contextmanager
from pathlib import Path
from typing import Any

import pytest


def pytest_addoption(parser: pytest.Parser) -> None:
    group = parser.getgroup("hexbot_sim", "HexBot HIL simulator")
    group.addoption(
        "--hexbot-scenario",
        default="single",
        help="scenario (built-in name or TOML path) of the hexbot_sim and hexbot_session fixtures",
    )
    group.addoption(
        "--hexbot-events-dir",
        default=None,
        help="write each test's simulator events to DIR/<test>.jsonl",
    )


def pytest_configure(config: pytest.Config) -> None:
    config.addinivalue_line(
        "markers",
        "hexbot_scenario(name, seed=None): scenario and seed of the hexbot_sim "
        "and hexbot_session fixtures",
    )


@pytest.fixture
def _hexbot_events(request: pytest.FixtureRequest) -> Iterator[list[Any]]:
    """The simulators a test built; their events go to ``--hexbot-events-dir``."""
    built: list[Any] = []
    yield built
    folder = request.config.getoption("--hexbot-events-dir")
    if folder:
        Path(folder).mkdir(parents=True, exist_ok=True)
        stem = re.sub(r"[^A-Za-z0-9_.-]+", "_", request.node.nodeid)
        for index, sim in enumerate(built):
            suffix = f"-{index}" if index else ""
            with (Path(folder) / f"{stem}{suffix}.jsonl").open("w", encoding="utf-8") as out:
                for event in sim.events:
                    out.write(json.dumps(event) + "\n")


def _marked(request: pytest.FixtureRequest) -> tuple[str, int | None]:
    marker = request.node.get_closest_marker("hexbot_scenario")
    scenario = request.config.getoption("--hexbot-scenario")
    seed = None
    if marker is not None:
        if marker.args:
            scenario = marker.args[0]
        seed = marker.kwargs.get("seed")
    return scenario, seed


@pytest.fixture
def hexbot_sim_factory(_hexbot_events: list[Any]) -> Callable[..., Any]:
    """Build simulators: ``factory(scenario, seed=None, **simulator_options)``."""
    from hexbot.hil_sim import Simulator, load_scenario

    def factory(scenario: str | Path, seed: int | None = None, **kwargs: Any) -> Any:
        sim = Simulator(load_scenario(scenario), seed, **kwargs)
        _hexbot_events.append(sim)
        return sim

    return factory


@pytest.fixture
def hexbot_sim(request: pytest.FixtureRequest, hexbot_sim_factory: Callable[..., Any]) -> Any:
    """A booting simulator (t = 0) of the marked scenario."""
    return hexbot_sim_factory(*_marked(request))


@contextmanager
def booted_session(scenario: str, seed: int | None) -> Iterator[Any]:
    """A :class:`~hexbot.host.session.Session` on a stepped ``hexbot-sim://``
    port of ``scenario``, every module booted; closed on exit."""
    from hexbot.errors import HexBotTimeoutError
    from hexbot.host.endpoints import sim_url
    from hexbot.host.host import IR, Host
    from hexbot.host.link import PortSettings
    from hexbot.host.session import Session

    host = Host(None)  # no session log
    try:
        host.add_port(IR, PortSettings(sim_url(str(scenario), seed, 0.0)))
        host.start(5.0)
        ids = host.simulator.module_ids()
        session = Session(host, ids)
        heard, answered = session.boot(ids)
        missing = set(ids) - heard - answered
        if missing:
            raise HexBotTimeoutError(f"{scenario}: modules {sorted(missing)} sent no boot "
                                     "text heard whole and did not answer a Status")
        yield session
    finally:
        host.close()


@pytest.fixture
def hexbot_session(request: pytest.FixtureRequest, _hexbot_events: list[Any]) -> Iterator[Any]:
    """A :class:`~hexbot.host.session.Session` on a stepped ``hexbot-sim://``
    port of the marked scenario, every module booted; closed after the test."""
    with booted_session(*_marked(request)) as session:
        _hexbot_events.append(session.host.simulator.simulator)
        yield session


def pytest_collect_file(file_path: Path, parent: pytest.Collector) -> pytest.Collector | None:
    """``test_*.hbs`` scripts are collected as tests, one per step."""
    if file_path.suffix == ".hbs" and file_path.name.startswith("test_"):
        from hexbot.hil_sim.pytest_scripts import ScriptFile

        return ScriptFile.from_parent(parent, path=file_path)
    return None
