"""``hexbot send`` against a simulator running in another process, through its
ptys: state built by one send is there for the next (issue 13, defects 3-5)."""

from __future__ import annotations

import json
import subprocess
import sys

import pytest

from hexbot.host.simproc import SimProcess


def hexbot(*argv: str, timeout: float = 120) -> subprocess.CompletedProcess:
    log = [] if argv[:1] == ("ports",) else ["--no-log"]
    return subprocess.run([sys.executable, "-m", "hexbot.cli", *argv, *log],
                          capture_output=True, text=True, timeout=timeout)


@pytest.fixture
def pair():
    with SimProcess("pair", speed=0) as sim:  # as fast as it goes; the host's clock is the wall
        yield sim


def test_collided_status_replies_are_a_decoding_failure(pair):
    """Before any Select both modules answer at once; their STA replies
    collide on the IR link (the bytes AND) into ``STA`` with id 0."""
    proc = hexbot("send", "70", "--port", pair.ports.ir)
    assert proc.returncode == 1, proc.stdout + proc.stderr
    assert ("Status (70): garbled reply: STA from id 0, which no module here has "
            "(replies collided?)") in proc.stderr
    assert "STA id 0 (no id: replies that collided" in proc.stdout  # shown as heard


def test_ref_then_localize_in_two_sends_on_a_running_simulator(pair):
    """The docs' example: Ref in one process, Localize in the next; the
    localization window is far longer than the old fixed 5 s time-out."""
    ref = hexbot("send", "Ref", "--module", "1", "--port", pair.ports.ir)
    assert ref.returncode == 0, ref.stderr
    loc = hexbot("send", "Localize", "--module", "0", "--port", pair.ports.ir,
                 "--linger", "2", "--json")
    assert loc.returncode == 0, loc.stderr
    rows = [json.loads(line) for line in loc.stdout.splitlines()]
    times = [r["t"] for r in rows]
    assert times == sorted(times)  # defect 5: in the order they arrived
    kinds = [(r["kind"], r.get("module"), r.get("code")) for r in rows]
    # module 2's report comes just before its ACK 66, which names it
    at = kinds.index(("ack", 2, 66))
    assert kinds[at - 1][0] == "positionreport"
    assert [r for r in rows if r["kind"] == "positionreport"][0]["x"] == -1
    status = hexbot("send", "Status", "--module", "2", "--port", pair.ports.ir)
    assert status.returncode == 0, status.stderr
    assert "STA id 2 role M at (-01,+01)" in status.stdout


def test_dry_run_prints_frames_and_opens_nothing():
    proc = hexbot("send", "Ref", "--module", "1", "--dry-run", "--port", "/nonexistent/tty")
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout.splitlines() == ["Select(1): 2a 45 01 4e 4e 4e 4e 4e 4e 4e 23",
                                        "Ref(): 2a 41 4e 4e 4e 4e 4e 4e 4e 4e 23"]


@pytest.mark.parametrize("raw", ["2a 46 4e 4e 4e 4e 4e 4e 4e 4e 23", '"*FNNNNNNNN#"'])
def test_raw_bytes_are_sent_as_they_are(pair, raw):
    proc = hexbot("send", "--module", "2", "--raw", raw, "--port", pair.ports.ir)
    assert proc.returncode == 0, proc.stderr
    assert "STA id 2" in proc.stdout


@pytest.mark.parametrize("argv, why", [
    (["Status", "--timeout", "-1"], "--timeout: must be more than 0 seconds"),
    (["Status", "--module", "64"], "must be 0..63, got 64"),
    (["--raw", "2x"], "not hex bytes"),
])
def test_bad_options_fail_before_any_port_opens(argv, why):
    proc = hexbot("send", *argv, "--port", "/nonexistent/tty")
    assert proc.returncode in (1, 2)  # never 4: the port was never tried
    assert why in proc.stderr


def test_a_wrong_baud_rate_is_caught_on_the_simulator():
    """Issue 13, defect 7: 9600 baud was accepted and replies still arrived."""
    proc = hexbot("send", "Status", "--module", "2", "--scenario", "pair", "--baud", "9600")
    assert proc.returncode == 3, proc.stderr
    assert "0 of 2 modules booted" in proc.stderr
    assert "only garbled bytes heard: the modules speak 300 8N1" in proc.stderr


def test_ports_lists_serial_ports_simulator_urls_and_running_sim_ptys():
    with SimProcess("single", speed=0) as sim:
        proc = hexbot("ports", "--json")
        assert proc.returncode == 0, proc.stderr
        listed = json.loads(proc.stdout)
    assert "hexbot-sim://pair?speed=0" in listed["simulator_urls"]
    (mine,) = [s for s in listed["running"] if s["pid"] == sim._proc.pid]
    assert mine["ptys"][0] == sim.ports.ir and sim.ports.uart1[1] in mine["ptys"]


def test_monitor_on_the_embedded_simulator_starts_with_the_boot_texts():
    """Issue 13, item 11: monitor started with a GARBAGE line (boot bytes
    lost before the port was read); the URL's cluster starts with its port."""
    proc = hexbot("monitor", "--scenario", "pair", "--sim-speed", "0", "--duration", "3",
                  "--json")
    assert proc.returncode == 0, proc.stderr
    rows = [json.loads(line) for line in proc.stdout.splitlines()]
    ir = [r for r in rows if r["port"] == "ir"]
    assert ir[0]["kind"] == "text" and ir[0]["phrase"] == "COMM. BOARD READY"
    assert not any(r["kind"] == "garbage" for r in rows[:3])


def test_ports_does_not_take_the_terminal_of_a_sim_run_in_it_for_its_ir_port():
    """``hexbot sim pair --pty &`` in a terminal holds that terminal's pty as
    its stdin, stdout and stderr; ``ports`` listed it first, as the IR port."""
    import os
    import select

    master, terminal = os.openpty()
    proc = subprocess.Popen([sys.executable, "-m", "hexbot.cli", "sim", "single", "--pty",
                             "--speed", "0"], stdin=terminal, stdout=terminal, stderr=terminal)
    os.close(terminal)
    try:
        text = b""
        while b'"ir"' not in text or not text.rstrip().endswith(b"}"):
            ready, _, _ = select.select([master], [], [], 60)
            assert ready, text
            text += os.read(master, 4096)
        line = next(line for line in text.decode().splitlines() if '"ir"' in line)
        ir = json.loads(line[line.index("{"):])["ir"]
        listed = json.loads(hexbot("ports", "--json").stdout)
        (mine,) = [s for s in listed["running"] if s["pid"] == proc.pid]
        assert mine["ptys"][0] == ir, (mine, ir)
    finally:
        proc.terminate()
        proc.wait(30)
        os.close(master)


def test_ports_lists_a_sim_started_through_a_wrapper_once():
    """``timeout 600 hexbot sim pair --pty``: the wrapper's command line names
    the sim too; ``ports`` listed it as a second running sim, with no ptys."""
    proc = subprocess.Popen(["timeout", "120", sys.executable, "-m", "hexbot.cli", "sim",
                             "single", "--pty", "--speed", "0"],
                            stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
    try:
        ir = json.loads(proc.stdout.readline())["ir"]
        listed = json.loads(hexbot("ports", "--json").stdout)["running"]
        assert not [s for s in listed if s["pid"] == proc.pid], listed
        (mine,) = [s for s in listed if s["ptys"][:1] == [ir]]
        assert mine["command"].split()[0] != "timeout"
    finally:
        proc.terminate()
        proc.wait(30)
