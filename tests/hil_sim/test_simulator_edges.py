"""Edges of the simulator's Python layer a user of its API would notice:
pacing of several writes, bytes left after expect(), event matching and
times, debug-port events, generated scenario names. Against the scripted
Cluster double (no firmware), as test_simulator_unit.py."""

import pytest
from cluster_double import ClusterDouble, RadiosDouble, pair_on_dummy_images, uart_settings

from hexbot.errors import HexBotTimeoutError
from hexbot.hil_sim import Simulator, load_scenario
from hexbot.hil_sim.module import decode_actuators, decode_leds
from hexbot.hil_sim.plant import NEG, OFF, POS, SHORT
from hexbot.protocol.pins import (
    LED_JOINT_PINS,
    LED_SIDE_NEG_PINS,
    LED_SIDE_POS_PINS,
    MAGNET_NEG_PINS,
    MAGNET_POS_PINS,
)

CENTRE_PORTA = 0xE0 | 0b010  # Y2
PC_BYTE = 33_333  # cycles of one 300-baud byte
DEBUG_BYTE = 2_083  # one 4800-baud byte


@pytest.fixture
def pair(tmp_path):
    scenario = pair_on_dummy_images(tmp_path)
    double = ClusterDouble()
    return Simulator(scenario, cluster=double), double


def test_two_pc_writes_queue_back_to_back(pair):
    sim, c = pair
    c.script_pin(0, 10, "A", CENTRE_PORTA)
    sim.pc_write(b"A")
    sim.pc_write(b"B")  # before A is out: it waits for it
    sim.run(0.2)
    assert c.received[(0, 1)] == [(PC_BYTE, 65, False), (2 * PC_BYTE, 66, False)]


def test_two_debug_writes_queue_back_to_back(pair):
    sim, c = pair
    sim.debug_write(1, b"x")
    sim.debug_write(1, b"y")
    sim.run(0.05)
    assert [(t, b) for t, b, _ in c.received[(1, 1)]] == [(DEBUG_BYTE, 120),
                                                         (2 * DEBUG_BYTE, 121)]


def test_pc_read_after_expect_returns_the_bytes_after_the_pattern(pair):
    sim, c = pair
    c.script_pin(2, 0, "A", CENTRE_PORTA)
    for k, value in enumerate(b"OK?!"):
        c.script_tx(2, 1, 1_000 + k * PC_BYTE, value)
    sim.run(0.2)  # all four bytes are in
    assert sim.expect(b"OK", timeout=1) == b"OK"
    assert sim.pc_read() == b"?!"  # kept from expect(), not lost


def test_debug_port_at_a_wrong_baud_rate_is_reported_at_the_bytes_end(pair):
    sim, c = pair
    c.config[(1, 1)] = uart_settings(300.5)  # the control board's UART1 at 300 baud
    c.script_tx(1, 1, 1_234, ord("A"), baud=300.5)
    event = sim.wait_event("debug-garbled", timeout=1, module=1)
    end = 1_234 + round(10e6 / 300.5)
    assert event["t"] == round(end / 1e6, 6)  # to the microsecond
    # every field given must match, not one of them
    with pytest.raises(HexBotTimeoutError):
        sim.wait_event("debug-garbled", timeout=0.1, module=1, reason="something else")


def test_a_debug_byte_to_a_receiver_that_is_off_is_reported(pair):
    sim, c = pair
    c.config[(3, 1)] = uart_settings(4807.7, rxen=False)
    sim.debug_write(2, b"z")
    event = sim.wait_event("debug-dropped", timeout=1)
    assert (event["module"], event["byte"]) == (2, ord("z"))


