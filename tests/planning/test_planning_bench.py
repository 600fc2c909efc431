"""The per-family benchmark rows: checked plans, bounds, and the summary table."""

from hexbot.bench.planning import make_pair, plan_pair, summary


def test_family_pairs_share_the_anchor_and_keep_size():
    for family in ("blob", "scramble"):
        a, b = make_pair(family, 30, 1)
        assert len(a) == len(b) == 30 and (0, 0) in a and (0, 0) in b


def test_a_row_is_checked_and_bounded():
    rows = [plan_pair("scramble", 10, seed, True, 30.0) for seed in range(2)]
    for row in rows:
        assert row["planned"] and row["reason"] == "" and row["warnings"] == []
        # a fallback's row says why the methods before it did not plan
        assert (row["tried"] == []) == (row["method"] == "direct")
        assert row["moves"] >= row["move_bound"] > 0
        assert row["steps"] >= row["step_bound"] > 0
        assert row["move_bound_kind"] == "assignment" and row["peak_mib"] > 0
    table = summary(rows)
    assert "| scramble | 10 | yes | 2/2 |" in table


def test_the_exhaustive_and_hub_runs_count_every_pair(capsys):
    from hexbot.bench.planning import exhaustive, through_hub

    assert exhaustive(3) == 0
    out = capsys.readouterr().out
    # 11 shapes of three modules: 110 ordered pairs, each planned free and fixed
    assert "3 modules, 11 shapes, 110 pairs, fixed None: direct 110" in out
    assert "fixed (0, 0): direct 110" in out
    assert through_hub(4) == 0
    assert "44 shapes to the hub and back, fixed None: direct 86" in capsys.readouterr().out


def test_a_failed_pair_is_listed_and_the_run_fails(monkeypatch, capsys):
    from hexbot.bench import planning as bench
    from hexbot.planning.plan import Plan

    def refusing(initial, goal, fixed=None):
        return Plan(mode="robust", initial=initial, goal=goal, reason="no plan found: test")

    monkeypatch.setattr(bench, "plan_robust", refusing)
    assert bench.exhaustive(2) == 1
    assert "no plan found: test" in capsys.readouterr().out
    # --scan too (it printed the failures and exited 0)
    assert bench.scan(2) == 1
    out = capsys.readouterr().out
    assert out.count("no plan found: test") == 2 and "2 random pairs: not reached: 2" in out


def test_the_holes_family_has_holes_in_both_shapes_and_is_reproducible():
    import pytest

    from hexbot.planning.checker import pieces
    from hexbot.planning.generate import blob_pair, holey_blob
    from hexbot.planning.surface import enclosed

    for n, seed in ((7, 0), (10, 3), (30, 1), (300, 2)):
        a, b = make_pair("holes", n, seed)
        assert (a, b) == make_pair("holes", n, seed)
        for shape in (a, b):
            assert len(shape) == n and (0, 0) in shape and pieces(set(shape)) == 1
            holes = enclosed(shape)
            assert holes, (n, seed)
            if n >= 300:  # about 4 % of the cells, carved out of the interior
                assert 0.03 * n <= len(holes) <= 0.06 * n
    plain = blob_pair(300, 2)[0]
    assert len(enclosed(plain)) < 0.01 * 300  # the blob family's shapes have next to none
    with pytest.raises(ValueError, match="at least 7"):
        holey_blob(6, 0)


def test_every_holes_pair_of_10_and_30_is_planned_free_and_fixed():
    from hexbot.planning.checker import check_plan
    from hexbot.planning.configuration import Configuration
    from hexbot.planning.robust import plan_robust

    for n, seeds in ((10, range(4)), (30, range(3))):
        for seed in seeds:
            a, b = make_pair("holes", n, seed)
            for fixed in (None, (0, 0)):
                start = Configuration.from_cells(a)
                plan = plan_robust(start, b, fixed=fixed)
                assert plan.reached, (n, seed, fixed, plan.reason)
                report = check_plan(start, b, plan.steps, fixed)
                assert report.ok, (n, seed, fixed, report.problem)


def test_an_unknown_family_is_a_usage_error_and_a_missed_pair_fails_the_run(capsys):
    import argparse

    import pytest

    from hexbot.bench import planning as bench

    parser = argparse.ArgumentParser()
    bench.add_arguments(parser)
    with pytest.raises(SystemExit) as exit_:
        parser.parse_args(["--families", "blob,rings"])
    assert exit_.value.code == 2
    assert "unknown family 'rings' (known: blob, scramble, holes)" in capsys.readouterr().err
    args = parser.parse_args(["--families", "holes", "--sizes", "10", "--seeds", "1",
                              "--fixed", "no", "--budget", "1e-9", "--json"])
    assert args.families == ["holes"]
    assert bench.run_families(args) == 1  # no time to plan: the pair is not planned
    assert "1 of 1 pairs not planned" in capsys.readouterr().err


def test_enclosed_finds_the_cells_a_shape_walls_in():
    from hexbot.planning.hexlattice import neighbors
    from hexbot.planning.surface import enclosed

    ring = set(neighbors((0, 0)))
    assert enclosed(ring) == {(0, 0)}
    assert enclosed(ring - {(1, 0)}) == set()  # an open side: an inlet, not a hole
    assert enclosed(set()) == set()
    assert enclosed({(0, 0)}) == set()


def test_the_cases_table_fails_the_run_when_a_robust_case_is_not_planned(monkeypatch, capsys):
    import argparse

    from hexbot.bench import planning as bench
    from hexbot.planning.plan import Plan

    parser = argparse.ArgumentParser()
    bench.add_arguments(parser)
    args = parser.parse_args(["--cases", "--sizes", "10", "--blob-sizes", "10",
                              "--apart-sizes", "", "--seeds", "1"])
    assert bench.run(args) == 0
    capsys.readouterr()

    def refusing(initial, goal, fixed=None):
        return Plan(mode="robust", initial=initial, goal=goal, reason="no plan found: test")

    monkeypatch.setattr(bench, "plan_robust", refusing)
    assert bench.run(args) == 1  # it printed the reasons and exited 0
    out = capsys.readouterr().out
    assert "\nparallelogram (10): no plan found: test" in out


def test_the_small_bank_run_fails_when_the_robust_mode_misses_a_case(monkeypatch, capsys):
    import argparse

    from hexbot.bench import planning as bench
    from hexbot.planning import bank, robust
    from hexbot.planning.plan import Plan

    cases = bank.small_cases()[:2]
    monkeypatch.setattr(bank, "small_cases", lambda: cases)
    args = argparse.Namespace(budget=30.0, json=False)
    assert bench.run_small(args) == 0
    capsys.readouterr()

    def refusing(initial, goal, fixed=None, budget=None):
        return Plan(mode="robust", initial=initial, goal=goal, reason="no plan found: test")

    monkeypatch.setattr(robust, "plan_robust", refusing)
    assert bench.run_small(args) == 1  # the gap table printed "-" and exited 0
    out, err = capsys.readouterr()
    assert "no plan found: test" in out
    assert err.strip() == ("robust mode did not plan (or the checker refused): "
                           + ", ".join(c.name for c in cases))
