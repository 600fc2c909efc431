"""hexbot traverse: the --json schema, exit statuses, --render."""

from __future__ import annotations

import json

import pytest

from hexbot.cli import main


def _json(capsys, *argv):
    status = main(["traverse", *argv, "--json"])
    return status, json.loads(capsys.readouterr().out)


def test_json_schema_on_a_bridged_pocket(capsys):
    status, out = _json(capsys, "left-5")
    assert status == 0 and out["status"] == "reached"
    assert out["time_steps"] == len(out["rounds"]) and out["moves"] == sum(
        len(r["moves"]) for r in out["rounds"])
    assert out["bridges"][0]["kind"] == "LEFT" and out["bridges"][0]["cells"]
    move = out["rounds"][0]["moves"][0]
    assert set(move) >= {"from", "to", "joint", "direction"} and move["direction"] in ("CW",
                                                                                        "CCW")


def test_violation_exits_1_with_the_reason(capsys):
    status = main(["traverse", "basic-5", "--no-bridges"])
    captured = capsys.readouterr()
    assert status == 1 and "violation: round" in captured.err


def test_bad_map_is_a_one_line_error(tmp_path, capsys):
    bad = tmp_path / "bad.txt"
    bad.write_text("M . G\nS Q S\n")
    assert main(["traverse", str(bad)]) == 1
    assert f"{bad}:2: unknown token 'Q'" in capsys.readouterr().err


def test_no_3_bridges_changes_the_bridges(capsys):
    _, with_three = _json(capsys, "three-deep4")
    _, without = _json(capsys, "three-deep4", "--no-3-bridges")
    assert [b["kind"] for b in with_three["bridges"]] == ["THREE"]
    assert "THREE" not in [b["kind"] for b in without["bridges"]]


def test_render_writes_an_animated_gif(tmp_path):
    pytest.importorskip("matplotlib")
    from PIL import Image

    out = tmp_path / "run.gif"
    assert main(["traverse", "single-1", "--render", str(out)]) == 0
    with Image.open(out) as gif:
        assert gif.n_frames > 10


def test_random_range_counts_outcomes_and_fails_unless_all_reached(capsys):
    status, out = _json(capsys, "--random", "160..169")
    assert status == 0 and out["reached"] == 10 and out["failures"] == []
    # under the hexbot model random:2 is refused (random:1 and 3 broke an
    # invariant before start holds): exit 1, with the reason
    status = main(["traverse", "--random", "0..3", "--motion", "hexbot"])
    text = capsys.readouterr().out
    assert status == 1 and "3 reached, 0 deadlock, 0 violation, 1 refused" in text
    assert "random:2: refused" in text and "random:1:" not in text


def test_start_holds_are_shown(capsys):
    # random:51: modules 3 and 4 hold back their start one round (docs/traversal.md)
    assert main(["traverse", "random:51", "--motion", "hexbot"]) == 0
    text = capsys.readouterr().out
    assert "start held back (rounds; their ways fold back): module 3: 1, module 4: 1" in text
    status, out = _json(capsys, "random:51", "--motion", "hexbot")
    assert status == 0 and out["start_holds"] == [0, 0, 1, 1]
    status, out = _json(capsys, "random:51")
    assert status == 0 and out["start_holds"] == [0, 0, 0, 0]


def test_random_range_must_be_seeds(capsys):
    assert main(["traverse", "--random", "a..b"]) != 0
    assert "expected FIRST..LAST" in capsys.readouterr().err


def test_a_binary_map_file_is_not_text(cli_status, capsys, tmp_path):
    binary = tmp_path / "g.bin"
    binary.write_bytes(bytes([0xA9, 0xFF, 0x00, 0xC3]) * 75)
    code, err = cli_status("traverse", binary)
    assert code == 1 and err.strip() == (
        f"hexbot traverse: error: {binary}: not a text file (UTF-8): byte 0xa9 at offset 0")


def test_a_random_map_needs_a_seed_from_0(cli_status, capsys):
    code, err = cli_status("traverse", "random:-1")
    assert code == 1 and "random:-1: the seed is a whole number from 0" in err


