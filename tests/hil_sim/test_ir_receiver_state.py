"""The receiving comm board's own USART through the whole simulator, with
the IR medium in the core and in Python (``Simulator(ir_in_c=False)``, as
with faults): two modules on small AVR programs (avr/irnode.c, avr/irrx.c;
the control boards run avr/quiet.c), module 1 sending to module 2 on the
sides that face. Both media must leave the receiver with the same bytes,
events and ``rx_dropped`` (docs/simulator.md, "The receiver's own USART")."""

from __future__ import annotations

from pathlib import Path

import pytest
from test_core_ir_medium import BIT, FRAME, selector_pins
from test_core_uart import build

from hexbot.hil_sim.geometry import SIDE_CHANNEL
from hexbot.hil_sim.scenario import Firmware, ModuleSpec, Scenario
from hexbot.hil_sim.simulator import Simulator
from hexbot.protocol.timing import BAUD_TOLERANCE

#: module 1's byte (its firmware starts it at cycle 94): the middle of its
#: stop bit, where the core hands it over, and its end
HORIZON = 94 + 9 * BIT + BIT // 2
END = 94 + 10 * BIT


def two_modules(ir_in_c: bool, receiver: str = "irnode", rxen: bool = True,
                send: bytes = b"\x5a") -> tuple[Simulator, int, int]:
    """Module 1 at (0, 0) sends ``send`` on its side 3 at boot; module 2
    at (1, 0) listens on its side 6. Returns the simulator and the two comm
    boards' MCU indices; module 2's reports (0x80 | FE, byte per byte it
    received) are watched on its UART0."""
    quiet = Path(build("quiet"))
    modules = [ModuleSpec(1, (0, 0), 0, Firmware(Path(build("irnode")), quiet), 0),
               ModuleSpec(2, (1, 0), 0, Firmware(Path(build(receiver)), quiet), 0)]
    sim = Simulator(Scenario("two", modules, base=1), seed=1, ir_in_c=ir_in_c)
    assert sim.ir_in_c == ir_in_c
    a, b = (sim.modules[m].comm.index for m in (1, 2))
    c = sim.cluster
    c.write_eeprom(a, 0, (send + b"\xff\xff")[:2] + b"\xff\x01")
    c.set_input(a, "C", 0x07, selector_pins(SIDE_CHANNEL[3]))
    if receiver == "irnode":
        c.write_eeprom(b, 0, b"\xff\xff\xff" + bytes([rxen]))
    c.set_input(b, "C", 0x0F, selector_pins(SIDE_CHANNEL[6]) | (0 if rxen else 0x08))
    c.watch_uart(b, 0)
    return sim, a, b


def report_starts(sim: Simulator, b: int) -> list[tuple[int, int]]:
    """(start, byte) of each report frame module 2's firmware began."""
    return [(start, value) for start, _, value in sim.cluster.uart_take(b, 0)]


def ir_events(sim: Simulator) -> list[tuple[str, object, object, int]]:
    return [(e["event"], e["from"], e["to"], e["byte"]) for e in sim.events
            if e["event"].startswith("ir-")]


@pytest.mark.parametrize("ir_in_c", [True, False])
def test_byte_arrives_whole_with_either_medium(ir_in_c):
    sim, _, b = two_modules(ir_in_c)
    sim.run_to_cycle(4 * FRAME)
    reports = report_starts(sim, b)
    assert [v for _, v in reports] == [0x80, 0x5A]
    # the core hands it over at the middle of the stop bit, the Python
    # medium at the boundary after its end
    assert HORIZON <= reports[0][0] < (HORIZON + 100 if ir_in_c else END + 2_000)
    assert ir_events(sim) == []


@pytest.mark.parametrize("ir_in_c", [True, False])
@pytest.mark.parametrize("delay", [2, 200])
def test_receiver_reset_after_the_horizon_gets_no_phantom_byte(ir_in_c, delay):
    # The byte is the receiver's at the horizon: the core puts it into its
    # receive buffer there, and the reset flushes it (or the firmware read
    # it already: 200 cycles after, its report has begun). The Python
    # medium hands bytes over at the boundary after their end; before, it
    # judged the receiver at the horizon only and put the byte into the
    # buffer of the rebooted firmware, which reported a byte it never had.
    sim, _, b = two_modules(ir_in_c)
    sim.run_to_cycle(HORIZON + delay)
    sim.cluster.reset(b)
    sim.run_to_cycle(4 * FRAME)
    assert [r for r in report_starts(sim, b) if r[0] > HORIZON + delay] == []
    assert ir_events(sim) == []  # the core logs no drop: the byte was had, then flushed
    assert sim.cluster.uart_config(b, 1)["rx_dropped"] == 0


