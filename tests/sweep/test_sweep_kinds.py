"""The built-in kinds on a real cluster: HIL scripts over firmware x seed with
JUnit XML, planner pairs as the planning bench builds them, the IR noise
trial (a double stands in for it only here), and a dotted-path kind."""

from __future__ import annotations

import shutil
import sys
import types
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
import serial

from hexbot.cli import main
from hexbot.errors import ScenarioError
from hexbot.sweep.engine import run_sweep
from hexbot.sweep.report import report
from hexbot.sweep.results import ResultStore, read_table
from hexbot.sweep.spec import load_spec

ROOT = Path(__file__).resolve().parents[2]
FIRMWARE = ROOT / "firmware" / "build"
PAIR_ROTATE = ROOT / "docs" / "examples" / "pair_rotate.hbs"


def run_here(spec_path: Path, client, out: Path) -> list[dict]:
    spec = load_spec(spec_path)
    with ResultStore(out, spec.kind.name, spec.param_names) as store:
        outcome = run_sweep(spec, client, store)
    assert outcome.stored == outcome.total
    return read_table(out).to_pylist()


@pytest.fixture
def broken_firmware(tmp_path) -> Path:
    """A build whose communication board got the control board's image."""
    folder = tmp_path / "broken-build"
    folder.mkdir()
    shutil.copy(FIRMWARE / "control.elf", folder / "comm.elf")
    shutil.copy(FIRMWARE / "control.elf", folder / "control.elf")
    return folder


def test_hil_scripts_over_firmware_and_seeds_with_junit(write_spec, tmp_path, broken_firmware,
                                                        capsys):
    shutil.copy(PAIR_ROTATE, tmp_path / "pair_rotate.hbs")
    spec = write_spec(f"""kind = "hil-script"
[grid]
script = "pair_rotate.hbs"
firmware = ["{FIRMWARE}", "broken-build"]
seed = [1, 2]
""")
    out = tmp_path / "out"
    assert main(["sweep", str(spec), "--out", str(out), "--no-progress"]) == 1
    rows = read_table(out).to_pylist()
    by = {(r["firmware"], r["seed"]): r for r in rows}
    for seed in (1, 2):
        good, bad = by[(str(FIRMWARE), seed)], by[("broken-build", seed)]
        assert (good["outcome"], good["result"], good["steps_passed"]) == ("ok", "passed", 21)
        assert bad["outcome"] == "failed" and bad["steps_passed"] < 21
        assert "no reply from module 1" in bad["error"]
        assert "28 ok" not in bad["log"] and "ok    select 0" in good["log"]
    suite = ET.parse(out / "junit.xml").getroot().find("testsuite")
    assert suite.get("name") == "pair_rotate.hbs"
    assert (suite.get("tests"), suite.get("failures"), suite.get("errors")) == ("4", "2", "0")
    failed = [c for c in suite.iter("testcase") if c.find("failure") is not None]
    assert {c.get("classname") for c in failed} == {"broken-build.pair"}
    assert "no reply from module 1" in failed[0].find("failure").get("message")
    assert "JUnit:" in capsys.readouterr().err


def test_the_simulator_url_refuses_a_folder_without_images(tmp_path):
    from hexbot.hil_sim import urlhandler

    urlhandler.register()
    with pytest.raises(serial.SerialException, match="does not exist"):
        serial.serial_for_url(f"hexbot-sim://pair?speed=0&firmware={tmp_path}")


def test_plan_tasks_give_the_planning_bench_figures(write_spec, tmp_path, embedded_client):
    from hexbot.bench.planning import bench_blobs

    rows = run_here(write_spec('kind = "plan"\n[grid]\nfamily = "blob"\nmodules = 10\n'
                               'seed = { start = 0, stop = 2 }\n'), embedded_client,
                    tmp_path / "out")
    bench = {int(r["family"].split()[-1]): r for r in bench_blobs([10], 2)}
    for row in rows:
        expected = bench[row["seed"]]
        assert row["outcome"] == "ok" and row["reached"]
        for key in ("moves", "time_steps", "move_lower_bound", "step_lower_bound", "method"):
            assert row[key] == expected[key], key
    text = report(tmp_path / "out")
    assert "| case | modules | method | reached |" in text  # docs/planning.md's table
    assert "| blob seed 1 | 10 |" in text


def _fake_trial_module(monkeypatch, trial=None) -> None:
    module = types.ModuleType("hexbot.bench.ir_noise")
    if trial is not None:
        module.trial = trial
    monkeypatch.setitem(sys.modules, "hexbot.bench.ir_noise", module)


IR_NOISE = 'kind = "ir-noise"\n[grid]\nframing = ["legacy", "mavlink"]\nber = [0, 0.01]\n' \
           'seed = [1, 2]\n'


def test_ir_noise_without_its_trial_stops_before_anything_runs(write_spec, monkeypatch):
    path = write_spec(IR_NOISE)
    _fake_trial_module(monkeypatch)  # a module, but no trial() in it
    with pytest.raises(ScenarioError, match=rf"{path}:1: .*ir_noise has no such function"):
        load_spec(path)
    monkeypatch.setitem(sys.modules, "hexbot.bench.ir_noise", None)  # not importable
    with pytest.raises(ScenarioError, match=rf"{path}:1: kind ir-noise needs .*trial"):
        load_spec(path)


