"""The IR medium in the core against the Python medium, on the real firmware:
the same localization outcome, the same trace for the same seed, and the
Python medium wherever faults are injected."""

from __future__ import annotations

import io
from dataclasses import replace

import pytest

from hexbot.hil_sim.geometry import CENTRE, CHANNEL_SIDE, facing, neighbor, to_global
from hexbot.hil_sim.scenario import Faults, load_scenario
from hexbot.hil_sim.simulator import Simulator
from hexbot.hil_sim.vcd import VcdWriter
from hexbot.protocol import parser
from hexbot.protocol.frames import encode_pc, make, select
from hexbot.protocol.timing import LOCALIZE_WINDOW_S, boot_seconds


def localize(sim: Simulator) -> dict[int, tuple[int, int, int]]:
    """Ref on module 1, Localize to all; per module the (x, y, Yref) it reported."""
    sim.run(boot_seconds(sim.modules))
    for frame, answer in ((select([1]), b"M01: ACKE"), (make("Ref"), b"S01: ACKA")):
        sim.pc_write(encode_pc(frame))
        sim.expect(answer, timeout=10.0)
    last = max(sim.modules)
    sim.pc_write(encode_pc(select([0])))
    sim.expect(f"M{last:02d}: ACKE".encode(), timeout=10.0)
    sim.pc_write(encode_pc(make("Localize")))
    # the flood window, then every module's report in the order of its id
    heard = sim.expect(f"M{last:02d}: ACKB".encode(), timeout=LOCALIZE_WINDOW_S + 40.0)
    sim.run(0.5)  # the line's end
    heard += sim.pc_read()
    found: dict[int, tuple[int, int, int]] = {}
    position: tuple[int, int] | None = None
    yref = None
    for event in parser.parse_all(heard):
        if isinstance(event, parser.PositionReport):
            position = (event.x, event.y)
        elif isinstance(event, parser.YrefReport):
            yref = event.yref
        elif isinstance(event, parser.Ack) and position is not None:
            found[event.module] = (*position, yref)
            position = yref = None
    return found


@pytest.fixture(scope="module")
def flower7():
    return load_scenario("flower7")


def test_core_medium_localizes_like_the_python_medium(flower7):
    in_c = Simulator(flower7, seed=3)
    in_python = Simulator(flower7, seed=3, ir_in_c=False)
    assert in_c.ir_in_c and not in_python.ir_in_c
    found = localize(in_c)
    assert found == localize(in_python)
    # and it is right: every module but the reference knows its cell and Yref
    assert sorted(found) == list(range(2, 8))
    for ident, (x, y, yref) in found.items():
        assert (x, y) == in_c.modules[ident].position
        assert yref == in_c.modules[ident].orientation
    # the only IR events: every module's first boot text at once, at the PC
    ir_events = [e for e in in_c.events if e["event"].startswith("ir-")]
    assert ir_events == [e for e in in_python.events if e["event"].startswith("ir-")]
    assert {e["to"] for e in ir_events} == {"pc"}


def run_traced(scenario, seed: int) -> tuple[dict, str]:
    sim = Simulator(scenario, seed=seed)
    out = io.StringIO()
    vcd = VcdWriter(sim, out)
    sim.run(boot_seconds(sim.modules))  # boot slots: texts to the PC, collisions
    sim.pc_write(encode_pc(select([0])))
    sim.run(2.0)
    vcd.close()
    return sim.trace(), out.getvalue()


def test_same_seed_same_trace_and_vcd_with_the_core_medium(flower7):
    # a clock spread moves every byte off the others' boundaries
    spread = replace(flower7, clock_spread_ppm=20_000)
    first, vcd_first = run_traced(spread, seed=5)
    again, vcd_again = run_traced(spread, seed=5)
    assert first == again
    assert vcd_first == vcd_again
    assert any(e["event"] == "ir-collision" for e in first["events"])  # boot slots overlap
    other, _ = run_traced(spread, seed=6)
    assert other != first  # the seed matters (clocks drawn from it)


def test_fault_injection_keeps_the_python_medium(flower7):
    noisy = replace(flower7, faults=Faults(byte_loss=0.01))
    assert not Simulator(noisy).ir_in_c
    one_link = replace(flower7, link_faults={(1, 2): Faults(bit_error_rate=0.001)})
    assert not Simulator(one_link).ir_in_c
    assert Simulator(flower7).ir_in_c


class ScriptedEvents:
    """The real core, with the next ir_events() answer scripted."""

    def __init__(self) -> None:
        from hexbot.hil_sim.simulator import _load_core, lookahead_cycles
        self.core = _load_core().Cluster(lookahead_cycles())
        self.script: list[tuple] = []

    def __getattr__(self, name: str):
        return getattr(self.core, name)

    def ir_events(self) -> list[tuple]:
        taken, self.script = self.script + self.core.ir_events(), []
        return taken


def test_core_events_are_worded_as_the_python_mediums(flower7):
    cluster = ScriptedEvents()
    sim = Simulator(flower7, seed=1, cluster=cluster)
    comm = {m: sim.modules[m].comm.index for m in sim.modules}
    cluster.script = [
        ("ir-collision", 2000, comm[3], comm[1], 0x3C, (comm[2], -1)),
        ("ir-dropped", 2500, -1, comm[4], 0x41, ()),
    ]
    sim.run(0.01)
    events = [e for e in sim.events if e["event"] in ("ir-collision", "ir-dropped")]
    assert events == [
        {"t": 0.002, "event": "ir-collision", "from": 3, "to": 1, "byte": 0x3C,
         "other": [2, "pc"]},
        {"t": 0.0025, "event": "ir-dropped", "from": "pc", "to": 4, "byte": 0x41,
         "reason": "receiver off (RXEN) or overrun"},
    ]


def test_core_routes_follow_the_plant(flower7):
    """Each comm board's routes name who the Python medium would deliver to,
    and are sent again when the plant moves a module."""
    sim = Simulator(flower7, seed=1)

    def expected(module_id: int) -> list[tuple]:
        module = sim.modules[module_id]
        routes: list[tuple] = []
        for y in range(8):
            channel = CHANNEL_SIDE[y]
            if channel is None:
                routes.append(("none",))
            elif channel == CENTRE:
                routes.append(("pc",))
            else:
                side = to_global(channel, module.orientation)
                other = sim.module_at(neighbor(module.position, side))
                if other is None:
                    routes.append(("none",))
                else:
                    # the Python medium: heard if the other's selector, as a
                    # global side, faces the sender
                    need = next(k for k in range(8) if CHANNEL_SIDE[k] not in (None, CENTRE)
                                and to_global(CHANNEL_SIDE[k], sim.modules[other].orientation)
                                == facing(side))
                    routes.append(("mcu", sim.modules[other].comm.index, need))
        return routes

    def routes(module_id: int) -> list[tuple]:
        return sim.cluster.ir_state(sim.modules[module_id].comm.index)["routes"]

    for module_id in sim.modules:
        assert routes(module_id) == expected(module_id)
    assert sum(r[0] == "mcu" for r in routes(1)) == 6  # the centre of the flower
    # move module 2 one cell out, turned, as a rotation would (plant bookkeeping)
    body = sim.plant.bodies[2]
    del sim.plant.cells[body.cell]
    body.cell = (body.cell[0] * 2, body.cell[1] * 2)
    body.orientation = (body.orientation + 2) % 6
    sim.plant.cells[body.cell] = 2
    sim.plant.geometry_version += 1
    sim.run(0.01)
    for module_id in sim.modules:
        assert routes(module_id) == expected(module_id)
    assert sum(r[0] == "mcu" for r in routes(1)) == 5
