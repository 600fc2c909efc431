"""TOML configurations refuse keys they do not know, at the top and in each
[[module]] table, naming the key, its line and the known key it is close to
(docs/planning.md, "Configuration files"). Before, `orientaton = 3` planned
with orientation 0 and exit 0, and `bogus = 3` was ignored."""

import pytest

from hexbot.errors import ScenarioError
from hexbot.hil_sim import load_scenario
from hexbot.planning.config_io import parse_toml

PAIR = "[[module]]\nid = 1\ncell = [0, 0]\n[[module]]\nid = 2\ncell = [1, 0]\n"


def test_a_misspelt_module_key_stops_the_plan_naming_its_line(cli_status, tmp_path):
    typo = tmp_path / "typo.toml"
    typo.write_text("[[module]]\nid = 1\ncell = [0, 0]\norientaton = 3\n"
                    "[[module]]\nid = 2\ncell = [1, 0]\n")
    goal = tmp_path / "two.toml"
    goal.write_text(PAIR)
    code, err = cli_status("plan", typo, goal, "--summary")
    assert (code, err) == (1, f"hexbot plan: error: {typo}:4: [[module]] #1: unknown key "
                              "'orientaton' (did you mean 'orientation'?)\n")
    typo.write_text(PAIR.replace("[1, 0]\n", "[1, 0]\n# two\nOrientation = 2\n"))
    with pytest.raises(ScenarioError, match=r"^m.toml:8: \[\[module\]\] #2: unknown key "
                                            r"'Orientation' \(did you mean 'orientation'\?\)$"):
        parse_toml(typo.read_text(), "m.toml")


@pytest.mark.parametrize(("text", "message"), [
    ("cells = [[0, 0], [1, 0]]\nbogus = 3\n", "c.toml:2: unknown key 'bogus'"),
    ("cell = [[0, 0], [1, 0]]\n", "c.toml:1: unknown key 'cell' (did you mean 'cells'?)"),
    ("cells = [[0, 0]]\n\n[extra]\nx = 1\n", "c.toml:3: unknown key 'extra'"),
    ("cells = [[0, 0]]\nmeta.name = 'x'\n", "c.toml:2: unknown key 'meta'"),
    (PAIR.replace("id = 1", "idd = 1"),
     "c.toml:2: [[module]] #1: unknown key 'idd' (did you mean 'id'?)"),
    (PAIR + "[module.extra]\nx = 1\n", "c.toml:4: [[module]] #2: unknown key 'extra'"),
    ("module = [{id = 1, cell = [0, 0]}, {id = 2, cell = [1, 0], orient = 1}]\n",
     "c.toml:1: [[module]] #2: unknown key 'orient' (did you mean 'orientation'?)"),
], ids=["top key", "top typo", "top table", "dotted key", "module typo", "module sub-table",
        "inline module"])
def test_unknown_keys_are_refused_at_every_level(text, message):
    with pytest.raises(ScenarioError) as err:
        parse_toml(text, "c.toml")
    assert str(err.value) == message


def test_scenario_files_suggest_the_close_key_the_same_way(tmp_path):
    # one helper (hexbot.toml_lines.unknown_key) words both formats' refusals
    path = tmp_path / "s.toml"
    path.write_text("name = \"two\"\n[faults]\nbyte_los = 0.1\n"
                    "[[module]]\nid = 1\nposition = [0, 0]\n")
    with pytest.raises(ScenarioError) as err:
        load_scenario(path)
    assert str(err.value) == (f"{path}:3: unknown key 'byte_los' in [faults] "
                              "(did you mean 'byte_loss'?)")