def test_ir_noise_runs_the_real_trial_and_checks_its_values_first(write_spec, tmp_path):
    from distributed import Client

    spec = ('kind = "ir-noise"\n[grid]\nframing = ["legacy", "mavlink"]\nber = 0.001\n'
            'seed = 1\ncommands = 3\n')
    with Client(processes=False, n_workers=1, threads_per_worker=1,
                dashboard_address="127.0.0.1:0") as client:
        rows = run_here(write_spec(spec), client, tmp_path / "out")
    assert [(r["framing"], r["outcome"]) for r in rows] == [("legacy", "ok"), ("mavlink", "ok")]
    assert all(r["executed"] + r["lost"] == 3 for r in rows)
    for bad, words in ((("framing", '"bogus"'), "framing 'bogus' is not one of legacy, mavlink"),
                       (("ber", "1.5"), "a bit error rate is 0..1, got 1.5"),
                       (("commands", "0"), "a trial sends at least 1 command, got 0")):
        values = {"framing": '"legacy"', "ber": "0.0", "commands": "3", **dict([bad])}
        path = write_spec('kind = "ir-noise"\n[grid]\n'
                          + "".join(f"{k} = {v}\n" for k, v in values.items()))
        with pytest.raises(ScenarioError, match=words):
            load_spec(path)


def test_ir_noise_puts_the_trial_on_the_grid(write_spec, tmp_path, monkeypatch):
    from distributed import Client

    calls = []

    def trial(framing: str, ber: float, seed: int, commands: int) -> dict:  # unit-test double
        calls.append((framing, ber, seed, commands))
        return {"delivered": commands - int(ber * 100) * seed, "framing_ok": framing == "mavlink",
                "framing": framing, "ber": ber}  # echoed inputs, as the real trial does

    _fake_trial_module(monkeypatch, trial)
    # threads in this process: the double is visible to the tasks
    with Client(processes=False, n_workers=1, threads_per_worker=2,
                dashboard_address="127.0.0.1:0") as client:
        rows = run_here(write_spec(IR_NOISE), client, tmp_path / "out")
    assert sorted(calls) == sorted((f, float(b), s, 100) for f in ("legacy", "mavlink")
                                   for b in (0, 0.01) for s in (1, 2))
    assert {r["outcome"] for r in rows} == {"ok"}
    assert {(r["framing"], r["ber"], r["seed"]): r["delivered"] for r in rows}[
        ("legacy", 0.01, 2)] == 98
    text = report(tmp_path / "out")
    assert ("| framing | ber | runs | ok | failed | error | mean delivered | mean seconds |"
            in text)
    assert "| legacy | 0.01 | 2 | 2 | 0 | 0 | 98.5 |" in text


def test_a_dotted_path_kind_runs_any_pure_function(write_spec, tmp_path, embedded_client):
    rows = run_here(write_spec('kind = "hexbot.bench.sweep:noop"\n[grid]\n'
                               'seed = { start = 0, stop = 5 }\n'), embedded_client,
                    tmp_path / "out")
    assert sorted((r["seed"], r["echo"], r["outcome"]) for r in rows) == [
        (s, s, "ok") for s in range(5)]
    assert "5 tasks of kind hexbot.bench.sweep:noop: ok 5" in report(tmp_path / "out")


def test_a_task_that_raises_is_an_error_row_and_the_sweep_goes_on(write_spec, tmp_path,
                                                                  embedded_client):
    # a ledge too short for a strip of 5 (each value is fine on its own, so
    # the file passes its checks): the kind raises, the row says why
    (tmp_path / "ledge.map").write_text("..............#\n....ooo.......#\n"
                                        "....###.......#\n###############\n")
    rows = run_here(write_spec('kind = "locomotion"\n[grid]\nruleset = "salvador-free"\n'
                               'scenario = "ledge.map"\nn = [5, 3]\nround_limit = 20\n'),
                    embedded_client, tmp_path / "out")
    by_n = {r["n"]: r for r in rows}
    assert by_n[5]["outcome"] == "error" and "ScenarioError" in by_n[5]["error"]
    assert "nothing holds the cell below" in by_n[5]["error"]
    assert by_n[3]["outcome"] == "ok"
    text = report(tmp_path / "out")
    assert "failed tasks (1):" in text and "n=5: error: ScenarioError" in text


@pytest.mark.parametrize(("how", "error"), [("exit", "SystemExit: 3"),
                                            ("interrupt", "KeyboardInterrupt: ")])
def test_a_task_that_exits_or_is_interrupted_is_an_error_row_not_a_dead_worker(how, error):
    from hexbot.sweep.engine import execute

    row = execute("tests.sweep.sample_tasks:misbehave", {"seed": 2, "how": how})
    assert (row["outcome"], row["error"]) == ("error", error)


def test_a_task_that_kills_its_worker_costs_the_others_nothing(write_spec, tmp_path):
    from hexbot.sweep.engine import connect

    spec = load_spec(write_spec('kind = "tests.sweep.sample_tasks:misbehave"\n[grid]\n'
                                'seed = { start = 0, stop = 6 }\nhow = "die"\n'))
    with connect(workers=2) as client, \
            ResultStore(tmp_path / "out", spec.kind.name, spec.param_names) as store:
        outcome = run_sweep(spec, client, store)
    rows = read_table(tmp_path / "out").to_pylist()
    assert [r["seed"] for r in rows] == [0, 1, 3, 4, 5]  # every healthy task, in grid order
    assert all(r["outcome"] == "ok" for r in rows)
    assert (outcome.stored, outcome.lost) == (5, 1)
    assert "seed=2" in outcome.lost_reason and "worker died" in outcome.lost_reason
