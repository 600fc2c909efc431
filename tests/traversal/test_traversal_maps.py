"""Traversal maps: the text convention of hexbot plan files, errors with file:line,
and the bank on disk is what the generator makes."""

from __future__ import annotations

import pytest

from hexbot.errors import ScenarioError
from hexbot.planning.traversal.bank import MAPS, bank
from hexbot.planning.traversal.surface import load_map, map_text, parse_map

SMALL = """\
. . . . . . . .
M M M . . G G G
S S S S S S S S
"""


def test_cells_follow_the_plan_grid_convention():
    surface = parse_map(SMALL, "small.txt")
    # row r, column c of an R-row map is the axial cell (c - 1, R - r)
    assert surface.modules == {(0, 1), (1, 1), (2, 1)}
    assert surface.goals == {(5, 1), (6, 1), (7, 1)}
    assert (0, 0) in surface.surface and (7, 0) in surface.surface


def test_tokens_may_be_written_together():
    packed = "\n".join(line.replace(" ", "") for line in SMALL.splitlines())
    assert parse_map(packed, "m.txt") == parse_map(SMALL, "m.txt")


@pytest.mark.parametrize("text, message", [
    ("M . G\nS X S\n", "bad.txt:2: unknown token 'X'"),
    ("M . G\nS S\n", "bad.txt:2: row has 2 cells, row 1 (line 1) has 3"),
    ("M . G G\nS S S S\n", "bad.txt: 1 module(s) M but 2 goal cell(s) G"),
    ("M . . .\n. . . G\nS S S S\n", "bad.txt:1: module at [0, 2] does not touch the surface"),
    ("M . G\nS . S\n", "bad.txt:2: the surface (S) is not contiguous"),
    ("# only a comment\n", "bad.txt: no map rows found"),
])
def test_bad_maps_name_the_file_and_line(text, message):
    with pytest.raises(ScenarioError, match=message.replace("[", r"\[").replace("]", r"\]")
                       .replace("(", r"\(").replace(")", r"\)")):
        parse_map(text, "bad.txt")


def test_goals_must_follow_the_chain_clockwise():
    with pytest.raises(ScenarioError, match="not consecutive|one chain"):
        from hexbot.planning.traversal.bridges import find_bridge_cells

        find_bridge_cells(parse_map(". . . . . .\nM . G . G M\nS S S S S S\n", "x.txt"))


def test_the_bank_on_disk_is_up_to_date():
    for name, (surface, _description) in bank().items():
        path = MAPS / f"{name}.txt"
        assert path.exists(), f"run python -m hexbot.planning.traversal.bank ({name})"
        on_disk = load_map(path)
        assert map_text(on_disk).split("\n") == map_text(surface).split("\n"), name
