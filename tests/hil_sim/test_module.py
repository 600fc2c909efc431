"""Pin maps: selector lines as the listing's IrSel() drives them, actuator lines of Table 3-4."""

import pytest

from hexbot.hil_sim.geometry import CHANNEL_SIDE
from hexbot.hil_sim.module import decode_actuators, selector_index
from hexbot.hil_sim.plant import NEG, OFF, POS, SHORT

# IrSel(i) of Appendix A: the PORTA low bits it writes for each side (0 = centre).
IRSEL_PORTA = {1: 0b000, 6: 0b100, 0: 0b010, 2: 0b110, 5: 0b001, 3: 0b101, 4: 0b011}


@pytest.mark.parametrize("side,bits", IRSEL_PORTA.items())
def test_selector_decodes_irsel(side, bits):
    assert CHANNEL_SIDE[selector_index(0xE0 | bits)] == side


def test_actuator_lines():
    # J1 = PA2, J5 = PA0; S1 positive = PB0, S3 negative = PD7, S2 both lines = short
    joints, magnets = decode_actuators({"A": 0b101, "B": 0b1, "D": (1 << 7) | (1 << 5) | (1 << 3)})
    assert joints == (True, False, False, False, True, False)
    assert magnets == (POS, SHORT, NEG, OFF, OFF, OFF)


def test_the_comm_receivers_changes_say_since_when_it_is_on():
    # what the Python medium asks of a module's receiver (Air.rx_since)
    from hexbot.hil_sim.module import Module

    m = Module(1, None, None, None)  # type: ignore[arg-type]
    assert m.rx_since(100) == 0  # nothing known (the tests' cluster double): on
    m.record_rx([], 0)  # known: it boots off
    assert m.rx_since(100) is None
    m.record_rx([(60, True), (7000, False), (7071, True)], 0)  # RXEN set, a reset, set
    assert [m.rx_since(c) for c in (60, 61, 7000, 7001, 7071, 7072)] == [
        None, 60, 60, None, None, 7071]
    m.record_rx([(9000, False)], 8000)  # what is older than 8000 folds into one entry
    assert m.rx_since(8500) == 7071 and m.rx_since(9001) is None
    assert len(m._rx) == 2
