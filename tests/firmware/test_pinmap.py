"""The pin map of docs/firmware.md, the board files of the firmware and the
simulator's own copy of Tables 3-3/3-4 must agree."""

from __future__ import annotations

import re

from fwsim import FIRMWARE, ROOT

from hexbot.hil_sim import module as sim

DOC = ROOT / "docs" / "firmware.md"


def c_table(file: str, name: str) -> list[str]:
    """The PIN(PORT_x, n) entries of a board table, as "Px" names."""
    text = (FIRMWARE / "board" / file).read_text()
    body = re.search(rf"{name}\[6\] PROGMEM = \{{(.*?)\}};", text, re.S)
    assert body, f"{file}: table {name} not found"
    pins = re.findall(r"PIN\(PORT_([A-E]), (\d)\)", body.group(1))
    assert len(pins) == 6
    return [f"P{port}{bit}" for port, bit in pins]


def sim_names(pins) -> list[str]:
    return [f"P{port}{bit}" for port, bit in pins]


def doc_rows() -> dict[str, list[str]]:
    text = DOC.read_text()
    table = text.split("<!-- BEGIN PINMAP")[1].split("<!-- END PINMAP -->")[0]
    rows = {}
    for line in table.splitlines():
        cells = [c.strip() for c in line.strip("|").split("|")]
        if len(cells) == 8 and cells[2].startswith("P"):
            rows[f"{cells[0]}: {cells[1]}"] = cells[2:]
    return rows


def test_firmware_board_files_match_the_simulator():
    assert c_table("control_board.c", "joint_pin") == sim_names(sim.JOINT_PINS)
    assert c_table("control_board.c", "magnet_p") == sim_names(sim.MAGNET_POS_PINS)
    assert c_table("control_board.c", "magnet_n") == sim_names(sim.MAGNET_NEG_PINS)
    leds = {k: f"P{p}{b}" for k, (p, b) in sim.LED_PINS.items()}
    assert c_table("comm_board.c", "led_side_p") == [leds[f"led_s{i}a"] for i in range(1, 7)]
    assert c_table("comm_board.c", "led_side_n") == [leds[f"led_s{i}b"] for i in range(1, 7)]
    assert c_table("comm_board.c", "led_joint") == [leds[f"led_j{i}"] for i in range(1, 7)]


def test_selector_lines_match_the_simulator():
    text = (FIRMWARE / "board" / "comm_board.c").read_text()
    lines = dict(re.findall(r"#define SEL_([ABC]) PA(\d)", text))
    assert [("A", int(lines[x])) for x in "ABC"] == list(sim.SELECTOR_PINS)


def test_documented_pin_map_is_the_firmware_one():
    rows = doc_rows()
    assert rows == {
        "control: joint J1..J6 (high = open)": c_table("control_board.c", "joint_pin"),
        "control: magnet positive line S1..S6": c_table("control_board.c", "magnet_p"),
        "control: magnet negative line S1..S6": c_table("control_board.c", "magnet_n"),
        'comm: side LED "(1)" positive (active low)': c_table("comm_board.c", "led_side_p"),
        'comm: side LED "(2)" negative (active low)': c_table("comm_board.c", "led_side_n"),
        "comm: joint LED (active low)": c_table("comm_board.c", "led_joint"),
    }
