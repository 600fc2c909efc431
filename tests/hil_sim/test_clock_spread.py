"""The real firmware on modules whose RC clocks differ by up to +-2 %.

Until the core ran each MCU on its own clock, every module shared one exact
clock and the firmware's boot slots and localization were only tested there.
These runs give each board a clock of its own: worst-case pairs for the boot
slots, a seeded spread for localization.
"""

import re
from dataclasses import replace

import pytest
from test_e2e_firmware import boot, send

from hexbot.hil_sim.scenario import load_scenario
from hexbot.hil_sim.scenario_gen import generate
from hexbot.hil_sim.simulator import Simulator
from hexbot.protocol.frames import make, select
from hexbot.protocol.timing import BOOT_SLOTS, CLOCK_SPREAD, boot_seconds

PPM = CLOCK_SPREAD * 1e6


@pytest.mark.parametrize("odd_ppm", [PPM, -PPM])
def test_boot_slots_hold_with_neighbouring_slots_at_opposite_clock_limits(odd_ppm):
    """Slot k slow and slot k + 1 fast (or the reverse): no boot text is lost."""
    scenario = generate("blob", BOOT_SLOTS, seed=2)
    scenario.modules[:] = [replace(m, clock_ppm=odd_ppm if m.id % 2 else -odd_ppm)
                           for m in scenario.modules]
    sim = Simulator(scenario)
    sim.run(boot_seconds(range(1, BOOT_SLOTS + 1)) * (1 + CLOCK_SPREAD))
    text = sim.pc_read()
    heard = re.findall(rb"COMM\. LISTENING ID=(\d\d)", text)
    assert sorted(int(i) for i in heard) == list(range(1, BOOT_SLOTS + 1))
    first_slot = 1.9  # the READY texts before the slots collide by design
    assert [e for e in sim.events if e["event"] == "ir-collision" and e["t"] > first_slot] == []


def spread(name: str, seed: int = 3):
    scenario = load_scenario(name)
    scenario.clock_spread_ppm = PPM
    return Simulator(scenario, seed)


def test_spread_gives_every_board_its_own_clock():
    sim = spread("flower7")
    clocks = [sim.cluster.clock(i) for i in range(sim.cluster.mcu_count)]
    assert len(set(clocks)) == len(clocks)
    assert all(abs(hz - sim.hz) <= PPM * sim.hz / 1e6 for hz in clocks)


@pytest.mark.parametrize("name,last", [("flower7", 7), ("thesis-fig5-8", 6)])
def test_localization_with_clock_spread(name, last):
    sim = spread(name)
    boot(sim)
    send(sim, select([1]), b"M01: ACKE")
    send(sim, make("Ref"), b"S01: ACKA")
    send(sim, select([0]), f"M{last:02d}: ACKE".encode())
    reports = send(sim, make("Localize"), f"M{last:02d}: ACKB".encode(), timeout=90)
    for module_id in range(2, last + 1):
        x, y = sim.modules[module_id].position
        assert f"Pos: {x:+03d}{y:+03d}".encode() in reports, module_id


def test_same_seed_same_trace_with_clock_spread():
    def trace():
        sim = spread("pair", seed=5)
        boot(sim)
        send(sim, select([1]), b"M01: ACKE")
        return sim.trace()

    assert trace() == trace()
