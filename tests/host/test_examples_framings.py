"""The shipped example scripts (docs/examples/*.hbs) pass on the embedded
simulator in both framings: docs/protocol.md promises that the workflows
run unchanged whether commands go out as legacy or MAVLink frames."""

from __future__ import annotations

from pathlib import Path

import pytest

from hexbot.cli import main

EXAMPLES = sorted((Path(__file__).resolve().parents[2] / "docs" / "examples").glob("*.hbs"))


def test_there_are_examples():
    assert len(EXAMPLES) >= 4


@pytest.mark.parametrize("framing", ["legacy", "mavlink"])
@pytest.mark.parametrize("script", EXAMPLES, ids=lambda p: p.name)
def test_every_example_script_passes_in_either_framing(script, framing, log_dir, capsys):
    status = main(["run", str(script), "--framing", framing])
    assert status == 0, capsys.readouterr().err
