"""Configuration files at their edges: what is refused names the file and the
line, what is accepted is read as written."""

import pytest

from hexbot.errors import ScenarioError
from hexbot.planning.config_io import load_configuration, parse_grid, parse_toml


def test_a_stray_closing_bracket_is_refused_with_its_line():
    with pytest.raises(ScenarioError, match=r"^g:2: '\]' closes no bracket$"):
        parse_grid("1 1\n1 1]\n", "g")
    assert parse_grid("[1 1\n 1 1]\n", "g").cells == {(0, 0), (1, 0), (0, 1), (1, 1)}


def test_a_row_longer_than_the_first_is_refused_with_its_line():
    with pytest.raises(ScenarioError, match=r"^g:3: row has 3 columns, row 1 \(line 1\) has 2$"):
        parse_grid("1 1\n0 1\n1 1 1\n", "g")


def test_an_empty_cell_list_is_refused_with_its_line():
    with pytest.raises(ScenarioError,
                       match=r"^c.toml:2: 'cells' must be a non-empty list of \[x, y\]$"):
        parse_toml("# nothing\ncells = []\n", "c.toml")


@pytest.mark.parametrize("entry,words", [
    ("id = 0\ncell = [0, 0]", "id must be an integer 1..63 (DIP switches), got 0"),
    ("id = 64\ncell = [0, 0]", "id must be an integer 1..63 (DIP switches), got 64"),
    ("id = 1\ncell = [0, 0]\norientation = 6", "orientation must be 0..5, got 6"),
    ("id = 1\ncell = [0, 0]\norientation = -1", "orientation must be 0..5, got -1"),
    ("id = 1\ncell = [0, 0, 0]", "a cell must be [x, y] with two integers, got [0, 0, 0]"),
    ("id = 1\ncell = [0]", "a cell must be [x, y] with two integers, got [0]"),
])
def test_module_tables_out_of_range_are_refused_naming_the_table(entry, words):
    with pytest.raises(ScenarioError) as caught:
        parse_toml(f"[[module]]\n{entry}\n", "m.toml")
    assert str(caught.value) == f"m.toml:1: [[module]] #1: {words}"


def test_module_tables_at_the_range_ends_are_read():
    config = parse_toml("[[module]]\nid = 1\ncell = [0, 0]\norientation = 0\n"
                        "[[module]]\nid = 63\ncell = [1, 0]\norientation = 5\n")
    assert {c: (m.id, m.orientation) for c, m in config.items()} == {(0, 0): (1, 0),
                                                                     (1, 0): (63, 5)}


def test_a_module_id_given_twice_is_refused():
    text = "[[module]]\nid = 5\ncell = [0, 0]\n[[module]]\nid = 5\ncell = [1, 0]\n"
    with pytest.raises(ScenarioError,
                       match=r"^m.toml:4: \[\[module\]\] #2: module id 5 used twice$"):
        parse_toml(text, "m.toml")
    text = "[[module]]\nid = 5\ncell = [0, 0]\n[[module]]\nid = 6\ncell = [0, 0]\n"
    with pytest.raises(ScenarioError, match=r"#2: cell \(0, 0\) holds two modules$"):
        parse_toml(text, "m.toml")


def test_cells_and_module_tables_together_are_refused():
    text = "cells = [[0, 0]]\n[[module]]\nid = 5\ncell = [9, 9]\n"
    with pytest.raises(ScenarioError,
                       match=r"^m.toml:1: give either 'cells' or \[\[module\]\] tables"):
        parse_toml(text, "m.toml")


def test_a_module_table_error_names_the_line_of_its_header():
    # a file of a few hundred [[module]] tables: "#37" alone sends the user counting
    text = ("# two modules\n[[module]]\nid = 1\ncell = [0, 0]\n\n"
            "[[module]]  # the second\nid = 2\ncell = [0, 0]\n")
    with pytest.raises(ScenarioError,
                       match=r"^m.toml:6: \[\[module\]\] #2: cell \(0, 0\) holds two modules$"):
        parse_toml(text, "m.toml")
    # inline tables have no header: the line that sets 'module'
    inline = "# inline\nmodule = [{id = 1, cell = [0, 0]}, {id = 0, cell = [1, 0]}]\n"
    with pytest.raises(ScenarioError, match=r"^m.toml:2: \[\[module\]\] #2: id must be"):
        parse_toml(inline, "m.toml")


def test_the_toml_suffix_is_recognised_in_any_case(tmp_path):
    upper = tmp_path / "pair.TOML"
    upper.write_text("[[module]]\nid = 7\ncell = [0, 0]\n[[module]]\nid = 9\ncell = [1, 0]\n")
    config = load_configuration(upper)
    assert {c: m.id for c, m in config.items()} == {(0, 0): 7, (1, 0): 9}


def test_a_cells_error_names_the_line_that_sets_cells_not_a_comment_naming_it():
    # (fixed in this audit: the first line containing "cells", here the comment, was named)
    with pytest.raises(ScenarioError, match=r"^c.toml:2: cell \(0, 0\) listed twice$"):
        parse_toml("# the cells of the bar\ncells = [[0, 0], [0, 0]]\n", "c.toml")
