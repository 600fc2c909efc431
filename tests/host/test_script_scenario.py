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


def test_a_rotation_the_plant_refuses_fails_with_its_reason(tmp_path, log_dir, capsys):
    from hexbot.cli import main

    # Module 2 is the reference; module 1 is bolted to the base: the plant
    # refuses to turn it, and the CLI says so and exits 1, never "ok".
    script = tmp_path / "refused.hbs"
    script.write_text("select 2\nRef\nselect 0\nLocalize\nstatus\n"
                      "rotate cw 1 mobile 1 substrate 2\n")
    assert main(["run", str(script), "--scenario", "pair"]) == 1
    err = capsys.readouterr().err
    assert "refused.hbs:6: rotate cw 1 mobile 1 substrate 2: the plant refused: " \
           "module 1 fixed to base" in err
    assert "5 of 6 steps passed" in err


def test_the_shipped_rotation_script_passes_on_its_scenario(log_dir, capsys):
    from hexbot.cli import main

    assert main(["run", str(EXAMPLES / "pair_rotate.hbs")]) == 0, capsys.readouterr().err
