"""The argparse types every command shares (hexbot/cli_args.py)."""

import argparse

import pytest

from hexbot.cli_args import output_file


def test_an_output_file_is_tried_and_nothing_is_left_behind(tmp_path):
    new = tmp_path / "new.jsonl"
    assert output_file(str(new)) == str(new) and not new.exists()
    kept = tmp_path / "kept.txt"
    kept.write_text("old")
    assert output_file(str(kept)) == str(kept) and kept.read_text() == "old"
    with pytest.raises(argparse.ArgumentTypeError, match="cannot write"):
        output_file("/proc/x.png")
    with pytest.raises(argparse.ArgumentTypeError, match="does not exist"):
        output_file(str(tmp_path / "no" / "x.png"))


def test_a_symlink_to_a_file_still_to_be_made_is_an_output_file(tmp_path):
    """exists() follows the link (False) and O_EXCL then refused the link itself:
    `ln -s events-target.jsonl ev.jsonl; hexbot sim --events ev.jsonl` was exit 2."""
    link = tmp_path / "ev.jsonl"
    link.symlink_to("events-target.jsonl")
    assert output_file(str(link)) == str(link)
    assert link.is_symlink() and not (tmp_path / "events-target.jsonl").exists()
    broken = tmp_path / "broken.png"
    broken.symlink_to(tmp_path / "no" / "target.png")
    with pytest.raises(argparse.ArgumentTypeError, match="cannot write"):
        output_file(str(broken))