def test_leds_are_lit_only_on_output_pins_driven_low():
    ddr = {p: 0 for p in "ABCDE"}
    ports = {p: 0 for p in "ABCDE"}
    assert decode_leds(ddr, ports) == {k: [0] * 6 for k in ("led_joints", "led_pos", "led_neg")}
    for port, bit in LED_SIDE_POS_PINS[:2]:
        ddr[port] |= 1 << bit
    port, bit = LED_SIDE_NEG_PINS[5]
    ddr[port] |= 1 << bit
    lit = decode_leds(ddr, ports)
    assert lit["led_pos"] == [1, 1, 0, 0, 0, 0]
    assert lit["led_neg"] == [0, 0, 0, 0, 0, 1]
    assert lit["led_joints"] == [0] * 6
    port, bit = LED_JOINT_PINS[2]
    ddr[port] |= 1 << bit
    assert decode_leds(ddr, ports)["led_joints"] == [0, 0, 1, 0, 0, 0]
    ports[port] |= 1 << bit  # driven high: dark
    assert decode_leds(ddr, ports)["led_joints"] == [0] * 6


def test_both_magnet_lines_on_read_as_a_short():
    ports = {p: 0 for p in "ABCDE"}
    for pins in (MAGNET_POS_PINS[0], MAGNET_NEG_PINS[0], MAGNET_POS_PINS[1],
                 MAGNET_NEG_PINS[2]):
        port, bit = pins
        ports[port] |= 1 << bit
    _, magnets = decode_actuators(ports)
    assert magnets == (SHORT, POS, NEG, OFF, OFF, OFF)


def test_generated_line_of_even_length_keeps_the_base_at_the_origin():
    scenario = load_scenario("line:4")
    assert [m.position for m in scenario.modules] == [(-1, 0), (0, 0), (1, 0), (2, 0)]
    assert scenario.base == 2


def test_generated_name_without_seed_uses_seed_one():
    assert load_scenario("blob:30").modules == load_scenario("blob:30:1").modules


def test_the_quantum_is_the_board_wires_lookahead():
    from hexbot.hil_sim.simulator import lookahead_cycles

    # start bit + 8 data bits + half a stop bit at 208 cycles a bit, on a clock
    # 5 % fast: 1,881 cycles; a longer quantum delivers wire bytes late
    assert lookahead_cycles() == 1881
    assert Simulator.from_name("single").cluster.quantum_cycles == 1881


class ResettingDouble(ClusterDouble):
    """The double with the core's reset log (``Cluster.resets``)."""

    def __init__(self) -> None:
        super().__init__()
        self.reset_at: dict[int, list[int]] = {}

    def resets(self, mcu: int) -> list[int]:
        due = [c for c in self.reset_at.get(mcu, []) if c <= self.cycle]
        self.reset_at[mcu] = [c for c in self.reset_at.get(mcu, []) if c > self.cycle]
        return due


def test_a_comm_board_reset_mid_byte_cuts_its_byte_with_the_python_medium(tmp_path):
    scenario = pair_on_dummy_images(tmp_path)
    c = ResettingDouble()
    sim = Simulator(scenario, cluster=c)
    c.script_pin(2, 0, "A", CENTRE_PORTA)
    c.script_tx(2, 1, 1_000, 0x00)
    bit = PC_BYTE / 10
    c.reset_at[2] = [round(1_000 + 5 * bit) + 50]  # in data bit 4: the USART stops
    c.script_pin(2, 1_000 + 6 * 3_333, "A", 0)  # (the reset clears PORTA)
    sim.run(0.1)
    assert sim.pc_read() == b"\xf0"  # bits 4..7 and the stop bit read idle high


def test_a_selector_write_on_the_bytes_first_cycle_sends_it_on_the_new_side(pair):
    sim, c = pair
    c.script_pin(2, 1_000, "A", CENTRE_PORTA)  # written on the start bit's cycle
    c.script_tx(2, 1, 1_000, ord("A"))
    sim.run(0.1)
    assert sim.pc_read() == b"A"


def test_the_comm_receiver_went_off_only_by_an_off_change_after_the_moment(pair):
    sim, _ = pair
    module = sim.modules[1]
    module.record_rx([(100, True), (300, False), (500, True)], 0)
    assert module.rx_went_off(200)       # off at 300
    assert not module.rx_went_off(400)   # only came on (500) since


