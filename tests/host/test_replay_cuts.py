"""A replay decodes as the live session did, also where the live reader ran
late: the session's capture records where its decoder cut a half reply
(``cut``), and a replay of it cuts there and nowhere else."""

from __future__ import annotations

import json
import os
import time
import tty

import pytest

from hexbot.cli import main
from hexbot.errors import ScenarioError
from hexbot.host.capture import Record, read_capture
from hexbot.host.host import IR, QUIET_FLUSH_S, Host, ReplayDecoders
from hexbot.host.link import Link, PortSettings
from hexbot.host.session_log import SessionLog
from hexbot.protocol import parser

REPLY = parser.reply_ack(69, "S", 1)  # b"\n\r\n\rS01: ACKE\n\r"
HALF = len(REPLY) // 2 + 1


def kinds(events):
    return [type(ev).__name__ for *_, ev in events]


def acked(events) -> bool:
    """Module 1's ACK came whole (the tail of a cut one reads without an id)."""
    return any(type(ev).__name__ == "Ack" and ev.module == 1 for *_, ev in events)


def rx(t, data, fmt):
    return Record(t, IR, "rx", data=data, format=fmt)


def test_a_format_2_replay_joins_reads_far_apart_that_the_live_session_joined():
    # the live reader read the halves 5 s apart and recorded no cut: one reply
    dec = ReplayDecoders()
    assert dec.play(rx(10.0, REPLY[:HALF], 2)) == []
    whole = dec.play(rx(15.0, REPLY[HALF:], 2))
    assert kinds(whole) == ["Ack"] and acked(whole)
    assert dec.flush() == []


def test_a_format_2_replay_cuts_where_the_live_session_cut_and_stamps_as_it_did():
    dec = ReplayDecoders()
    dec.play(rx(10.0, REPLY[:HALF], 2))
    cut = dec.play(Record(11.3, IR, "cut", text="11.050", format=2))
    assert kinds(cut) == ["Garbage"] and cut[0][0] == 11.05
    assert not acked(dec.play(rx(11.5, REPLY[HALF:], 2)) + dec.flush())


def test_a_format_1_replay_still_judges_the_quiet_second_by_read_times():
    dec = ReplayDecoders()
    dec.play(rx(10.0, REPLY[:HALF], 1))
    late = dec.play(rx(10.0 + 2 * QUIET_FLUSH_S, REPLY[HALF:], 1)) + dec.flush()
    assert kinds(late)[0] == "Garbage" and not acked(late)


def write_capture(path, first_line, body):
    path.write_text(f"{first_line}\n# start 2026-11-28T00:00:00.000+00:00\n{body}",
                    encoding="utf-8")
    return path


def test_cut_records_are_read_from_format_2_and_refused_in_format_1(tmp_path):
    ok = write_capture(tmp_path / "a.hbcap", "# hexbot-capture 2", "1.000 ir cut 0.950\n")
    (rec,) = read_capture(ok)
    assert (rec.kind, rec.text, rec.format) == ("cut", "0.950", 2)
    old = write_capture(tmp_path / "b.hbcap", "# hexbot-capture 1",
                        "1.000 ir cut 0.950\n2.000 ir rx 41\n")
    with pytest.raises(ScenarioError, match=r"b.hbcap:3: unknown record kind 'cut'"):
        list(read_capture(old))
    bad = write_capture(tmp_path / "c.hbcap", "# hexbot-capture 2",
                        "1.000 ir cut soon\n2.000 ir rx 41\n")
    with pytest.raises(ScenarioError, match=r"c.hbcap:3: a cut needs the time stamp"):
        list(read_capture(bad))


# --- a live session behind a pty, replayed by the CLI --------------------------


@pytest.fixture
def module_pty():
    """The module's end of a pty (its master); the host opens the slave."""
    master, slave = os.openpty()
    tty.setraw(slave)
    try:
        yield master, os.ttyname(slave)
    finally:
        os.close(master)
        os.close(slave)