def test_an_unknown_map_is_neither_a_file_nor_a_shipped_map(cli_status, capsys):
    code, err = cli_status("traverse", "nosuchcase")
    assert code == 1 and "nosuchcase: neither a map file nor a shipped map" in err
    assert "fig14" in err and "random:SEED" in err


@pytest.mark.parametrize("argv, words", [
    (["--random", "5..1"], "--random 5..1: the range is empty"),
    (["--random", "x"], "--random x: expected FIRST..LAST seeds"),
    (["fig14", "--plot", "x.png"], "--plot draws the --sweep figures: give --sweep too"),
    (["hil-basic-2", "--render", "/nonexistent/x.gif"], "folder /nonexistent does not exist"),
    ([], "give a MAP (or --sweep or --random FIRST..LAST)"),
    (["fig14", "--random", "0..1"], "give no MAP with them"),
    (["fig14", "--sweep"], "give no MAP with them"),
    # rigid modules cannot make the deformable model's moves
    (["hil-three", "--execute", "--motion", "deformable"],
     "--execute runs rigid modules, which cannot make deformable moves"),
    # options --random and --sweep would otherwise ignore
    (["--random", "0..1", "--execute"], "--execute runs one map on a cluster: not with --random"),
    (["--sweep", "--execute"], "--execute runs one map on a cluster: not with --sweep"),
    (["--random", "0..1", "--render", "x.gif"], "--render animates one map: not with --random"),
    (["--sweep", "--render", "x.gif"], "--render animates one map: not with --sweep"),
    (["--sweep", "--no-bridges"], "no --no-bridges or --no-3-bridges"),
    (["--sweep", "--no-3-bridges"], "no --no-bridges or --no-3-bridges"),
    (["--sweep", "--motion", "hexbot"], "deformable motion only"),
    # drawings that cannot be written: refused before the work
    (["hil-flat", "--render", "x.txt"], "x.txt: the name must end in .gif"),
    (["hil-flat", "--render", "/proc/x.gif"], "/proc/x.gif: cannot write"),
    (["--sweep", "--plot", "x.txt"], "x.txt: the name must end in .png or .svg or .pdf"),
])
def test_usage_errors_exit_2_before_any_run(cli_status, capsys, argv, words):
    code, err = cli_status("traverse", *argv)
    assert code == 2 and words in err


def test_random_honours_no_bridges(capsys):
    status, out = _json(capsys, "--random", "160..169", "--no-bridges")
    # the same seeds all reached with bridges (above); narrow pockets break without
    assert status == 1 and out["bridges"] == "none" and out["violation"] > 0
    status, out = _json(capsys, "--random", "160..161", "--no-3-bridges")
    assert status == 0 and out["bridges"] == "1-2"


def test_the_result_is_printed_before_the_drawing_and_a_failed_write_is_one_line(
        capsys, monkeypatch, tmp_path):
    pytest.importorskip("matplotlib")
    from hexbot.planning.traversal import render

    def refuse(*_args, **_kwargs):
        raise PermissionError(13, "Permission denied")

    monkeypatch.setattr(render.FuncAnimation, "save", refuse)
    out = tmp_path / "run.gif"
    code = main(["traverse", "hil-flat", "--render", str(out)])
    captured = capsys.readouterr()
    assert code == 1 and captured.err.strip() == (
        f"hexbot traverse: error: --render: cannot write {out}: Permission denied")
    assert "reached: 8 time steps, 9 moves" in captured.out


def test_perimeter_errors_name_the_map_file(cli_status, tmp_path):
    chain = tmp_path / "gap.txt"  # two modules apart: not one chain along the perimeter
    chain.write_text("M . M G . G .\nS S S S S S S\n")
    code, err = cli_status("traverse", chain)
    assert code == 1 and err.strip() == (
        f"hexbot traverse: error: {chain}: the modules (M) do not form one chain along "
        "the perimeter")
    goals = tmp_path / "goals.txt"
    goals.write_text(". . . . . . .\nM M G . . G .\nS S S S S S S\n")
    code, err = cli_status("traverse", goals, "--motion", "hexbot")
    assert code == 1 and f"error: {goals}: the goal cells (G) are not consecutive" in err
