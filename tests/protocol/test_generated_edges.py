"""`hexbot gen-header --check`, what CI runs: exit 1 and the file named for
a stale copy or a file mavgen no longer writes, exit 0 when all is current."""

from __future__ import annotations

from hexbot.cli import main
from hexbot.protocol import generated, mavlink_gen


def test_check_passes_on_the_checked_in_files(capsys):
    assert main(["gen-header", "--check"]) == 0
    assert "stale" not in capsys.readouterr().out


def test_check_fails_and_names_a_stale_file(tmp_path, monkeypatch, capsys):
    copy = tmp_path / "hexbot_codes.h"
    copy.write_text("/* an old copy */\n")
    monkeypatch.setattr(generated, "ARTIFACTS",
                        (generated.Generated(copy, None, lambda: "/* fresh */\n"),))
    monkeypatch.setattr(mavlink_gen, "C_DIR", tmp_path / "mavlink")  # no leftovers there
    assert main(["gen-header", "--check"]) == 1
    assert f"{copy} is stale: run `hexbot gen-header`" in capsys.readouterr().out
    assert copy.read_text() == "/* an old copy */\n"  # --check writes nothing


def test_check_fails_and_names_a_file_mavgen_no_longer_writes(tmp_path, monkeypatch, capsys):
    folder = tmp_path / "mavlink"
    (folder / "hexbot").mkdir(parents=True)
    leftover = folder / "hexbot" / "mavlink_msg_hexbot_removed.h"
    leftover.write_text("/* a message removed from the dialect */\n")
    monkeypatch.setattr(mavlink_gen, "C_DIR", folder)
    assert main(["gen-header", "--check"]) == 1
    out = capsys.readouterr().out
    assert f"{leftover} is no longer generated" in out and "stale" not in out
    assert leftover.exists()  # --check removes nothing
