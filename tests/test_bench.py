"""``hexbot bench``: every benchmark in bench/ is registered and runs by name."""

import importlib
import json
from pathlib import Path

import pytest

from hexbot.bench.cli import BENCHMARKS
from hexbot.cli import main

BENCH = Path(__file__).resolve().parent.parent / "bench"
HELPERS = {"__init__", "cli", "quiet_child", "raw"}


def test_every_benchmark_module_is_registered_and_runnable():
    modules = {p.stem for p in BENCH.glob("*.py")} - HELPERS
    assert {m.rsplit(".", 1)[1] for m, _ in BENCHMARKS.values()} == modules
    for module_name, _ in BENCHMARKS.values():
        module = importlib.import_module(module_name)
        assert callable(module.add_arguments) and callable(module.run)


def test_help_lists_the_benchmarks(capsys):
    with pytest.raises(SystemExit) as exit_:
        main(["bench", "--help"])
    assert exit_.value.code == 0
    out = capsys.readouterr().out
    assert all(name in out for name in BENCHMARKS)


def test_unknown_benchmark_is_a_usage_error(capsys):
    with pytest.raises(SystemExit) as exit_:
        main(["bench", "no-such-bench"])
    assert exit_.value.code == 2


def test_isp_benchmark_runs(capsys):
    assert main(["bench", "isp", "--repeat", "1"]) == 0
    assert "write+read 16 KiB" in capsys.readouterr().out


def test_core_benchmark_measures_raw_simavr_outside_the_extension(capsys):
    assert main(["bench", "sim-core", "--busy-cycles", "200000", "--idle-seconds", "0.05",
                 "--repeat", "1"]) == 0
    result = json.loads(capsys.readouterr().out)
    assert result["raw_simavr"]["cycles_per_s"] > 0
    assert result["raw_loop_m162"]["cycles_per_s"] > 0
    assert not hasattr(importlib.import_module("hexbot.hil_sim._avr"), "raw_simavr_run")


def test_ir_noise_trial_counts_from_the_actuator_log():
    from hexbot.bench.ir_noise import trial

    clean = trial("mavlink", 0.0, seed=3, commands=12)
    assert (clean["executed"], clean["wrong"], clean["lost"]) == (12, 0, 0)
    noisy = trial("legacy", 3e-2, seed=3, commands=30)
    assert noisy["executed"] + noisy["wrong"] + noisy["lost"] >= 30
    assert noisy["lost"] > 0 and noisy["goodput_per_min"] < clean["goodput_per_min"]
    assert trial("legacy", 3e-2, seed=3, commands=30) == noisy  # seeded
    with pytest.raises(ValueError, match="framing"):
        trial("morse", 0.0, seed=3, commands=1)


@pytest.mark.parametrize("ir", ["core", "python"])
def test_sim_benchmark_says_where_ir_is_routed(capsys, ir):
    assert main(["bench", "sim", "--json", "--sizes", "2", "--seconds", "0.1", "--ir", ir]) == 0
    [size] = json.loads(capsys.readouterr().out)["sizes"]
    assert size["ir"] == ir
    assert size["wave"]["simulated_s"] > 20  # the localization window ran
    # busy is also measured in CPU time, against raw simavr's CPU time
    assert size["busy"]["cycles_per_cpu_s"] > 0 and size["busy"]["vs_raw_cpu"] > 0
    # the firmware's own cost per tick, per board: idle sleeps through the ticks
    idle = size["idle"]["firmware"]
    assert set(idle) == {"comm", "control"}
    assert all(0 < b["awake_cycles_per_tick"] < 100 for b in idle.values()), idle
    assert all(0.9 < b["wakeups_per_tick"] < 1.1 for b in idle.values()), idle
    assert set(size["wave"]["firmware"]) == {"comm", "control"}


def test_surface_benchmark_counts_segments(capsys):
    assert main(["bench", "surface", "--sizes", "100", "--seeds", "1", "--json"]) == 0
    rows = [json.loads(line) for line in capsys.readouterr().out.splitlines()]
    by_shape = {r["shape"]: r for r in rows}
    assert by_shape["ball"]["segments"] == 1 and by_shape["ball"]["largest_share"] == 1.0
    assert by_shape["blob 0 goal"]["segments"] > 1
    assert sum(r["modules"] == 100 for r in rows) == 6
    with pytest.raises(SystemExit):
        main(["bench", "surface", "--seeds", "0"])


def test_pockets_benchmark_measures_how_much_the_holes_digs_move(capsys):
    assert main(["bench", "pockets", "--families", "holes,blob", "--sizes", "300",
                 "--seeds", "1", "--json"]) == 0
    rows = {r["family"]: r for r in map(json.loads, capsys.readouterr().out.splitlines())}
    holes, blob = rows["holes"], rows["blob"]
    assert holes["to_fill"] >= 5 and holes["to_empty"] >= 5  # about 4 % of 300, both ways
    assert holes["closure_max"] > 40  # deeper than a dig moves (dig.DIG_LIMIT)
    assert holes["fill_union_share"] > 0.3 > blob["fill_union_share"]
    with pytest.raises(SystemExit):
        main(["bench", "pockets", "--families", "cubes"])
    with pytest.raises(SystemExit):
        main(["bench", "pockets", "--sizes", "5"])


@pytest.mark.parametrize("option", ["--tasks", "--noop"])
def test_a_sweep_benchmark_of_no_tasks_is_a_usage_error(capsys, option):
    """It used to write a sweep file of an empty range and name that temporary file."""
    with pytest.raises(SystemExit) as exit_:
        main(["bench", "sweep", option, "0"])
    assert exit_.value.code == 2
    assert f"argument {option}: must be at least 1, got 0" in capsys.readouterr().err


def test_the_readme_names_every_benchmark():
    readme = (BENCH.parent / "README.md").read_text()
    row = next(line for line in readme.splitlines() if line.startswith("| `bench/` |"))
    assert {name for name in BENCHMARKS if f"`{name}`" not in row} == set()


def test_the_locomotion_benchmark_fails_when_a_map_case_misses_its_goal(monkeypatch, capsys):
    from hexbot.bench import locomotion

    real = locomotion.case
    # one round each: the flat strips have no goal (fine), the maps miss theirs
    monkeypatch.setattr(locomotion, "case",
                        lambda ruleset, n, rounds, scenario="flat": real(ruleset, n, 1, scenario))
    assert main(["bench", "locomotion", "--quick"]) == 1
    out, err = capsys.readouterr()
    cases = json.loads(out)["cases"]
    assert [c["ok"] for c in cases] == [c["scenario"] == "flat" for c in cases]
    assert err.startswith("not ok: salvador on histogram-3 (90): rounds-exhausted; ")
