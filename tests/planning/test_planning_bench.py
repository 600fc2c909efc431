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
