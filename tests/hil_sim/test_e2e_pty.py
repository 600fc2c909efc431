"""``hexbot sim --pty`` from the outside: a pyserial client on the pseudo-terminals."""

import json
import signal
import subprocess
import sys
import time

import pytest
import serial

from hexbot.protocol.frames import encode_pc, make, select

WAIT_S = 60.0  # wall-clock limit for a reply, only so that a broken build cannot hang
_leftover: dict[int, bytes] = {}  # bytes read past a pattern, per open port


def start(*args: str) -> tuple[subprocess.Popen, dict]:
    _leftover.clear()
    proc = subprocess.Popen(
        [sys.executable, "-m", "hexbot.cli", "sim", *args],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )
    line = proc.stdout.readline()
    if not line:
        proc.wait(5)
        pytest.fail(f"hexbot sim printed nothing: {proc.stderr.read()}")
    return proc, json.loads(line)


def stop(proc: subprocess.Popen, signum: int = signal.SIGTERM) -> str:
    proc.send_signal(signum)
    _, err = proc.communicate(timeout=20)
    assert proc.returncode == 0, err
    return err


def read_until(port: serial.Serial, pattern: bytes) -> bytes:
    """Bytes up to and including ``pattern``; what came after waits for the next call."""
    data = _leftover.pop(id(port), b"")
    deadline = time.monotonic() + WAIT_S
    while pattern not in data:
        if time.monotonic() > deadline:
            pytest.fail(f"{pattern!r} never came; got {data!r}")
        data += port.read(port.in_waiting or 1)
    cut = data.index(pattern) + len(pattern)
    _leftover[id(port)] = data[cut:]
    return data[:cut]


def test_boot_texts_and_an_ack_through_the_ptys():
    proc, ports = start("single", "--pty", "--speed", "0", "--wait-client")
    try:
        assert set(ports) == {"ir", "uart1", "isp"} and list(ports["uart1"]) == ["1"]
        with serial.Serial(ports["ir"], 300, timeout=0.2) as ir, \
                serial.Serial(ports["uart1"]["1"], 4800, timeout=0.2) as debug:
            boot = read_until(ir, b"COMM. LISTENING")
            assert b"COMM. BOARD READY" in boot and b"CTR. LISTENING" in boot
            read_until(ir, b"\n\r")
            ir.write(encode_pc(make("JxOpen", 3)))
            assert b"M: ACK\x01\n\r" in read_until(ir, b"ACK\x01\n\r")
            assert b"MSG\x01\x03NNN" in read_until(debug, b"MSG\x01\x03NNN")
    finally:
        if proc.poll() is None:
            stop(proc)


def test_rotation_over_the_ptys_writes_events_and_vcd(tmp_path):
    events_path, vcd_path = tmp_path / "events.jsonl", tmp_path / "pins.vcd"
    proc, ports = start("pair", "--pty", "--speed", "0", "--wait-client",
                        "--events", str(events_path), "--vcd", str(vcd_path))
    try:
        with serial.Serial(ports["ir"], 300, timeout=0.2) as ir:
            read_until(ir, b"COMM. LISTENING ID=02")  # the last boot slot (docs/firmware.md)
            for command, reply in ((select([1]), b"M01: ACKE"), (make("Ref"), b"S01: ACKA"),
                                   (select([1, 2]), b"M02: ACKE"),
                                   (make("CW", 4, 8, 4, 9, 4, 8, 4, 9), b"M02: ACKC")):
                ir.write(encode_pc(command))
                read_until(ir, reply)
    finally:
        err = stop(proc, signal.SIGINT)
    assert "Traceback" not in err
    events = [json.loads(line) for line in events_path.read_text().splitlines()]
    moved = [e for e in events if e["event"] == "moved"]
    assert len(moved) == 1
    assert {k: moved[0][k] for k in ("event", "module", "from", "to", "orientation")} == {
        "event": "moved", "module": 2, "from": [-1, 1], "to": [0, 1], "orientation": 2}
    assert moved[0]["t"] > 0
    vcd = vcd_path.read_text()
    header, _, body = vcd.partition("$enddefinitions $end")
    assert "$timescale 1 us $end" in header and "$scope module module_2 $end" in header
    times = [int(line[1:]) for line in body.splitlines() if line.startswith("#")]
    assert times == sorted(times) and len(times) > 10
    # the mobile's magnet S4 negative line (PB4) went high and low again during the CW
    scope = header.split("$scope module module_2 $end")[1].split("$upscope")[0]
    code = next(line.split()[3] for line in scope.splitlines() if line.endswith(" s4n $end"))
    changes = [line for line in body.splitlines() if line[1:] == code and line[0] in "01"]
    assert changes[-2:] == [f"1{code}", f"0{code}"]


class _Chatty:
    """Unit-test double of the simulator's output side: 100 bytes for the
    PC at every pump, no debug ports."""

    modules: dict = {}

    def pc_read(self) -> bytes:
        return b"A" * 100


def test_bytes_a_slow_client_misses_are_said_not_only_counted(capsys):
    from hexbot.hil_sim.pty_bridge import PtyBridge

    bridge = PtyBridge(_Chatty())  # type: ignore[arg-type]
    try:
        for _ in range(3000):  # 300 kB, nobody reading: the pty fills
            bridge.pump_out()
        assert bridge.ir.dropped > 0
        warnings = capsys.readouterr().err.splitlines()
        # one note for the whole burst (at most one per DROP_NOTE_S), with the count
        assert len(warnings) == 1 and "bytes dropped so far" in warnings[0], warnings
    finally:
        bridge.close()
