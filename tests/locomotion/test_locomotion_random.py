"""Random obstacle maps: the generator, `hexbot locomotion random`, and the
two invariant breaks it found beyond the bank, each fixed by a tagged rule."""

import json

import pytest
from ruletext import shipped, without_tag

from hexbot.cli import main
from hexbot.planning.locomotion import load_scenario, loads, simulate
from hexbot.planning.locomotion.randommaps import random_map, random_scenario, sweep


def test_a_seed_always_gives_the_same_map_and_the_strip_at_its_foot():
    assert random_map(153) == random_map(153)
    assert random_map(153) != random_map(154)
    sc = random_scenario(153, 12)
    assert len(sc.modules) == 12 and {y for _, y in sc.modules} == {1}
    assert load_scenario("random-153", 12).modules == sc.modules
    assert load_scenario("random-153-north", 12).direction == (0, 1)


# (rule set, seed, n, tag): with the tag left out the run breaks an invariant.
FOUND = [
    # A cork between two active modules walking off in opposite directions.
    ("salvador", 153, 12, "ORPHAN", "disconnected"),
    # The same round a cork under a convex transition (Rule 7) lost its link.
    ("salvador", 787, 20, "ORPHAN", "disconnected"),
    # A superactive turned diagonally into the path of an active that had come
    # within two cells after the superactive was detected.
    ("otero", 237, 20, "SUPER_CLEAR", "collision"),
]


@pytest.mark.parametrize(("ruleset", "seed", "n", "tag", "kind"), FOUND)
def test_random_maps_that_broke_an_invariant_now_hold(ruleset, seed, n, tag, kind):
    text = shipped(ruleset)
    ours = simulate(loads(text), random_scenario(seed, n), rounds=2500)
    assert ours.violation is None, ours.violation
    old = simulate(loads(without_tag(text, tag)), random_scenario(seed, n), rounds=2500)
    assert old.violation is not None and old.violation.kind == kind


def test_sweep_counts_every_run_and_reports_violations_in_full():
    report = sweep(loads(without_tag(shipped("salvador"), "ORPHAN")), range(153, 155), [12])
    assert report.runs == 2 and sum(report.outcomes.values()) == 2
    assert [(v["seed"], v["n"], v["kind"]) for v in report.violations] == [
        (153, 12, "disconnected")]


def test_cli_random_prints_json_and_fails_on_a_violation(capsys, tmp_path):
    assert main(["locomotion", "random", "salvador", "--seeds", "150:153", "--n", "5",
                 "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["runs"] == 3 and out["violations"] == []
    old = tmp_path / "old.rules"
    old.write_text(without_tag(shipped("salvador"), "ORPHAN"))
    # a broken invariant: failed (1)
    assert main(["locomotion", "random", str(old), "--seeds", "153:154", "--n", "12"]) == 1
    assert "random-153 n = 12: disconnected" in capsys.readouterr().out


def test_cli_random_refuses_a_bad_seed_range(capsys):
    assert main(["locomotion", "random", "salvador", "--seeds", "9:3"]) != 0
    assert "--seeds" in capsys.readouterr().err