@pytest.mark.parametrize("ir_in_c", [True, False])
def test_rxen_cleared_and_set_after_the_horizon_flushes_the_byte(ir_in_c):
    # irrx.c: RXEN follows PC3. The firmware reads PC3 just before the
    # horizon and clears RXEN 4 cycles after it, before it looks at RXC;
    # set again 500 cycles later, before the Python medium's hand-over: the
    # byte went with the buffer in both media (before, the Python medium
    # handed it to the receiver, on again, and it reported it).
    sim, _, b = two_modules(ir_in_c, receiver="irrx")
    sim.run_to_cycle(HORIZON - 10)
    sim.cluster.set_input(b, "C", 0x08, 0x08)
    sim.run_to_cycle(HORIZON + 500)
    sim.cluster.set_input(b, "C", 0x08, 0)
    sim.run_to_cycle(4 * FRAME)
    offs = [cycle for cycle, on in sim.modules[2]._rx or () if not on]
    assert offs[-1] == HORIZON + 4  # on at the horizon, off right after it
    assert report_starts(sim, b) == []
    assert ir_events(sim) == []
    assert sim.cluster.uart_config(b, 1)["rx_dropped"] == 0


@pytest.mark.parametrize("ir_in_c", [True, False])
@pytest.mark.parametrize("back_on", [None, HORIZON + 100])
def test_byte_for_a_receiver_off_at_the_horizon_is_counted_as_dropped(ir_in_c, back_on):
    # Off at the horizon: lost, an ir-dropped event, and the USART's
    # rx_dropped counts it, in both media (before, the Python medium did not
    # count it: it never reached the USART). On again before the Python
    # medium's hand-over, it still does not get it.
    sim, _, b = two_modules(ir_in_c, receiver="irrx", rxen=False)
    if back_on is not None:
        sim.run_to_cycle(back_on)
        sim.cluster.set_input(b, "C", 0x08, 0)
    sim.run_to_cycle(4 * FRAME)
    assert report_starts(sim, b) == []
    assert ir_events(sim) == [("ir-dropped", 1, 2, 0x5A)]
    assert sim.cluster.uart_config(b, 1)["rx_dropped"] == 1


PC_BYTE = round(10 * 1_000_000 / 300)  # Simulator._ir_frame_cycles: the PC's bit is a tenth


@pytest.mark.parametrize("hz", [955_400, 955_407, 1_045_440, 1_045_448, 1_045_452, 1_045_460])
def test_pc_byte_near_the_baud_tolerance_is_judged_alike_by_both_media(hz):
    # The PC's bit time is its byte's length over its bits (3,333.3 cycles)
    # in both media, compared in cycles with the receiver's as the core's
    # m162_usart_frame_ok does. Before, the Python medium compared bauds
    # (300 against the receiver's), so at 955,407 Hz the core garbled the
    # byte and the Python medium took it, at 1,045,448 and 1,045,452 the
    # reverse.
    sent, own = PC_BYTE / 10, 16 * 208 * 1_000_000 / hz
    in_tolerance = abs(sent - own) <= BAUD_TOLERANCE * sent
    got = {}
    for ir_in_c in (True, False):
        quiet = Path(build("quiet"))
        spec = ModuleSpec(1, (0, 0), 0, Firmware(Path(build("irnode")), quiet), 0)
        sim = Simulator(Scenario("one", [spec], base=1), seed=1, ir_in_c=ir_in_c)
        m = sim.modules[1].comm.index
        sim.cluster.set_clock(m, hz)
        sim.cluster.set_input(m, "C", 0x07, selector_pins(SIDE_CHANNEL[0]))  # the centre
        sim.cluster.watch_uart(m, 0)
        sim.run_to_cycle(2_000)
        sim.pc_write(b"\x5a")
        sim.run_to_cycle(2_000 + 3 * FRAME)
        got[ir_in_c] = (sim.events, [v for _, _, v in sim.cluster.uart_take(m, 0)])
    assert got[True] == got[False]
    events, reports = got[True]
    assert [e["event"] for e in events] == ([] if in_tolerance else ["ir-garbled"])
    # beyond the tolerance 0x5A still samples right: it keeps a framing error
    assert reports == [0x80 | (not in_tolerance), 0x5A]
    assert in_tolerance == (hz in (1_045_440, 1_045_448, 1_045_452))


def test_receiver_log_overflow_is_reported():
    # The core keeps the last 64 changes of a receiver between two looks of
    # the simulator; the Python medium judges bytes by them. Firmware that
    # switches RXEN more often within one run loses the older ones: the
    # simulator says so (an error event) instead of judging bytes silently
    # by a wrong state.
    sim, _, b = two_modules(False, receiver="irrx", send=b"")
    sim.run_to_cycle(1_000)
    assert [e for e in sim.events if e["event"] == "sim-error"] == []
    c = sim.cluster
    for k in range(70):  # behind the simulator's back: no look in between
        c.set_input(b, "C", 0x08, 0x08 if k % 2 == 0 else 0)
        c.run(c.cycle + 200)
    lost = c.uart_config(b, 1)["rx_log_lost"]
    assert lost == 70 - 64
    sim.run_to_cycle(c.cycle + 1_000)
    [error] = [e for e in sim.events if e["event"] == "sim-error"]
    assert error["module"] == 2 and f"{lost} RXEN changes lost" in error["reason"]
    sim.run_to_cycle(sim.cycle + 1_000)
    assert len([e for e in sim.events if e["event"] == "sim-error"]) == 1  # said once