def wait_for(predicate, what: str, limit_s: float = 20.0):
    end = time.monotonic() + limit_s  # a bound against a hang, not a measurement
    while not predicate():
        assert time.monotonic() < end, f"never saw {what}"
        time.sleep(0.02)


def live_session(tmp_path, name, module_pty, monkeypatch, lag_first_read_s):
    """A host with a session log on the pty whose reader sleeps
    ``lag_first_read_s`` after its first read that found bytes."""
    deliver = Link._deliver
    lagged = []

    def late(self, data: bytes) -> None:
        deliver(self, data)
        if data and not lagged:
            lagged.append(data)
            time.sleep(lag_first_read_s)

    monkeypatch.setattr(Link, "_deliver", late)
    log = SessionLog(tmp_path / name)
    host = Host(log=log)
    host.add_port(IR, PortSettings(module_pty[1]))
    host.start(wait_s=3)
    return host, log, lagged


def replayed(capture, capsys) -> list[str]:
    """What ``hexbot replay --json`` decodes (received events only)."""
    capsys.readouterr()
    assert main(["replay", "--json", str(capture)]) == 0
    kinds = [json.loads(line)["kind"] for line in capsys.readouterr().out.splitlines()]
    return [k for k in kinds if k not in ("tx", "state", "note")]


def console_replayed(capture) -> list[str]:
    """What the console's replay (``Host.replay``) decodes."""
    host = Host()
    host.replay(read_capture(capture))
    return live_kinds(host)


def live_kinds(host) -> list[str]:
    return [type(o.event).__name__.lower() for o in host.since(0)]


def acked_live(host) -> bool:
    return acked([(o.t, o.event) for o in host.since(0)])


@pytest.mark.wallclock
def test_a_reply_a_late_reader_read_whole_replays_whole(tmp_path, module_pty, monkeypatch, capsys):
    # the reader gets the first half, sleeps 2.5 quiet seconds, then reads the
    # rest: the line had no gap, the live session saw one ACK, so must a replay
    master = module_pty[0]
    host, log, lagged = live_session(tmp_path, "late", module_pty, monkeypatch,
                                     2.5 * QUIET_FLUSH_S)
    try:
        os.write(master, REPLY[:HALF])
        wait_for(lambda: lagged, "the first read")
        os.write(master, REPLY[HALF:])
        wait_for(lambda: live_kinds(host), "the reply")
        time.sleep(2 * QUIET_FLUSH_S)  # nothing more comes, nothing is cut
        assert live_kinds(host) == ["ack"] and acked_live(host)
    finally:
        host.close()
        log.close()
    rx_times = [r.t for r in read_capture(log.capture_path) if r.kind == "rx"]
    assert len(rx_times) == 2 and rx_times[1] - rx_times[0] > 2 * QUIET_FLUSH_S
    assert replayed(log.capture_path, capsys) == ["ack"]
    assert console_replayed(log.capture_path) == ["ack"]


@pytest.mark.wallclock
def test_a_reply_cut_live_by_a_quiet_second_replays_cut(tmp_path, module_pty, monkeypatch, capsys):
    master = module_pty[0]
    host, log, _ = live_session(tmp_path, "cut", module_pty, monkeypatch, 0.0)
    try:
        os.write(master, REPLY[:HALF])
        wait_for(lambda: live_kinds(host), "the half reply cut as garbage")
        os.write(master, REPLY[HALF:])
        wait_for(lambda: len(live_kinds(host)) >= 2, "the rest cut as garbage")
        live = live_kinds(host)
    finally:
        host.close()
        log.close()
    assert live[0] == "garbage"
    assert [r.kind for r in read_capture(log.capture_path)].count("cut") == 1
    assert replayed(log.capture_path, capsys) == live
    assert console_replayed(log.capture_path) == live
