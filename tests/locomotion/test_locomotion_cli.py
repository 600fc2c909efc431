"""``hexbot locomotion``: the JSON contract, rendering, and user errors."""

import json

import numpy as np
import pytest

from hexbot.cli import main


def run_cli(capsys, *argv):
    code = main(["locomotion", *argv])
    out, err = capsys.readouterr()
    return code, out, err


def test_json_output_has_the_promised_fields(capsys):
    code, out, _ = run_cli(
        capsys, "run", "salvador-free", "flat", "--n", "20", "--until-advance", "5", "--json"
    )
    data = json.loads(out)
    assert code == 0
    assert data["status"] == "advanced"
    assert data["rounds"] == 38  # Table 1: n = 20, k = 5
    assert len(data["moves_per_module"]) == 20
    assert data["moves_per_module"][:5] == [20] * 5
    assert len(data["final"]["modules"]) == 20


def test_rounds_exhausted_and_text_output(capsys):
    code, out, _ = run_cli(capsys, "run", "salvador-free", "flat", "--n", "6", "--rounds", "9")
    assert code == 0
    assert "status: rounds-exhausted after 9 rounds" in out
    assert "moves per module:" in out
    assert "######" in out  # the final state, drawn


def test_deadlock_exit_code_and_report(capsys):
    code, out, _ = run_cli(capsys, "run", "salvador-free", "flat", "--n", "1", "--json")
    data = json.loads(out)
    assert code == 1  # the rules failed (docs/console.md, Exit statuses)
    assert data["status"] == "deadlock"
    assert data["deadlock"]["round"] == 1


@pytest.mark.parametrize("suffix", ["png", "gif"])
def test_render(tmp_path, capsys, suffix):
    out = tmp_path / f"run.{suffix}"
    code, _, _ = run_cli(capsys, "run", "salvador-pyramids", "pyramid", "--n", "5",
                         "--rounds", "30", "--render", str(out))
    assert code == 3  # 30 rounds do not get past the pyramid (a time-out); drawn anyway
    head = out.read_bytes()[:4]
    assert head == (b"\x89PNG" if suffix == "png" else b"GIF8")


def test_the_animation_has_a_frame_per_round_a_counter_a_legend_and_the_grid(tmp_path, capsys):
    from PIL import Image

    from hexbot.planning.locomotion.render import COLOURS, GRID_RGB, HEADER_PX, OBSTACLE_RGB

    out = tmp_path / "run.gif"
    code, _, _ = run_cli(capsys, "run", "salvador", "flat", "--n", "6", "--rounds", "12",
                         "--render", str(out))
    assert code in (0, 3)
    gif = Image.open(out)
    assert gif.n_frames == 13  # round 0 (the start) and one per round
    pictures = []
    for k in (0, 12):
        gif.seek(k)
        pictures.append(gif.convert("RGB"))
    first, last = pictures
    def colours(img) -> set[tuple[int, ...]]:
        return set(map(tuple, np.asarray(img).reshape(-1, 3).tolist()))

    header = colours(first.crop((0, 0, first.width, HEADER_PX)))
    for rgb in (OBSTACLE_RGB, COLOURS["static"], COLOURS["active"]):  # legend swatches
        assert rgb in header
    counter = (0, 0, 85, HEADER_PX)  # "round k/12" changes, the legend does not
    assert first.crop(counter).tobytes() != last.crop(counter).tobytes()
    legend = (90, 0, first.width, HEADER_PX)
    assert first.crop(legend).tobytes() == last.crop(legend).tobytes()
    assert GRID_RGB in colours(first.crop((0, HEADER_PX, first.width, first.height)))


def test_bad_rule_file_error_names_the_line(tmp_path, capsys):
    bad = tmp_path / "bad.rules"
    bad.write_text("ruleset x\nstates a b\nrule R\n  priority 1\n  state a\n  move NNE\n")
    code, _, err = run_cli(capsys, "run", str(bad), "flat")
    assert code == 1
    assert f"{bad}:6:" in err and "NNE" in err


def test_unknown_names_are_user_errors(capsys):
    assert run_cli(capsys, "run", "nope", "flat")[0] == 1
    code, _, err = run_cli(capsys, "run", "salvador", "nowhere")
    assert code == 1 and "unknown scenario" in err
    code, _, err = run_cli(capsys, "run", "salvador", "flat", "--render", "x.bmp")
    assert code == 1 and ".png or .gif" in err


def test_bank_json(capsys):
    code, out, _ = run_cli(capsys, "bank", "--rulesets", "salvador-pyramids", "--n", "5",
                           "--rounds", "400", "--json")
    rows = json.loads(out)
    assert code == 0
    assert {r["scenario"] for r in rows} >= {"pyramid", "maze", "histogram-1"}
    assert all(r["status"] in ("reached", "deadlock", "violation", "rounds-exhausted")
               for r in rows)


def test_rounds_out_before_the_goal_is_a_time_out_and_zero_rounds_a_usage_error(capsys):
    """Issue 13, item 11: exit statuses were inconsistent and undocumented."""
    code, out, _ = run_cli(capsys, "run", "salvador-free", "flat", "--n", "6", "--rounds", "3",
                           "--until-advance", "5")
    assert code == 3 and "status: rounds-exhausted after 3 rounds" in out
    with pytest.raises(SystemExit) as info:
        run_cli(capsys, "run", "salvador-free", "flat", "--rounds", "0")
    assert info.value.code == 2
    assert "--rounds: must be at least 1, got 0" in capsys.readouterr().err


def test_a_binary_map_or_rule_file_is_not_text(cli_status, capsys, tmp_path):
    binary = tmp_path / "g.bin"
    binary.write_bytes(bytes([0xA9, 0xFF, 0x00, 0xC3]) * 75)
    for argv in (["run", "salvador", binary, "--n", "5"], ["run", binary, "flat", "--n", "5"]):
        code, err = cli_status("locomotion", *argv)
        assert code == 1 and err.strip() == (
            f"hexbot locomotion: error: {binary}: not a text file (UTF-8): byte 0xa9 at offset 0")


@pytest.mark.parametrize("argv, words", [
    (["run", "salvador", "flat", "--n", "0"], "argument --n: must be at least 1, got 0"),
    (["run", "salvador", "flat", "--until-advance", "-1"], "argument --until-advance"),
    (["run", "salvador", "flat", "--render", "/nonexistent/x.gif"], "/nonexistent does not exist"),
    (["random", "salvador", "--seeds", "20:0"], "--seeds: '20:0' is empty"),
])
def test_usage_errors_exit_2(cli_status, capsys, argv, words):
    code, err = cli_status("locomotion", *argv)
    assert code == 2 and words in err
