"""The pin maps against Tables 3-3 and 3-4 as printed (seed 002, lines
1387-1483): pin -> function, written out here, not imported."""

from hexbot.protocol import pins

# Table 3-3, communication microcontroller (LEDs and the selector).
TABLE_3_3 = {
    "PD4": "Joint 6 LED", "PD5": "Side 6 (2) LED", "PD6": "Side 6 (1) LED", "PD7": "Joint 1 LED",
    "PC0": "Side 5 (2) LED", "PC1": "Side 5 (1) LED", "PC2": "Joint 5 LED",
    "PC3": "Side 4 (1) LED", "PC4": "Side 4 (2) LED", "PC5": "Joint 4 LED",
    "PC6": "Side 3 (1) LED", "PC7": "Side 3 (2) LED", "PE2": "Joint 3 LED",
    "PE1": "Side 2 (1) LED", "PE0": "Side 2 (2) LED", "PA7": "Joint 2 LED",
    "PA6": "Side 1 (1) LED", "PA5": "Side 1 (2) LED",
    "PA2": "Selector A", "PA1": "Selector B", "PA0": "Selector C",
}
# Table 3-4, control microcontroller (drive lines, joints, DIP switches).
TABLE_3_4 = {
    "PB0": "Side 1 (1)", "PB1": "Side 5 (1)", "PB4": "Side 4 (2)", "PB5": "Side 5 (2)",
    "PB6": "Side 3 (1)", "PB7": "Side 6 (1)", "PD2": "Side 6 (2)", "PD3": "Side 2 (1)",
    "PD4": "Side 4 (1)", "PD5": "Side 2 (2)", "PD6": "Side 1 (2)", "PD7": "Side 3 (2)",
    "PA5": "Joint 3", "PA4": "Joint 4", "PA3": "Joint 2", "PA2": "Joint 1", "PA1": "Joint 6",
    "PA0": "Joint 5",
    **{f"PC{i}": f"DIP {i + 1}" for i in range(8)},
}
UART_PINS = {"PD0", "PD1", "PB2", "PB3"}  # RX0, TX0, RX1, TX1 on both boards


def functions(table: dict[str, str], prefix: str, suffix: str = "") -> list[str]:
    """The pins of "<prefix> 1<suffix>" .. "<prefix> 6<suffix>" in the table."""
    by_function = {f: pin for pin, f in table.items()}
    return [by_function[f"{prefix} {i}{suffix}"] for i in range(1, 7)]


def names(table) -> list[str]:
    return [pins.name(p) for p in table]


def test_control_board_is_table_3_4():
    assert names(pins.JOINT_PINS) == functions(TABLE_3_4, "Joint")
    assert names(pins.MAGNET_POS_PINS) == functions(TABLE_3_4, "Side", " (1)")
    assert names(pins.MAGNET_NEG_PINS) == functions(TABLE_3_4, "Side", " (2)")
    dip = [f"P{pins.DIP_PORT}{bit}" for bit in range(8) if pins.DIP_ID_MASK >> bit & 1]
    assert dip == [pin for pin, f in TABLE_3_4.items() if f.startswith("DIP")]  # all eight


def test_communication_board_is_table_3_3():
    assert names(pins.LED_JOINT_PINS) == functions(TABLE_3_3, "Joint", " LED")
    assert names(pins.LED_SIDE_POS_PINS) == functions(TABLE_3_3, "Side", " (1) LED")
    assert names(pins.LED_SIDE_NEG_PINS) == functions(TABLE_3_3, "Side", " (2) LED")
    by_function = {f: pin for pin, f in TABLE_3_3.items()}
    assert names(pins.SELECTOR_PINS) == [by_function[f"Selector {x}"] for x in "ABC"]


def test_no_pin_serves_twice_nor_takes_a_uart_line():
    control = names(pins.JOINT_PINS + pins.MAGNET_POS_PINS + pins.MAGNET_NEG_PINS)
    comm = names(list(pins.LED_PINS.values()) + list(pins.SELECTOR_PINS))
    for board in (control, comm):
        assert len(set(board)) == len(board)
        assert not set(board) & UART_PINS


def test_led_names_cover_every_led_once():
    assert len(pins.LED_PINS) == 18
    assert pins.LED_PINS["led_s4a"] == pins.LED_SIDE_POS_PINS[3]
    assert pins.LED_PINS["led_s4b"] == pins.LED_SIDE_NEG_PINS[3]
    assert pins.LED_PINS["led_j2"] == pins.LED_JOINT_PINS[1]
