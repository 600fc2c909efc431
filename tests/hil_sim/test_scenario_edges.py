"""Scenario-file checks at their edges: each bad value a user may type is
refused with file, line and problem (not accepted and run), and the last
value inside a range is accepted."""

from pathlib import Path

import pytest

from hexbot.errors import ScenarioError
from hexbot.hil_sim import load_scenario

BASE = """\
name = "edges"
seed = 7

[faults]
byte_loss = 0.1

[[faults.link]]
from = 1
to = "pc"
bit_error_rate = 0.5

[[module]]
id = 1
position = [0, 0]

[[module]]
id = 2
position = [1, 0]
"""


def write(tmp_path: Path, text: str) -> Path:
    path = tmp_path / "s.toml"
    path.write_text(text)
    return path


@pytest.mark.parametrize(
    "old,new,line,problem",
    [
        # id 0 is no DIP setting a module can have (Select(0) addresses all)
        ("id = 2\n", "id = 0\n", 17, "module id 0 outside 1..255"),
        ("id = 2\n", "id = 2\nclock_ppm = -60000\n", 18, "beyond +-50000 ppm"),
        ("byte_loss = 0.1", "byte_loss = -0.1", 5, "must be a probability 0..1"),
        ("bit_error_rate = 0.5", "bit_error_rate = -1", 10, "must be a probability 0..1"),
        # a misspelt fault would silently inject nothing
        ("byte_loss = 0.1", "byte_los = 0.1", 5, "unknown key 'byte_los' in [faults]"),
        ("bit_error_rate = 0.5", "bit_eror_rate = 0.5", 10,
         "unknown key 'bit_eror_rate' in [faults.link]"),
        ("seed = 7", "seed = 7\nradio_range = -1", 3, "radio_range must be a whole number"),
        ("seed = 7", "seed = 7\nthreads = 0", 3, "threads must be a whole number 1..256"),
    ],
)
def test_bad_values_are_refused_with_file_line_problem(tmp_path, old, new, line, problem):
    path = write(tmp_path, BASE.replace(old, new, 1))
    with pytest.raises(ScenarioError) as err:
        load_scenario(path)
    assert f"{path}:{line}:" in str(err.value)
    assert problem in str(err.value)


def test_a_position_on_the_coordinate_limit_is_accepted(tmp_path):
    # MSG1 carries two decimal digits per coordinate: +-99 still fits
    text = BASE.replace("position = [1, 0]", "position = [99, -99]")
    scenario = load_scenario(write(tmp_path, text))
    assert scenario.modules[1].position == (99, -99)

