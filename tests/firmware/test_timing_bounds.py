"""The protocol's time bounds hold on the real firmware: from the end of a
PC frame, the last reply arrives within ``reply_timeout_s``; every boot text
is out by ``boot_seconds``."""

from __future__ import annotations

import pytest
from fwsim import Bench, scenario_file

from hexbot.protocol import frames, parser, timing, wire
from hexbot.protocol.rotation import THESIS_TIMINGS

FRAME_S = timing.wire_seconds(wire.PC_FRAME_LEN, wire.BAUD_IR)


def last_reply_after_frame(bench: Bench, key: str, *args: int, replies: int,
                           limit: float = 60.0) -> float:
    """Seconds from the end of the frame until the last of the ``replies``
    replies its addressing implies (waiting up to ``limit``, not the bound)."""
    bench.drain()
    outcome = bench.session.exchange(frames.make(key, *args), timeout=limit)
    assert outcome.ok and len(outcome.replies) == replies, outcome.reason
    return outcome.waited - FRAME_S


@pytest.fixture
def trio(images, tmp_path) -> Bench:
    """Three modules in a row, ids 2, 5, 7, addressed in that order."""
    bench = Bench.boot(scenario_file(tmp_path, [(2, (0, 0), 0), (5, (1, 0), 0),
                                                (7, (2, 0), 0)]))
    bench.command("Select", 2, 5, 7)
    return bench


@pytest.mark.parametrize("key,args", [
    ("Status", ()),
    ("LOn", ()),
    ("JxOpen", (3,)),
    ("JTest", (2, 5)),
    ("SidePTest", (1, 4)),
    ("MCW", (2, *THESIS_TIMINGS[("CW", "mobile")])),
])
def test_addressed_replies_arrive_within_the_bound(trio: Bench, key: str, args: tuple):
    code = frames.make(key, *args).code
    took = last_reply_after_frame(trio, key, *args, replies=3)
    bound = timing.reply_timeout_s(code, 3, args)
    assert took <= bound, (key, took, bound)
    # And the bound is a bound, not a guess several times too long (the
    # control functions carry the 2.5 s echo time-out the firmware never hits).
    slack = timing.CONTROL_ACK_TIMEOUT_TICKS * timing.TICK_S + 1.0
    assert bound <= took * 1.2 + slack, (key, took, bound)


def test_legacy_substrate_answers_within_the_bound(single: Bench):
    single.command("SetRole", 2)  # substrate: the thesis' 1 s wait
    took = last_reply_after_frame(single, "LOff", replies=1)
    assert 1.0 <= took <= timing.reply_timeout_s(45, 1)


def test_localize_reports_arrive_within_the_bound(images):
    bench = Bench.boot("flower7")
    bench.command("Select", 1)
    bench.command("Ref")
    bench.command("Select", 0)
    took = last_reply_after_frame(bench, "Localize", replies=7, limit=80.0)
    bound = timing.reply_timeout_s(66, 7, last_rank=6)  # Select(0): rank = id - 1
    assert timing.LOCALIZE_WINDOW_S < took <= bound
    reports = [e for e in bench.events() if isinstance(e, parser.Text)
               and e.phrase == "LOCALIZED"]
    assert len(reports) == 6  # everybody but the reference


def listening(bench: Bench) -> list[str]:
    return [e.tail for e in parser.parse_all(bytes(bench.heard))
            if isinstance(e, parser.Text) and e.phrase == wire.TEXT_COMM_LISTENING]


def test_boot_texts_are_out_by_boot_seconds_and_not_long_before(images, tmp_path):
    # id 4's text ends one guard before its slot does
    early = timing.BOOT_GUARD_TICKS * timing.TICK_S + 0.3
    bench = Bench.boot(scenario_file(tmp_path, [(3, (0, 0), 0), (4, (1, 0), 0)]),
                       boot_s=timing.boot_seconds([3, 4]) - early)
    assert listening(bench) == ["ID=03 FW=0.1.0"]  # id 4's slot is not over yet
    bench.run(early)
    assert listening(bench) == ["ID=03 FW=0.1.0", "ID=04 FW=0.1.0"]
