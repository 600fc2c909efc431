"""A grid file's MATLAB brackets (docs/planning.md, "Configuration files"):
one pair, if any, holds every row. Before, an unclosed `[` planned (exit 0),
and a second pair, or rows outside the pair, were read as more rows."""

import pytest

from hexbot.errors import ScenarioError
from hexbot.planning.config_io import parse_grid


def test_an_unclosed_bracket_stops_the_plan_at_the_end_of_the_file(cli_status, tmp_path):
    grid = tmp_path / "g.txt"
    grid.write_text("I = [0 1;\n1 1\n")
    code, err = cli_status("plan", grid, grid, "--summary")
    assert (code, err) == (1, f"hexbot plan: error: {grid}:2: ']' missing: the '[' on line 1 "
                              "is never closed\n")


@pytest.mark.parametrize(("text", "message"), [
    ("[1 1\n1 1\n% the end\n", "g:3: ']' missing: the '[' on line 1 is never closed"),
    ("[0 1]\n[1 1]\n", "g:2: a second '[' after the grid's ']' on line 1: a file holds one grid"),
    ("[0 1] [1 1]\n", "g:1: a second '[' after the grid's ']' on line 1: a file holds one grid"),
    ("I = [0 1;\n1 1]\n1 0\n", "g:3: a row after the grid's closing ']' on line 2"),
    ("[1 1] 0\n", "g:1: a row after the grid's closing ']' on line 1"),
    ("0 1\n[1 1]\n", "g:2: '[' after the first row (line 1): it opens the grid, before its rows"),
], ids=["unclosed", "second pair", "two pairs on a line", "row after", "cell after",
        "bracket after a row"])
def test_brackets_that_do_not_hold_the_whole_grid_are_refused(text, message):
    with pytest.raises(ScenarioError) as err:
        parse_grid(text, "g")
    assert str(err.value) == message


def test_one_pair_around_the_rows_is_read_however_it_is_laid_out():
    square = {(0, 0), (1, 0), (0, 1), (1, 1)}
    for text in ("[\n1 1\n1 1\n]\n", "I = [1 1; 1 1];  % MATLAB\n", "[1, 1\n 1, 1];\n% end\n",
                 "1 1\n1 1\n"):
        assert parse_grid(text, "g").cells == square, text
    with pytest.raises(ScenarioError, match=r"^g:1: ']' missing"):
        parse_grid("[1 1\n", "g")  # (the one line of this test failing on the old reader)
