"""Several modules on one IR link: Select(id...) addresses commands, and
acknowledgements are staggered by rank so that they never collide."""

from __future__ import annotations

import pytest
from fwsim import QUIET_S, Bench

from hexbot.hil_sim.module import LED_PINS
from hexbot.protocol import frames, parser


@pytest.fixture
def flower(images) -> Bench:
    bench = Bench.boot("flower7")
    bench.drain()  # the boot texts
    bench.sim.events.clear()
    return bench


def collisions(bench: Bench) -> list[dict]:
    return [e for e in bench.sim.events if e["event"] == "ir-collision"]


def acks(replies) -> list[tuple[int, int | None]]:
    assert all(isinstance(r, parser.Ack) for r in replies), replies
    return [(r.code, r.module) for r in replies]


def test_select_all_every_module_answers_in_id_order_without_collision(flower: Bench):
    replies = flower.command("Select", 0, settle=QUIET_S)  # one reply per module, no more
    assert acks(replies) == [(69, i) for i in range(1, 8)]
    assert not [e for e in flower.events() if isinstance(e, parser.Garbage)]
    # Forwarded to seven control boards: the echo delay does not shift the slots.
    assert acks(flower.command("JxOpenAll", settle=QUIET_S)) == [(3, i) for i in range(1, 8)]
    assert all(m.control.port("A")[1] & 0x3F == 0x3F for m in flower.sim.modules.values())
    assert collisions(flower) == []


def test_status_of_seven_modules(flower: Bench):
    flower.command("Select", 0)
    replies = flower.command("Status")
    assert [(r.module_id, r.role, r.localized) for r in replies] == [
        (i, "M", False) for i in range(1, 8)
    ]
    assert collisions(flower) == []


def test_only_the_selected_module_executes(flower: Bench):
    assert acks(flower.command("Select", 3)) == [(69, 3)]
    assert acks(flower.command("LOn", settle=QUIET_S)) == [(44, 3)]  # nobody else answers
    for ident, module in flower.sim.modules.items():
        port, bit = LED_PINS["led_j1"]
        lit = not module.comm.port(port)[1] >> bit & 1
        assert lit == (ident == 3), ident
    assert acks(flower.command("JxOpen", 2)) == [(1, 3)]
    opened = {i for i, m in flower.sim.modules.items() if m.control.port("A")[1] & (1 << 3)}
    assert opened == {3}


def test_rank_is_the_position_in_the_select_list(flower: Bench):
    assert acks(flower.command("Select", 5, 2, 7)) == [(69, 5), (69, 2), (69, 7)]
    assert acks(flower.command("LOff")) == [(45, 5), (45, 2), (45, 7)]
    assert collisions(flower) == []


def test_invalid_select_keeps_the_previous_selection(flower: Bench):
    flower.command("Select", 4)
    flower.drain()
    flower.send(frames.encode_pc(frames.make(69, 64, strict=False), strict=False))
    flower.run(2.0)
    assert flower.replies() == []
    assert acks(flower.command("LOn")) == [(44, 4)]


def test_roles_and_prefixes_in_addressed_mode(flower: Bench):
    flower.command("Select", 6)
    flower.command("SetRole", 2)
    flower.command("Select", 0)
    replies = flower.command("Status")
    assert [r.role for r in replies] == ["M", "M", "M", "M", "M", "S", "M"]
    assert [r.prefix_role for r in replies] == ["M", "M", "M", "M", "M", "S", "M"]
