"""Maps at the edges of what FINDBRIDGECELLS accepts: the smallest pocket a
3-bridge closes, and a goal cell the modules can never reach."""

from __future__ import annotations

from hexbot.planning.traversal.bank import random_surface
from hexbot.planning.traversal.bridges import find_bridge_cells


def test_a_three_bridge_closes_a_pocket_of_three_cells():
    # bridges.py: "a 3-bridge must cut off at least three perimeter cells";
    # random:19 has such a pocket, spanned by layer1 cells 22 and 26
    bmap = find_bridge_cells(random_surface(19))
    threes = [(g.span, g.pocket_length, g.shape) for g in bmap.groups if g.kind == "THREE"]
    assert ((22, 26), 3, "straight") in threes


def test_a_goal_off_the_perimeter_is_a_one_line_error(cli_status, tmp_path):
    # the goal cell is a hole inside the surface: it touches the surface (the
    # map reader accepts it) but no module can roll there; the error names it
    enclosed = tmp_path / "enclosed.txt"
    enclosed.write_text("M . . . . .\nS S S S S S\nS S G S S S\nS S S S S S\n")
    for motion in ("deformable", "hexbot"):
        code, err = cli_status("traverse", enclosed, "--motion", motion)
        assert code == 1 and err.strip() == (
            f"hexbot traverse: error: {enclosed}: cell [2, 1] is not on the perimeter the "
            f"modules roll along (under the {motion} motion model)"), err
