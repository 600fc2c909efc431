"""A host whose reader thread runs late (a loaded machine) beside a paced
simulator: the replies it reads in pieces, seconds of simulated time
apart, are still whole replies, and the waits still see them."""

from __future__ import annotations

import time
from pathlib import Path

import pytest

from hexbot.host import workflows
from hexbot.host.endpoints import sim_url
from hexbot.host.host import IR, Host
from hexbot.host.link import Link, PortSettings
from hexbot.host.session import Session
from hexbot.protocol.parser import Garbage

pytest.importorskip("hexbot.hil_sim._avr")
FIRMWARE = Path(__file__).resolve().parents[2] / "firmware" / "build"
pytestmark = [pytest.mark.wallclock,
              pytest.mark.skipif(not (FIRMWARE / "comm.elf").exists(),
                                 reason="firmware not built (make -C firmware)")]

LAG_S = 0.1  # wall seconds the reader sleeps after each read that found bytes
SPEED = 20.0  # so each lag is 2 simulated seconds: twice the quiet second


def lagging(monkeypatch, lag_s: float) -> None:
    """Every port's reader sleeps ``lag_s`` after each read that found bytes."""
    deliver = Link._deliver

    def late(self, data: bytes) -> None:
        deliver(self, data)
        if data:
            time.sleep(lag_s)

    monkeypatch.setattr(Link, "_deliver", late)


def test_a_reader_that_lags_the_simulator_still_reads_whole_replies(monkeypatch):
    lagging(monkeypatch, LAG_S)
    host = Host()
    host.add_port(IR, PortSettings(sim_url("pair", 1, SPEED)))
    try:
        host.start(5.0)
        session = Session(host)
        session.boot(host.simulator.module_ids())
        booted = host.mark()
        poses = workflows.localize(session, 1)
        assert sorted(poses) == [1, 2]
        garbage = [o for o in host.since(booted) if isinstance(o.event, Garbage)]
        assert garbage == []
    finally:
        host.close()


def test_boot_texts_read_late_still_count_when_no_slot_is_shared(monkeypatch):
    # 0.5 s of wall time is 10 simulated seconds, far outside any boot slot;
    # with seven modules in eight slots no text can be a collision, so each
    # counts whenever it is read, and nobody is asked for a Status
    lagging(monkeypatch, 0.5)
    host = Host()
    host.add_port(IR, PortSettings(sim_url("flower7", 1, SPEED)))
    try:
        host.start(5.0)
        heard, answered = Session(host).boot(host.simulator.module_ids())
        assert (heard, answered) == (set(range(1, 8)), set())
    finally:
        host.close()