# --- the radio air (radio.py) ---------------------------------------------------

CH = (1, 1600, 71)


def radio_medium(cells):
    from hexbot.hil_sim.radio import RadioMedium

    radios, events = RadiosDouble(cells, CH), []
    med = RadioMedium(radios, {i: i for i in cells}, cells.__getitem__, 5, 1,
                      lambda cycle, e: events.append(e))
    for i in cells:
        radios.state[i]["receiving"] = i == 3
    return radios, med, events


def test_radio_bytes_back_to_back_from_two_senders_do_not_collide():
    radios, med, events = radio_medium({1: (0, 0), 2: (1, 0), 3: (2, 0)})
    radios.logs[1] = [(0, 1670, 0x55, False, CH)]
    radios.logs[2] = [(1670, 3340, 0x66, False, CH)]  # starts as the first ends
    med.step(3340)
    assert radios.delivered == [(3, 1670, 0x55), (3, 3340, 0x66)]
    assert med.garbled == 0 and events == []


def test_one_radio_collision_event_per_receiver_while_the_collision_lasts():
    radios, med, events = radio_medium({1: (0, 0), 2: (1, 0), 3: (2, 0)})
    for k in range(3):  # three bytes each, overlapping pairwise
        radios.logs[1].append((k * 1670, (k + 1) * 1670, 0x55, False, CH))
        radios.logs[2].append((k * 1670 + 100, (k + 1) * 1670 + 100, 0x66, False, CH))
    med.step(4 * 1670)
    assert med.garbled == 6
    assert events == [{"event": "radio-collision", "module": 3, "senders": [1, 2]}]


def test_the_pc_radio_paces_packets_at_the_rate_the_bridge_passes_them_on():
    from hexbot.hil_sim.radio import PcRadio
    from hexbot.protocol import radio as rf

    pc = PcRadio((0, 0), 1_000_000)
    data = bytes(range(2 * rf.LINK_BYTES))  # two full packets
    pc.write(data, 0)
    per_packet = len(rf.packet(rf.payloads(data)[0]))
    first, second = pc.tx[0][0], pc.tx[per_packet][0]
    # the bridge sends each link byte on at 300 baud (33,333 cycles) before the next packet
    assert second - first >= rf.LINK_BYTES * 33_333


# --- hexbot sim (cli_sim.py) ----------------------------------------------------

def sim_args(*argv: str):
    import argparse

    from hexbot.hil_sim import cli_sim

    parser = argparse.ArgumentParser()
    cli_sim.add_arguments(parser)
    return parser.parse_args(list(argv))


def test_sim_duration_stops_at_the_duration_not_at_the_next_slice(monkeypatch, capsys):
    from hexbot.hil_sim import cli_sim

    made = []

    class Recorded(Simulator):
        def __init__(self, *args, **kwargs):
            super().__init__(*args, **kwargs)
            made.append(self)

    monkeypatch.setattr(cli_sim, "Simulator", Recorded)
    assert cli_sim.run(sim_args("single", "--duration", "0.015", "--speed", "0")) == 0
    assert made[0].time == pytest.approx(0.015)


def test_sim_without_ports_or_duration_is_a_usage_error(monkeypatch):
    from hexbot.errors import UsageError
    from hexbot.hil_sim import cli_sim

    monkeypatch.setattr(cli_sim, "_loop", lambda *a: pytest.fail("ran with nothing to do"))
    with pytest.raises(UsageError, match="nothing to do"):
        cli_sim.run(sim_args("single"))


def test_sim_rfc2217_refuses_threads(monkeypatch):
    from hexbot.errors import UsageError
    from hexbot.hil_sim import cli_sim, urlhandler

    monkeypatch.setattr(urlhandler, "register", lambda: pytest.fail("went on serving"))
    with pytest.raises(UsageError, match="--threads"):
        cli_sim.run(sim_args("single", "--rfc2217", "0", "--threads", "2"))
