"""The scripting CLI (send, monitor, run, replay) through real ptys."""

from __future__ import annotations

import json
import subprocess
import sys
import threading
import time

from hexbot.cli import main
from hexbot.protocol import wire


def _session(log_dir):
    (folder,) = sorted(log_dir.iterdir())[-1:]
    return folder


def test_send_selects_module_and_prints_its_ack(responder, log_dir, capsys):
    rc = main(["send", "Ref", "--module", "1", "--port", responder.path])
    out = capsys.readouterr()
    assert rc == 0, out.err
    assert "M01 ACK 69 Select" in out.out
    assert "S01 ACK 65 Ref" in out.out
    # Select(1) then Ref() went over the wire byte for byte.
    assert responder.received == [b"*E\x01NNNNNNN#", b"*ANNNNNNNN#"]


def test_send_reports_error_reply_with_nonzero_exit(responder, log_dir, capsys):
    rc = main(["send", "JxOpen", "9", "--unchecked", "--port", responder.path])
    err = capsys.readouterr().err
    assert rc == 1
    assert "ARG_RANGE" in err


def test_send_rejects_out_of_range_argument_before_sending(responder, log_dir, capsys):
    rc = main(["send", "JxOpen", "9", "--port", responder.path])
    assert rc == 1
    assert "must be 1..6, got 9" in capsys.readouterr().err
    assert responder.received == []


def test_send_times_out_clearly(silent_responder, log_dir, capsys):
    rc = main(["send", "Status", "--timeout", "0.3", "--port", silent_responder.path])
    err = capsys.readouterr().err
    assert rc == 3  # a time-out, not a refusal (1) nor a lost port (4)
    assert "Status (70): no reply within 0.3 s (0 received)" in err


def test_send_to_a_module_that_does_not_answer_names_it(silent_responder, log_dir, capsys):
    rc = main(["send", "Status", "--module", "5", "--timeout", "0.3",
               "--port", silent_responder.path])
    assert rc == 3
    assert "no reply from module 5 within 0.3 s" in capsys.readouterr().err


def test_send_to_a_port_that_is_not_there_exits_4(log_dir, capsys):
    rc = main(["send", "Status", "--port", "/nonexistent/ttyUSB9"])
    assert rc == 4
    assert "cannot open /nonexistent/ttyUSB9" in capsys.readouterr().err


def test_send_json_lines(responder, log_dir, capsys):
    rc = main(["send", "Status", "--module", "4", "--json", "--port", responder.path])
    assert rc == 0
    rows = [json.loads(line) for line in capsys.readouterr().out.splitlines()]
    assert rows[0]["kind"] == "ack" and rows[0]["module"] == 4 and rows[0]["code"] == 69
    assert rows[1]["kind"] == "statusreport" and rows[1]["module_id"] == 4


def test_send_as_a_subprocess(responder, log_dir):
    proc = subprocess.run([sys.executable, "-m", "hexbot.cli", "send", "70", "--module", "2",
                           "--port", responder.path], capture_output=True, text=True,
                          timeout=30)
    assert proc.returncode == 0, proc.stderr
    assert "STA id 2" in proc.stdout


def test_monitor_prints_decoded_json_lines(responder, log_dir, capsys):
    def boot():
        time.sleep(0.3)
        responder.write(wire.PREAMBLE + b"COMM. BOARD READY ID=05 FW=0.1.0" + wire.EOL)
        responder.write(wire.PREAMBLE + b"M05: ACK\x14" + wire.EOL)

    threading.Thread(target=boot, daemon=True).start()
    rc = main(["monitor", "--json", "--duration", "1.0", "--port", responder.path])
    assert rc == 0
    rows = [json.loads(line) for line in capsys.readouterr().out.splitlines()]
    assert [r["kind"] for r in rows] == ["text", "ack"]
    assert rows[0]["tail"] == "ID=05 FW=0.1.0"
    assert rows[1]["function"] == "TurnOffAll" and rows[1]["module"] == 5


def test_session_capture_replays_to_the_same_events(responder, log_dir, capsys):
    assert main(["send", "Localize", "--module", "3", "--linger", "0.5",
                 "--port", responder.path]) == 0
    capsys.readouterr()
    folder = _session(log_dir)
    assert main(["replay", str(folder), "--no-tx"]) == 0
    replayed = [line.split(None, 3)[3] for line in capsys.readouterr().out.splitlines()
                if " < " in line]
    decoded = [line.split(None, 3)[3] for line in
               (folder / "decoded.log").read_text().splitlines() if " < " in line]
    assert replayed == decoded
    assert "LOC position (+00,+01)" in replayed


