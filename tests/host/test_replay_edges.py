"""`hexbot replay` at the edges of what a user asks (a mutation audit): a
window whose ends fall exactly on a record, several --port options, --no-tx,
a reply the window cuts, and a paced replay that seeks with --from."""

from __future__ import annotations

import json

from hexbot.cli import main
from hexbot.protocol import parser

NOTES = "1.000 host note one\n2.000 host note two\n3.000 host note three\n"


def _capture(tmp_path, body, name="c.hbcap"):
    path = tmp_path / name
    path.write_text(f"# hexbot-capture 2\n# start 2026-11-28T00:00:00.000+00:00\n{body}",
                    encoding="utf-8")
    return path


def _rows(capsys, *argv):
    capsys.readouterr()
    assert main(["replay", "--json", *map(str, argv)]) == 0
    return [json.loads(line) for line in capsys.readouterr().out.splitlines()]


def _texts(rows):
    return [r.get("text", r["kind"]) for r in rows]


def test_from_prints_the_record_stamped_at_exactly_from(tmp_path, capsys):
    # "print from T seconds on": a record at T is on
    assert _texts(_rows(capsys, _capture(tmp_path, NOTES), "--from", "2")) == ["two", "three"]


def test_to_prints_the_record_stamped_at_exactly_to(tmp_path, capsys):
    # "stop after T": a record at T is before the stop
    assert _texts(_rows(capsys, _capture(tmp_path, NOTES), "--to", "2")) == ["one", "two"]


def test_a_window_of_one_instant_is_no_usage_error(tmp_path, capsys):
    # --to equal to --from is not "before" it: the record at that time
    assert _texts(_rows(capsys, _capture(tmp_path, NOTES), "--from", "2", "--to", "2")) == [
        "two"]


def test_port_is_repeatable(tmp_path, capsys):
    body = ("1.000 host note from host\n"
            f"2.000 ir rx {parser.reply_ack(65, 'S', 1).hex()}\n"
            "3.000 sim note from sim\n")
    rows = _rows(capsys, _capture(tmp_path, body), "--port", "ir", "--port", "host")
    assert [(r["port"], r["kind"]) for r in rows] == [("host", "note"), ("ir", "ack")]


def test_no_tx_hides_what_the_pc_sent(tmp_path, capsys):
    body = "1.000 ir tx 2a45014e4e4e4e4e4e4e23\n" f"1.500 ir rx {parser.reply_ack(69).hex()}\n"
    capture = _capture(tmp_path, body)
    assert [r["kind"] for r in _rows(capsys, capture)] == ["tx", "ack"]
    assert [r["kind"] for r in _rows(capsys, capture, "--no-tx")] == ["ack"]


def test_a_reply_the_window_cuts_is_not_garbage(tmp_path, capsys):
    # the reply's second half comes after --to: the window ends before the
    # reply does, and the half before it is no garbage of the session's
    reply = parser.reply_ack(69, "S", 1)
    body = (f"0.500 host note start\n1.000 ir rx {reply[:6].hex()}\n"
            f"3.000 ir rx {reply[6:].hex()}\n")
    assert _texts(_rows(capsys, _capture(tmp_path, body), "--to", "2")) == ["start"]


def test_a_paced_replay_starts_at_from_without_waiting_for_the_records_before(
        tmp_path, capsys, monkeypatch):
    # --from 30 --speed X seeks: the replay's clock starts at 30 s, so the
    # first record prints at once instead of 30 s / X later
    from hexbot.host import cli_replay

    starts = []

    class Watched(cli_replay.ReplayControl):
        def __init__(self, *args, **kwargs) -> None:
            super().__init__(*args, **kwargs)
            starts.append(self.position())

    monkeypatch.setattr(cli_replay, "ReplayControl", Watched)
    capture = _capture(tmp_path, "0.100 host note early\n30.000 host note late\n")
    assert _texts(_rows(capsys, capture, "--from", "30", "--speed", "64")) == ["late"]
    assert len(starts) == 1 and starts[0] >= 30


def test_a_capture_that_cannot_be_read_is_one_line_with_its_cause(tmp_path, capsys):
    """The OS's reason once, not Python's ``[Errno 2] ...: 'path'`` with the
    path a second time; a session folder names the capture inside it."""
    missing = tmp_path / "gone.hbcap"
    assert main(["replay", str(missing)]) == 1
    err = capsys.readouterr().err.strip()
    assert err == f"hexbot replay: error: {missing}: cannot read capture: No such file or directory"
    assert main(["replay", str(tmp_path)]) == 1
    err = capsys.readouterr().err.strip()
    assert err == (f"hexbot replay: error: {tmp_path / 'capture.hbcap'}: cannot read capture: "
                   "No such file or directory")


def test_a_replayed_module_is_not_checked_against_this_hosts_protocol():
    """The recorded modules spoke to the capture's host: a Status whose
    schema differs from this host's (any capture older than the last
    protocol change) is no warning in a replay, where the console showed it
    for every module."""
    from pathlib import Path

    from hexbot.host.capture import read_capture
    from hexbot.host.host import Host
    from hexbot.protocol.header import SCHEMA_HASH

    capture = Path(__file__).parent / "data" / "flower7_session.hbcap"
    host = Host()
    host.replay(read_capture(capture))
    schemas = {o.event.schema for o in host.since(0) if isinstance(o.event, parser.StatusReport)}
    assert schemas and SCHEMA_HASH not in schemas  # recorded before this host's protocol
    assert host.warnings == []
