"""LED patterns of the comm board, read from its pins: the walks (LCircle,
LColor, JointTest) and the echo of the control board's rotations, which are
the same patterns as the actuators' (common/sequence.c)."""

from __future__ import annotations

import pytest
from fwsim import Bench
from test_functions import NEG, POS, ROTATIONS

from hexbot.hil_sim.module import LED_PINS


def lit(ports: dict[str, int]) -> frozenset[str]:
    return frozenset(n for n, (port, bit) in LED_PINS.items() if not ports[port] >> bit & 1)


def record_leds(bench: Bench, key: str, *args: int) -> list[tuple[float, frozenset[str]]]:
    """Send one command; return (seconds after the first change, LEDs lit) for
    every distinct LED state the comm board went through."""
    changes: list = []
    bench.sim.pin_sinks.append(changes.extend)
    bench.command(key, *args, timeout=20)
    bench.sim.pin_sinks.remove(changes.extend)
    ports = {p: 0xFF for p in "ACDE"}  # replayed from every LED off (the fixture's state)
    states: list = [(None, lit(ports))]
    for cycle, _mod, board, port, value in changes:
        if board != "comm" or port not in ports:
            continue
        ports[port] = value
        now = lit(ports)
        if states[-1][0] is not None and cycle - states[-1][0] < 2000:
            states[-1] = (states[-1][0], now)  # writes microseconds apart are one step
        elif now != states[-1][1]:
            states.append((cycle, now))
    t0 = states[1][0]
    merged = [s for i, s in enumerate(states[1:], 1) if s[1] != states[i - 1][1]]
    return [(round((c - t0) / 1e6, 2), leds) for c, leds in merged]


def as_leds(joints: tuple, magnets: tuple) -> frozenset[str]:
    """An actuator state as the LEDs that show it."""
    on = {f"led_j{j}" for j in range(1, 7) if joints[j - 1]}
    on |= {f"led_s{s}a" for s in range(1, 7) if magnets[s - 1] == POS}
    on |= {f"led_s{s}b" for s in range(1, 7) if magnets[s - 1] == NEG}
    return frozenset(on)


@pytest.mark.parametrize("name", ROTATIONS)
@pytest.mark.parametrize("own", [False, True], ids=["echo", "led-code"])
def test_rotation_leds_show_the_actuator_steps(single: Bench, name: str, own: bool):
    # The echo after MCW..SCCW, and the LED functions LMCW..LSCCW (56-59).
    got = record_leds(single, "L" + name if own else name, 2, 8, 4, 9)
    want = [(t, as_leds(j, m)) for t, j, m in ROTATIONS[name]]
    want[-1] = (want[-1][0], frozenset())
    assert [leds for _t, leds in got] == [leds for _t, leds in want]
    for (t_got, _), (t_want, _) in zip(got, want, strict=True):
        assert abs(t_got - t_want) <= 0.011, (got, want)


def steps(got: list, want: list[frozenset[str]], period: float) -> None:
    """``got`` shows the LED sets ``want`` in order, one every ``period`` s."""
    assert [leds for _t, leds in got] == want
    for k, (t, _leds) in enumerate(got):
        assert abs(t - k * period) <= 0.011, got


def test_circle_lights_joint_then_n_then_p_of_each_side(single: Bench):
    got = record_leds(single, "LCircle", 1, 5)
    order = [f"led_{x}" for s in range(1, 7) for x in (f"j{s}", f"s{s}b", f"s{s}a")]
    steps(got, [leds for name in order for leds in (frozenset({name}), frozenset())], 0.05)


def test_colour_lights_every_joint_then_every_n_then_every_p(single: Bench):
    got = record_leds(single, "LColor", 2, 5)
    groups = [frozenset(n for n in LED_PINS if n.startswith("led_j")),
              frozenset(n for n in LED_PINS if n.endswith("b")),
              frozenset(n for n in LED_PINS if n.endswith("a"))]
    steps(got, [leds for g in groups for leds in (g, frozenset())] * 2, 0.05)


def test_magnet_test_echo_walks_the_pole_leds(single: Bench):
    # SnTest runs on the control board; the comm board shows the same walk.
    got = record_leds(single, "SnTest", 1, 5)
    steps(got, [leds for s in range(1, 7) for leds in (frozenset({f"led_s{s}b"}), frozenset())],
          0.05)
