"""Salvador's no-obstacle rules reproduce Table 1 of 001 round for round."""

import pytest

from hexbot.planning.locomotion import flat_scenario, load_ruleset, simulate

# Table 1 of 001_c2c1d60ca63d03fa.txt (lines ~1190-1200), typed in from the text:
# rounds to advance k positions with n modules, no obstacles.
TABLE_1 = {
    1: {5: 7, 10: 12, 20: 22, 50: 52, 100: 102},
    2: {5: 11, 10: 16, 20: 26, 50: 56, 100: 106},
    5: {5: 23, 10: 28, 20: 38, 50: 68, 100: 118},
    10: {5: 43, 10: 48, 20: 58, 50: 88, 100: 138},
    50: {5: 203, 10: 208, 20: 218, 50: 248, 100: 298},
}


@pytest.mark.parametrize("n", [5, 10, 20, 50, 100])
def test_rounds_to_advance_match_table_1(n):
    rs = load_ruleset("salvador-free")
    result = simulate(rs, flat_scenario(n), rounds=1000, until_advance=50)
    assert result.status == "advanced"
    ours = {k: result.advance_rounds[k - 1] for k in TABLE_1}
    assert ours == {k: row[n] for k, row in TABLE_1.items()}


def test_each_relocated_module_moves_n_times():
    # Chapter 7: "each module moves exactly n times in order to traverse the strip".
    n = 12
    result = simulate(load_ruleset("salvador-free"), flat_scenario(n), until_advance=3)
    assert result.moves_per_module[:3] == [n] * 3
    assert all(m < n for m in result.moves_per_module[3:])  # later ones are on their way
    pairs = zip(result.positions, result.states, strict=True)
    resting = sorted(p for p, s in pairs if s == "static")
    assert resting[-3:] == [(n, 0), (n + 1, 0), (n + 2, 0)]


def test_run_never_breaks_an_invariant_over_long_runs():
    result = simulate(load_ruleset("salvador-free"), flat_scenario(7), rounds=600)
    assert result.status == "rounds-exhausted"
    assert result.violation is None
    assert result.advanced >= 140  # (600 - 7 + 2) / 4 relocations
