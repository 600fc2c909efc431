"""The simulator loop against a scripted Cluster double (no firmware): wiring, pacing,
selector history, actuator decoding. The real extension is exercised in test_e2e_*.py."""

import sys

import pytest
from cluster_double import ClusterDouble, pair_on_dummy_images

from hexbot.errors import HexBotError, ScenarioError
from hexbot.hil_sim import Simulator, load_scenario
from hexbot.hil_sim.scenario import Firmware, Scenario

CENTRE_PORTA = 0xE0 | 0b010  # Y2
SIDE4_PORTA = 0xE0 | 0b011  # Y6
SIDE1_PORTA = 0xE0  # Y0


@pytest.fixture
def pair(tmp_path):
    scenario = pair_on_dummy_images(tmp_path)
    double = ClusterDouble()
    return Simulator(scenario, cluster=double), double


def test_wiring_of_a_module(pair):
    sim, c = pair
    assert c.names == ["comm1", "control1", "comm2", "control2"]
    assert (0, 0, 1, 0) in c.wires and (2, 0, 3, 0) in c.wires
    assert c.inputs[(1, "C")] == 1 and c.inputs[(3, "C")] == 2
    assert {(0, 1), (1, 1), (2, 1), (3, 1)} <= c.watched


def test_pc_bytes_are_paced_at_300_baud_to_centre_listeners(pair):
    sim, c = pair
    c.script_pin(0, 10, "A", CENTRE_PORTA)
    c.script_pin(2, 10, "A", SIDE4_PORTA)
    sim.pc_write(b"*AB")
    sim.run(0.2)
    assert c.received[(0, 1)] == [(33_333, 42, False), (66_666, 65, False), (99_999, 66, False)]
    assert c.received[(2, 1)] == []


def test_module_reply_on_centre_reaches_the_pc_and_side_bytes_the_neighbour(pair):
    sim, c = pair
    c.script_pin(2, 0, "A", CENTRE_PORTA)  # module 2 talks to the PC ...
    c.script_pin(2, 50_000, "A", SIDE4_PORTA)  # ... then to module 1 on its side 4
    c.script_pin(0, 0, "A", SIDE1_PORTA)  # module 1 listens on side 1, facing module 2
    c.script_tx(2, 1, 1_000, ord("M"))
    c.script_tx(2, 1, 60_000, ord("*"))
    sim.run(0.3)
    assert sim.pc_read() == b"M"
    assert [b for _, b, _ in c.received[(0, 1)]] == [ord("*")]


def test_actuator_pins_move_the_mobile(pair):
    sim, c = pair
    ms = 1000
    # mobile (control MCU 3): CW about joint 4 -> J5 = PA0, J4 = PA4; S3-, S4- = PD7, PB4
    c.script_pin(3, 0, "A", 0b0000_0001)
    c.script_pin(3, 80 * ms, "D", 1 << 7)
    c.script_pin(3, 80 * ms, "B", 1 << 4)
    c.script_pin(3, 125 * ms, "A", 0b0001_0001)
    c.script_pin(3, 215 * ms, "A", 0)
    c.script_pin(3, 216 * ms, "D", 0)
    c.script_pin(3, 216 * ms, "B", 0)
    # substrate (control MCU 1): J1, J2 = PA2, PA3; S1- = PD6, S2+ = PD3
    c.script_pin(1, 0, "A", 0b0000_1100)
    c.script_pin(1, 80 * ms, "D", (1 << 6) | (1 << 3))
    c.script_pin(1, 120 * ms, "A", 0)
    c.script_pin(1, 216 * ms, "D", 0)
    sim.run(1.0)
    moved = [e for e in sim.events if e["event"] == "moved"]
    assert moved == [{"t": 0.216, "event": "moved", "module": 2, "from": [-1, 1], "to": [0, 1],
                      "orientation": 2, "joint": 4, "substrate": 1, "direction": "CW"}]
    assert sim.modules[2].position == (0, 1) and sim.modules[2].orientation == 2


def test_debug_port_both_ways(pair):
    sim, c = pair
    c.script_tx(1, 1, 100, ord("A"), baud=4807.7)
    sim.debug_write(1, b"xy")
    sim.run(0.05)
    assert sim.debug_read(1) == b"A"
    assert [b for _, b, _ in c.received[(1, 1)]] == [ord("x"), ord("y")]


def test_run_until_times_out_in_virtual_time(pair):
    sim, _ = pair
    with pytest.raises(TimeoutError):
        sim.run_until(lambda s: False, timeout=0.5)
    assert sim.time == pytest.approx(0.5)


def test_missing_image_names_scenario_line_and_fix(tmp_path):
    scenario = Scenario("x", load_scenario("single").modules, path=tmp_path / "x.toml")
    scenario.modules = [type(m)(m.id, m.position, m.orientation,
                                Firmware(tmp_path / "no.elf", tmp_path / "no.elf"), 9)
                        for m in scenario.modules]
    with pytest.raises(ScenarioError, match=r"x\.toml:9: .*make -C firmware"):
        Simulator(scenario, cluster=ClusterDouble())


def test_missing_extension_says_how_to_build_it(monkeypatch):
    import hexbot.hil_sim

    monkeypatch.setitem(sys.modules, "hexbot.hil_sim._avr", None)
    monkeypatch.delattr(hexbot.hil_sim, "_avr", raising=False)
    with pytest.raises(HexBotError, match=r"pip install -e \."):
        Simulator(load_scenario("single"))
