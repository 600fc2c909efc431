"""A bad option value is a usage error (exit 2) with a one-line reason: not a
traceback, a hang, or exit 0 on nonsense (found by a fuzz pass)."""

import pytest

B = ("bench",)
CASES = [
    # tracebacks
    (B + ("sim", "--seconds", "nan"), "argument --seconds: not a finite number"),
    (B + ("sim", "--seconds", "inf"), "argument --seconds: not a finite number"),
    (B + ("sim", "--seconds", "1e400"), "argument --seconds: not a finite number"),
    (B + ("sim-core", "--busy-cycles", "0"), "argument --busy-cycles: must be at least 1"),
    (B + ("sim-core", "--idle-seconds", "nan"), "argument --idle-seconds: not a finite"),
    (B + ("sim-core", "--idle-seconds", "inf"), "argument --idle-seconds: not a finite"),
    (B + ("sim-core", "--repeat", "0"), "argument --repeat: must be at least 1"),
    (B + ("sim-core", "--repeat", "-1"), "argument --repeat: must be at least 1"),
    (B + ("isp", "--repeat", "0"), "argument --repeat: must be at least 1"),
    (B + ("isp", "--repeat", "-1"), "argument --repeat: must be at least 1"),
    (B + ("planning", "--hub", "-1"), "argument --hub: must be 2..100,000, got -1"),
    (B + ("surface", "--sizes", "abc"), "argument --sizes: not a whole number: 'abc'"),
    (B + ("surface", "--sizes", "nan"), "argument --sizes: not a whole number: 'nan'"),
    (B + ("ir-noise", "--rates", "abc"), "argument --rates: not a number: 'abc'"),
    (B + ("ir-noise", "--rates", ""), "argument --rates: empty list"),
    (B + ("ir-noise", "--framings", "nosuch"), "argument --framings: unknown 'nosuch'"),
    (B + ("ir-noise", "--framings", ""), "argument --framings: empty list"),
    (B + ("pyramid-search", "--samples", "0"), "argument --samples: must be at least 1"),
    (B + ("pyramid-search", "--samples", "-1"), "argument --samples: must be at least 1"),
    (("locomotion", "random", "salvador", "--seeds", "0:99999999999999999999"),
     "--seeds: expected FIRST:END"),
    (("sim", "pair", "--duration", "1", "--speed", "1e-300"),
     "argument --speed: must be 0 (as fast as it goes) or at least 0.001"),
    # hangs, or a value silently ignored
    (B + ("sim-core", "--busy-cycles", "-1"), "argument --busy-cycles: must be at least 1"),
    (B + ("sim-core", "--idle-seconds", "-1"), "argument --idle-seconds: must be more than 0"),
    (B + ("planning", "--scan", "0"), "argument --scan: must be at least 1, got 0"),
    (B + ("planning", "--exhaustive", "0"), "argument --exhaustive: must be 2..100,000, got 0"),
    (B + ("planning", "--hub", "0"), "argument --hub: must be 2..100,000, got 0"),
    (("send", "Status", "--scenario", "pair", "--expect", "99999"),
     "argument --expect: must be 1..255, got 99999"),
    # exit 0 on nonsense
    (B + ("host", "--repeat", "0"), "argument --repeat: must be at least 1"),
    (B + ("host", "--repeat", "-1"), "argument --repeat: must be at least 1"),
    (B + ("ir-noise", "--commands", "0"), "argument --commands: must be at least 1"),
    (B + ("ir-noise", "--commands", "-1"), "argument --commands: must be at least 1"),
    (B + ("planning", "--seeds", "0"), "argument --seeds: must be at least 1"),
    (B + ("planning", "--seeds", "-1"), "argument --seeds: must be at least 1"),
    (B + ("planning", "--scan", "-1"), "argument --scan: must be at least 1, got -1"),
    (B + ("planning", "--exhaustive", "-1"), "argument --exhaustive: must be 2..100,000"),
    (("locomotion", "bank", "--n", "5,,10"), "argument --n: an empty item in '5,,10'"),
    (("locomotion", "random", "salvador", "--n", "5,,10"), "argument --n: an empty item"),
    (("locomotion", "tables", "--only", ""), "--only: empty list"),
    (B + ("planning", "--sizes", ""), "--sizes: empty list"),
    # unclear: the scenario's rule, named by the option
    (B + ("ir-noise", "--rates", "1.5"),
     "argument --rates: each fault rate of the run's scenario is set to it: "
     "bit_error_rate must be a probability 0..1, not 1.5"),
]


@pytest.mark.parametrize("argv, words", CASES, ids=[" ".join(a) for a, _ in CASES])
def test_a_bad_value_is_a_usage_error(cli_status, argv, words):
    code, err = cli_status(*argv)
    assert code == 2, err
    assert words in err
    assert "Traceback" not in err
