"""Session log folders and files at their edges (a mutation audit): where
the folder goes, two sessions in one second, and the stamp of a recorded
cut as a replay shows it."""

from __future__ import annotations

import datetime as dt
import json
import types

from hexbot.cli import main
from hexbot.host import session_log
from hexbot.host.host import IR
from hexbot.host.session_log import SessionLog, default_log_root, new_session_dir
from hexbot.protocol import parser


def test_the_default_log_root_is_under_xdg_state_home(tmp_path, monkeypatch):
    monkeypatch.delenv("HEXBOT_LOG_DIR", raising=False)
    monkeypatch.setenv("XDG_STATE_HOME", str(tmp_path / "state"))
    assert default_log_root() == tmp_path / "state" / "hexbot" / "sessions"


def test_two_sessions_started_in_one_second_get_two_folders(tmp_path, monkeypatch):
    # the folder is named by the second: the second session must not write
    # its capture over the first one's
    fixed = dt.datetime(2026, 11, 28, 12, 0, 0, tzinfo=dt.UTC)
    clock = types.SimpleNamespace(UTC=dt.UTC,
                                  datetime=types.SimpleNamespace(now=lambda tz: fixed))
    monkeypatch.setattr(session_log, "dt", clock)
    first, second = new_session_dir(tmp_path), new_session_dir(tmp_path)
    assert (first.name, second.name) == ("20261128-120000", "20261128-120000-1")


def test_a_replay_stamps_a_recorded_cut_to_the_millisecond(tmp_path, capsys):
    # the live session cut a half reply at 4.105 s: the replay's garbage is
    # stamped there, as the live session's was
    log = SessionLog(tmp_path / "s")
    log.received(IR, parser.reply_ack(69, "S", 1)[:6])
    log.cut(IR, 4.105)
    log.close()
    assert main(["replay", "--json", str(tmp_path / "s")]) == 0
    rows = [json.loads(line) for line in capsys.readouterr().out.splitlines()]
    assert [(r["t"], r["kind"]) for r in rows] == [(4.105, "garbage")]



def test_a_simulated_port_is_logged_at_0_s_until_the_simulators_clock_runs(tmp_path):
    # the host's wall clock starts with the host; the simulator's at its
    # port's connection: what comes between is at 0 s of the simulation (the
    # "connecting" line carried wall-clock milliseconds, and two runs of a
    # seed wrote different captures)
    import time

    from hexbot.host.capture import read_capture
    from hexbot.host.endpoints import sim_url
    from hexbot.host.host import Host
    from hexbot.host.link import PortSettings

    log = SessionLog(tmp_path / "s")
    host = Host(log)
    host.add_port(IR, PortSettings(sim_url("pair", 4, 0.0)))
    time.sleep(0.05)  # setting up takes the host time, not the simulation
    host.start(5.0)
    host.close()
    log.close()
    states = [(r.t, r.text.split()[0]) for r in read_capture(log.capture_path)
              if r.kind == "state"]
    assert states[:2] == [(0.0, "connecting"), (0.0, "connected")]