def test_capture_is_byte_exact(responder, log_dir, capsys):
    assert main(["send", "Status", "--module", "2", "--port", responder.path]) == 0
    from hexbot.host.capture import read_capture

    records = list(read_capture(_session(log_dir) / "capture.hbcap"))
    tx = b"".join(r.data for r in records if r.kind == "tx")
    rx = b"".join(r.data for r in records if r.kind == "rx")
    assert tx == responder.received[0] + responder.received[1]
    assert rx.count(b"STA\x02") == 1 and rx.startswith(wire.PREAMBLE)
    stamps = [r.t for r in records]
    assert stamps == sorted(stamps)


def test_scenario_and_port_are_exclusive(log_dir, capsys):
    assert main(["send", "Status", "--scenario", "pair", "--port", "loop://"]) == 2  # usage
    assert "cannot be combined with --port" in capsys.readouterr().err


def test_monitor_over_loop_url_sees_its_own_frames_as_garbage(log_dir, capsys):
    """loop:// echoes: a PC frame is no reply, so the parser calls it garbage."""
    from hexbot.host.host import IR, Host
    from hexbot.host.link import PortSettings
    from hexbot.host.session import Session
    from hexbot.protocol import frames

    with Host() as host:
        host.add_port(IR, PortSettings("loop://"), retry_s=0.1)
        host.start(wait_s=2)
        session = Session(host)
        mark = session.send(frames.make("Ref"))
        obs = session.wait_for(lambda o: True, mark, 3.0)
    assert obs is not None and type(obs.event).__name__ == "Garbage"
    assert obs.event.raw == b"*ANNNNNNNN#"


def test_a_module_with_another_protocol_schema_is_warned_about(responder, log_dir, capsys):
    from hexbot.protocol.header import SCHEMA_HASH

    responder.schema = SCHEMA_HASH ^ 0xFFFF  # firmware built from another protocol table
    assert main(["send", "Status", "--module", "2", "--port", responder.path]) == 0
    err = capsys.readouterr().err
    assert f"warning: module 2: module firmware speaks protocol schema {SCHEMA_HASH ^ 0xFFFF:08x}" \
        in err


def test_a_module_with_this_schema_gives_no_warning(responder, log_dir, capsys):
    assert main(["send", "Status", "--module", "2", "--port", responder.path]) == 0
    assert "warning" not in capsys.readouterr().err


def test_a_port_held_by_another_program_is_busy_and_names_it(responder, log_dir, capsys):
    """Issue 13, defect 7: two programs on one port split its bytes silently."""
    holder = subprocess.Popen(
        [sys.executable, "-c",
         "import serial, sys, time\n"
         f"p = serial.Serial({responder.path!r}, 300, exclusive=True)\n"
         "print('locked', flush=True)\n"
         "time.sleep(60)\n"],
        stdout=subprocess.PIPE, text=True)
    try:
        assert holder.stdout.readline().strip() == "locked"
        rc = main(["send", "Status", "--port", responder.path, "--timeout", "1"])
    finally:
        holder.kill()
        holder.wait()
    err = capsys.readouterr().err
    assert rc == 4, err
    assert f"port busy, held by PID {holder.pid} (" in err and "-c import serial" in err
    reason = next(line for line in err.splitlines() if "port busy" in line)
    assert reason.endswith(")")  # the holder's command line, on the same line
    assert responder.received == []


def test_parse_raw_reads_hex_and_quoted_text():
    import pytest

    from hexbot.errors import FrameError
    from hexbot.host.commands import parse_raw

    assert parse_raw("2A:46 4e") == b"*FN"
    assert parse_raw('"*F\\x4e#"') == b"*FN#"
    assert parse_raw("'ab'") == b"ab"
    for bad in ("2A 4", '""', "", '"\\x4"'):
        with pytest.raises(FrameError):
            parse_raw(bad)


def test_monitor_exits_4_when_its_port_is_lost_and_not_back_at_the_end(log_dir, capsys):
    import socket

    server = socket.create_server(("127.0.0.1", 0))
    port = server.getsockname()[1]

    def serve_once():
        conn, _ = server.accept()
        time.sleep(0.3)
        conn.close()
        server.close()  # reconnections are refused from now on

    threading.Thread(target=serve_once, daemon=True).start()
    rc = main(["monitor", "--duration", "2", "--retry", "0.2", "--port",
               f"socket://127.0.0.1:{port}"])
    out = capsys.readouterr()
    assert rc == 4, out.err
    assert out.err.strip().splitlines()[-1] == (
        "error: port lost and not back when the monitor ended: ir")
