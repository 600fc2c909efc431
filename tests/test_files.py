"""Input files: one reader, one TOML loader, errors with file and line."""

import pytest

from hexbot.errors import ScenarioError
from hexbot.files import load_toml


@pytest.mark.parametrize("text, where", [
    ("cells = [[0, 0],\n  [1, 0]\n", "goal.toml:2: Unclosed array"),  # at the end of the text
    ("a = 1\nb = = 2\nc = 3\n", "goal.toml:2: "),
])
def test_a_toml_syntax_error_names_its_line(text, where):
    with pytest.raises(ScenarioError) as info:
        load_toml(text, "goal.toml")
    assert str(info.value).startswith(where) and "(at" not in str(info.value)


def test_every_toml_input_reports_the_line(tmp_path, cli_status):
    # a goal, a scenario and a sweep file: the same loader (the goal and the
    # scenario said "(at end of document)" with no line)
    bad = tmp_path / "bad.toml"
    bad.write_text("cells = [[0, 0],\n  [1, 0]\n")
    code, err = cli_status("plan", bad, bad)
    assert code == 1 and f"{bad}:2: Unclosed array" in err
    code, err = cli_status("sim", bad, "--duration", "1")
    assert code == 1 and f"{bad}:2: Unclosed array" in err
