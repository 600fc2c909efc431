"""A MAVLink client we did not write: pymavlink's ``mavutil`` on the pty of
``hexbot sim --pty``, with a dialect module that pymavlink's own mavgen.py
makes from protocol/hexbot.xml. It commands a module and reads its ACK;
the CLI does the same with ``--framing``, and its session's .tlog reads
back with pymavlink."""

from __future__ import annotations

import importlib.util
import json
import os
import subprocess
import sys
import time
from pathlib import Path

from pymavlink import mavutil

from hexbot.host.simproc import SimProcess
from hexbot.host.tlog import TlogWriter
from hexbot.protocol import wire
from hexbot.protocol.codes import lookup
from hexbot.protocol.mavlink_xml import XML_PATH

BIN = Path(sys.executable).parent


def dialect_from_xml(tmp_path: Path):
    out = tmp_path / "hexbot_dialect.py"
    subprocess.run([str(BIN / "mavgen.py"), "--lang", "Python3", "--wire-protocol", "2.0",
                    "-o", str(out), str(XML_PATH)], check=True, capture_output=True)
    spec = importlib.util.spec_from_file_location("hexbot_dialect", out)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def use_dialect(conn, dialect) -> None:
    """Our dialect on a mavutil connection; the link is MAVLink 2 from the
    start (else mavutil swaps in its built-in dialect at the first 0xFD)."""
    conn.mav = dialect.MAVLink(conn, srcSystem=255, srcComponent=190)
    conn.WIRE_PROTOCOL_VERSION = "2.0"


def wait_for_boot(conn, timeout: float) -> None:
    """The legacy boot texts, read as raw bytes from the connection's port."""
    seen, end = b"", time.monotonic() + timeout
    while wire.TEXT_COMM_LISTENING.encode() not in seen or not seen.endswith(wire.EOL):
        assert time.monotonic() < end, f"no boot text, heard {seen!r}"
        seen += conn.port.read(64)


def test_mavutil_commands_a_simulated_module_and_reads_its_ack(tmp_path):
    dialect = dialect_from_xml(tmp_path)
    with SimProcess("single", speed=10.0) as sim:
        conn = mavutil.mavlink_connection(sim.ports.ir, baud=300)
        try:
            use_dialect(conn, dialect)
            wait_for_boot(conn, 60)
            lon = lookup("LOn").code
            conn.mav.hexbot_command_send(1, lon, [0] * 8)
            ack = conn.recv_match(type="HEXBOT_ACK", blocking=True, timeout=20)
            assert ack is not None, "no HEXBOT_ACK"
            assert (ack.code, ack.result, ack.get_srcSystem()) == (
                lon, dialect.HEXBOT_RESULT_DONE, 1)
            conn.mav.hexbot_command_send(1, lookup("Status").code, [0] * 8)
            status = conn.recv_match(type="HEXBOT_STATUS", blocking=True, timeout=20)
            assert status is not None and status.get_seq() == (ack.get_seq() + 1) % 256
        finally:
            conn.close()


def test_send_with_mavlink_framing_leaves_a_tlog_pymavlink_reads(log_dir, tmp_path):
    env = {**os.environ, "HEXBOT_LOG_DIR": str(log_dir)}
    proc = subprocess.run([sys.executable, "-m", "hexbot.cli", "send", "JxOpen", "3",
                           "--module", "1", "--scenario", "single", "--framing", "auto",
                           "--json"], capture_output=True, text=True, timeout=300, env=env)
    assert proc.returncode == 0, proc.stderr
    rows = [json.loads(line) for line in proc.stdout.splitlines()]
    assert [(r["kind"], r["code"], r["mav"]["name"]) for r in rows] == [
        ("mavack", 69, "HEXBOT_ACK"), ("mavack", 1, "HEXBOT_ACK")]
    (folder,) = list(log_dir.iterdir())
    log = mavutil.mavlink_connection(str(folder / "session.tlog"))
    use_dialect(log, dialect_from_xml(tmp_path))
    names = []
    while (msg := log.recv_match()) is not None:
        names.append(msg.get_type())
    # the probe (Status), Select(1), JxOpen(3): commands and answers in order
    assert names == ["HEXBOT_COMMAND", "HEXBOT_STATUS", "HEXBOT_COMMAND", "HEXBOT_ACK",
                     "HEXBOT_COMMAND", "HEXBOT_ACK"]


def test_tlog_records_are_stamped_frames(tmp_path):
    path = tmp_path / "x.tlog"
    writer = TlogWriter(path, started=1_700_000_000.0)
    writer.sent(1.5, b"*ANNNNNNNN#")  # a legacy frame is not MAVLink: not logged
    writer.received(2.25, b"\xfd\x00")
    writer.close()
    assert path.read_bytes() == (1_700_000_002_250_000).to_bytes(8, "big") + b"\xfd\x00"
