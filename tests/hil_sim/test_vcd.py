"""hil_sim.vcd: pyvcd writes the trace the hand-written writer it replaced wrote.

The golden file was made by that writer from the same random pin changes.
Only the first two lines differ (pyvcd sorts the header keywords and writes
"1 us"); see docs/simulator.md.
"""

import io
import random
from pathlib import Path
from types import SimpleNamespace

from hexbot.hil_sim.vcd import VcdWriter

GOLDEN = Path(__file__).parent / "data" / "vcd_two_modules_seed1.vcd"


def fake_sim(modules: int) -> SimpleNamespace:
    """What VcdWriter reads of a Simulator."""
    return SimpleNamespace(modules=dict.fromkeys(range(1, modules + 1)), hz=1_000_000, cycle=0,
                           scenario=SimpleNamespace(name="two-modules"), pin_sinks=[])


def trace(writer=VcdWriter, seed: int = 1, modules: int = 2, count: int = 400) -> str:
    """Random port writes, some at cycle 0, some in the same microsecond."""
    rng = random.Random(seed)
    cycle, changes = 0, []
    for _ in range(count):
        cycle += rng.choice((0, 0, 1, 7, 500, 12_345))
        changes.append((cycle, rng.randint(1, modules), rng.choice(("comm", "control")),
                        rng.choice("ABCDE"), rng.randrange(256)))
    sim, out = fake_sim(modules), io.StringIO()
    vcd = writer(sim, out)
    for i in range(0, count, 50):
        for sink in sim.pin_sinks:
            sink(changes[i:i + 50])
    sim.cycle = cycle + 20_000
    vcd.close()
    assert sim.pin_sinks == []
    return out.getvalue()


def test_trace_is_the_hand_written_writers_but_for_the_timescale_line():
    got, want = trace().splitlines(), GOLDEN.read_text().splitlines()
    assert want[:2] == ["$version hexbot hil_sim $end", "$timescale 1us $end"]
    assert got[:2] == ["$timescale 1 us $end", "$version hexbot hil_sim $end"]
    assert got[2:] == want[2:]


def test_no_date_so_runs_are_byte_identical():
    assert trace() == trace()
    assert "$date" not in trace()
