"""Scenario files: the built-ins load, bad files fail with file, line and problem."""

from pathlib import Path

import pytest

from hexbot.errors import ScenarioError
from hexbot.hil_sim import load_scenario
from hexbot.hil_sim.scenario import builtin_names

GOOD = """\
name = "two"
seed = 7
base = 1

[faults]
byte_loss = 0.1

[[faults.link]]
from = "pc"
to = 2
bit_error_rate = 0.5

[[module]]
id = 1
position = [0, 0]

[[module]]
id = 2
position = [1, 0]
orientation = 3
firmware = { comm = "img/comm.elf" }
"""


def write(tmp_path: Path, text: str) -> Path:
    path = tmp_path / "s.toml"
    path.write_text(text)
    return path


def test_builtins_exist_and_load():
    assert {"single", "pair", "thesis-fig5-8", "flower7"} <= set(builtin_names())
    flower = load_scenario("flower7")
    assert len(flower.modules) == 7 and flower.base == 1
    cells = {m.position for m in flower.modules}
    assert cells == {(0, 0), (-1, 1), (0, 1), (1, 0), (1, -1), (0, -1), (-1, 0)}
    fig = load_scenario("thesis-fig5-8")
    assert {m.position for m in fig.modules} == {(0, 0), (1, 0), (2, 0), (3, 0), (4, 0), (0, 1)}


def test_full_file(tmp_path):
    s = load_scenario(write(tmp_path, GOOD))
    assert s.seed == 7 and s.base == 1
    assert s.modules[1].orientation == 3
    assert s.modules[1].firmware.comm == (tmp_path / "img/comm.elf").resolve()
    assert s.faults_for(1, 2).byte_loss == 0.1
    assert s.faults_for("pc", 2).bit_error_rate == 0.5


@pytest.mark.parametrize(
    "old,new,line,problem",
    [
        ("id = 2\n", "id = 1\n", 18, "module id 1 used twice"),
        ("orientation = 3", "orientation = 6", 20, "orientation must be an integer 0..5"),
        ("position = [1, 0]", "position = [0, 0]", 19, "already holds module 1"),
        ("position = [1, 0]", "position = [1]", 19, "position must be [x, y]"),
        ("to = 2", "to = 9", 10, "neither \"pc\" nor the id of a module"),
        ("byte_loss = 0.1", "byte_loss = 2", 6, "probability"),
        ("base = 1", "base = 5", 3, "base = 5 is not the id"),
        ("orientation = 3", "orientation = 3\ncolour = 1", 21, "unknown key 'colour'"),
        ("id = 2\n", "id = 256\n", 18, "outside 1..255"),
        ("id = 2\n", "id = 2\nclock_ppm = 60000\n", 19, "beyond +-50000 ppm"),
        ("seed = ", "clock_spread_ppm = -5\nseed = ", 2, "must not be negative"),
        ("seed = ", "pc_radio = [1]\nseed = ", 2, "pc_radio must be a cell [x, y]"),
    ],
)
def test_semantic_errors_name_file_line_problem(tmp_path, old, new, line, problem):
    path = write(tmp_path, GOOD.replace(old, new, 1))
    with pytest.raises(ScenarioError) as err:
        load_scenario(path)
    assert f"{path}:{line}:" in str(err.value)
    assert problem in str(err.value)


def test_toml_syntax_error_names_the_line(tmp_path):
    path = write(tmp_path, GOOD.replace("seed = 7", "seed = = 7"))
    with pytest.raises(ScenarioError, match=r"s\.toml.*line 2"):
        load_scenario(path)


def test_unknown_builtin_lists_the_choices():
    with pytest.raises(ScenarioError, match="flower7"):
        load_scenario("no-such-scenario")
