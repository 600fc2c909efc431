"""A script names the scenario it was written for; `hexbot run` uses it."""

from pathlib import Path

from hexbot.host.cli_run import declared_scenario

EXAMPLES = Path(__file__).resolve().parents[2] / "docs" / "examples"


def test_examples_declare_their_scenarios():
    assert declared_scenario(EXAMPLES / "pair_rotate.hbs") == "pair"
    assert declared_scenario(EXAMPLES / "flower7_localize.hbs") == "flower7"


def test_no_pragma_means_no_scenario(tmp_path):
    script = tmp_path / "s.hbs"
    script.write_text("# just a comment: scenario pair is not a pragma\nselect 1\n")
    assert declared_scenario(script) is None
