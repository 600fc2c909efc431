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
        assert row["moves"] >= row["move_bound"] > 0
        assert row["steps"] >= row["step_bound"] > 0
        assert row["move_bound_kind"] == "assignment" and row["peak_mib"] > 0
    table = summary(rows)
    assert "| scramble | 10 | yes | 2/2 |" in table
