"""Pin maps of the two boards of a module (Tables 3-3, 3-4 and 3-5).

The firmware's board files take their pin tables from the generated
``firmware/include/hexbot_pins.h``, the simulator reads the actuators and
LEDs at these pins, and the pin table of docs/firmware.md is generated from
here; nothing else names a pin.

A pin is ``(port letter, bit)``. Index ``k`` of a six-entry tuple is side or
joint ``k + 1`` in the module's body frame.
"""

from __future__ import annotations

Pin = tuple[str, int]

# --- control board (Table 3-4) ----------------------------------------------------

#: Solenoid joints J1..J6; high = energised = pin retracted = joint open.
JOINT_PINS: tuple[Pin, ...] = (("A", 2), ("A", 3), ("A", 5), ("A", 4), ("A", 0), ("A", 1))
#: Magnet of side S1..S6: the "(1)" line drives it positive...
MAGNET_POS_PINS: tuple[Pin, ...] = (("B", 0), ("D", 3), ("B", 6), ("D", 4), ("B", 1), ("B", 7))
#: ...and the "(2)" line negative; both high would short the driver.
MAGNET_NEG_PINS: tuple[Pin, ...] = (("D", 6), ("D", 5), ("D", 7), ("B", 4), ("B", 5), ("D", 2))
#: DIP switches PC0..PC7: the module id, all eight bits.
DIP_PORT = "C"
DIP_SWITCHES = 8  # a cluster has up to 2**8 - 1 modules (id 0: no switch on)
DIP_ID_MASK = (1 << DIP_SWITCHES) - 1
CONTROL_PORTS = ("A", "B", "D")  # the ports the simulator reads actuators from

# --- communication board (Tables 3-3 and 3-5) -------------------------------------

#: Status LEDs, active low. Side LED "(1)" shows the positive pole...
LED_SIDE_POS_PINS: tuple[Pin, ...] = (("A", 6), ("E", 1), ("C", 6), ("C", 3), ("C", 1), ("D", 6))
#: ...side LED "(2)" the negative pole.
LED_SIDE_NEG_PINS: tuple[Pin, ...] = (("A", 5), ("E", 0), ("C", 7), ("C", 4), ("C", 0), ("D", 5))
LED_JOINT_PINS: tuple[Pin, ...] = (("D", 7), ("A", 7), ("E", 2), ("C", 5), ("C", 2), ("D", 4))
#: IR channel selector lines A, B, C (index Y = 4C + 2B + A, Table 3-5). The
#: listing's IrSel() writes Y1 (side 6) as PA2 alone and Y4 (side 5) as PA0
#: alone, so A = PA2 and C = PA0, as Table 3-3 says.
SELECTOR_PINS: tuple[Pin, ...] = (("A", 2), ("A", 1), ("A", 0))
SELECTOR_PORT = SELECTOR_PINS[0][0]  # all three lines are on one port (PORTA)
COMM_PORTS = ("A", "C", "D", "E")

# --- wireless board (Appendix A, "Wireless SPI") ----------------------------------

#: Bit-banged SPI to the RF12: nSEL, SDI (to the radio), SDO (from it), SCK,
#: all on one port, and the radio's nIRQ (active low).
RF12_SPI_PINS: tuple[Pin, ...] = (("B", 4), ("B", 5), ("B", 6), ("B", 7))
RF12_IRQ_PIN: Pin = ("D", 5)
#: nFFS (held high: FIFO access through commands) and the green and red LEDs
#: (active high), on the nIRQ's port.
RF12_FFS_PIN: Pin = ("D", 4)
RF12_LED_PINS: tuple[Pin, ...] = (("D", 6), ("D", 7))
#: Mode jumper (pull-up): open = transmit test, closed (low) = receive test.
RF12_MODE_PIN: Pin = ("A", 0)

#: The wireless board's link to its communication board (our decision: the
#: thesis planned to merge the two boards and left no wiring). The comm board
#: has no free USART (UART0 is the control board, UART1 the IR multiplexer),
#: so the wireless board's USART0 (RX0, TX0) joins the multiplexer's centre
#: input beside the central IR transceiver, wired-AND: the comm board hears
#: the radio as it hears the PC, whenever its selector is on the centre, and
#: its replies on the centre reach the wireless board. The line runs at the
#: IR rate (the listing's 4800 baud UART0 had nothing to talk to).
RF12_LINK_UART = 0
RF12_LINK_PINS: tuple[Pin, ...] = (("D", 0), ("D", 1))  # RX0, TX0 of the wireless board
RF12_LINK_CHANNEL = "centre"  # comm board selector input the line joins (Table 3-5)

#: Every LED by the name the simulator and its traces use: led_jN (joint N),
#: led_sNa (side N positive), led_sNb (side N negative).
LED_PINS: dict[str, Pin] = {
    **{f"led_j{i}": p for i, p in enumerate(LED_JOINT_PINS, 1)},
    **{f"led_s{i}{ab}": p for i, pair in enumerate(zip(LED_SIDE_POS_PINS, LED_SIDE_NEG_PINS,
                                                      strict=True), 1)
       for ab, p in zip("ab", pair, strict=True)},
}


def port_mask(pins: tuple[Pin, ...] | list[Pin], port: str) -> int:
    """The bits of ``port`` among ``pins``."""
    return sum(1 << bit for p, bit in pins if p == port)


def name(pin: Pin) -> str:
    """``("A", 2)`` -> ``"PA2"``."""
    return f"P{pin[0]}{pin[1]}"


#: The rows of the pin table in docs/firmware.md and of hexbot_pins.h:
#: (board, signal, C name, pins).
TABLES: tuple[tuple[str, str, str, tuple[Pin, ...]], ...] = (
    ("control", "joint J1..J6 (high = open)", "JOINT", JOINT_PINS),
    ("control", "magnet positive line S1..S6", "MAGNET_P", MAGNET_POS_PINS),
    ("control", "magnet negative line S1..S6", "MAGNET_N", MAGNET_NEG_PINS),
    ("comm", 'side LED "(1)" positive (active low)', "LED_SIDE_P", LED_SIDE_POS_PINS),
    ("comm", 'side LED "(2)" negative (active low)', "LED_SIDE_N", LED_SIDE_NEG_PINS),
    ("comm", "joint LED (active low)", "LED_JOINT", LED_JOINT_PINS),
)
