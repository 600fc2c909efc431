"""Bad input to the host and simulator commands: one line on stderr, the
exit status of docs/console.md's table (2 usage, 4 port, 1 other), and
nothing opened or sent first."""

from __future__ import annotations

import io
import sys
from pathlib import Path

import pytest

from hexbot.cli import main
from hexbot.host import cli_common
from hexbot.host.events import PortChanged
from hexbot.host.link import LinkState
from hexbot.protocol import wire

CAPTURE = Path(__file__).parent / "data" / "flower7_session.hbcap"
SMOKE = Path(__file__).parents[2] / "docs" / "examples" / "actuators_smoke.hbs"


def status(capsys, *argv: str) -> tuple[int, str]:
    """Exit status and stderr, argparse's usage errors (SystemExit) included."""
    try:
        code = main([str(a) for a in argv])
    except SystemExit as exc:
        code = exc.code
    return code, capsys.readouterr().err


def reason(err: str) -> str:
    """The one error line (argparse prints its usage above it)."""
    (line,) = [x for x in err.splitlines() if ": error: " in x]
    return line


@pytest.fixture
def binary(tmp_path):
    path = tmp_path / "g.bin"
    path.write_bytes(bytes([0xA9, 0xFF, 0x00, 0xC3]) * 75)
    return path


def test_a_binary_script_or_scenario_is_not_text(capsys, tmp_path, binary, log_dir):
    script = tmp_path / "script.hbs"
    script.write_text(f"plan {binary}\n")
    for argv in (["run", script, "--check"], ["run", script, "--scenario", "pair"],
                 ["run", binary, "--check"], ["sim", binary, "--duration", "1"]):
        code, err = status(capsys, *argv)
        assert code == 1, argv
        assert f"{binary}: not a text file (UTF-8)" in reason(err), argv
        assert "Traceback" not in err
    assert not log_dir.exists()  # nothing booted


def test_junit_report_in_a_missing_folder_is_refused_before_running(capsys, log_dir, tmp_path):
    code, err = status(capsys, "run", SMOKE, "--scenario", "pair", "--junit",
                       tmp_path / "nope" / "r.xml")
    assert code == 2 and "folder" in reason(err) and "does not exist" in reason(err)
    afile = tmp_path / "afile"
    afile.write_text("")
    code, err = status(capsys, "run", SMOKE, "--junit", afile / "r.xml")
    assert code == 2 and "is not a folder" in reason(err)
    assert not log_dir.exists()  # no step ran


def test_log_dir_that_cannot_be_created_is_a_usage_error(capsys, tmp_path, responder):
    afile = tmp_path / "afile"
    afile.write_text("")
    for where in (afile, afile / "below"):
        code, err = status(capsys, "send", "Status", "--port", responder.path, "--log-dir", where)
        assert code == 2 and f"--log-dir {where}: cannot create a session folder" in reason(err)
    assert responder.received == []  # refused before anything was sent


def test_an_unusable_default_log_dir_warns_and_runs_without_a_log(capsys, tmp_path, monkeypatch,
                                                                   responder):
    afile = tmp_path / "afile"
    afile.write_text("")
    monkeypatch.setenv("HEXBOT_LOG_DIR", str(afile / "sessions"))
    code, err = status(capsys, "send", "Status", "--port", responder.path)
    assert code == 0, err
    assert "warning: session log folder" in err and "running without a session log" in err
    assert "session log: " not in err


@pytest.mark.parametrize("argv, words", [
    (["sim", "pair", "--rfc2217", "99999"], "0..65535"),
    (["sim", "pair", "--rfc2217", "-5"], "0..65535"),
    (["sim", "pair", "--duration", "-5"], "--duration"),
    (["sim", "pair", "--duration", "0"], "--duration"),
    (["sim", "pair", "--speed", "-1"], "--speed"),
    (["sim", "pair", "--threads", "0"], "--threads: threads must be 1..256"),
    (["sim", "pair", "--threads", "300"], "--threads: threads must be 1..256"),
    (["monitor", "--duration", "-1"], "--duration"),
    (["send", "JxOpen", "1", "--scenario", "pair", "--expect", "-5"], "--expect"),
    (["send", "Status", "--port", "loop://", "--baud", "0"], "--baud"),
    # (fuzz, session 37) rates no module's UART makes: 99999999999 hung the run
    (["send", "Status", "--port", "loop://", "--baud", "125001"],
     "--baud: a module's UART runs at 15..125000 baud (ATmega162 at 1 MHz), got 125001"),
    (["run", "x.hbs", "--baud", "99999999999"], "--baud: a module's UART runs at 15..125000"),
    (["monitor", "--port", "loop://", "--debug-port", "loop://", "--debug-baud", "14",
      "--duration", "1"], "--debug-baud: a module's UART runs at 15..125000 baud"),
    (["send", "Status", "--scenario", "pair", "--module=-1"],
     f"argument --module: a module id is 1..{wire.MAX_MODULE_ID} (0 = every module)"),
    (["replay", CAPTURE, "--port", "nosuch"], "'ir', 'debug'"),
    (["bench", "sim", "--seconds", "-1"], "--seconds"),
    # --duration: should the check regress, the monitor ends instead of hanging the suite
    (["monitor", "--port", "loop://", "--debug-module", "2", "--duration", "1"], "--debug-port"),
    # ``--port "$PORT"`` with the variable unset: not the embedded simulator
    (["send", "Status", "--port", ""], "--port: empty port name"),
    # (fuzz, session 37) ignored: the default scenario, or the script's, ran instead
    (["send", "Status", "--scenario", ""], "--scenario: empty scenario name"),
    (["run", "x.hbs", "--scenario", " "], "--scenario: empty scenario name"),
    # (fuzz, session 37) ignored: the simulation started at once, for nobody
    (["sim", "pair", "--duration", "1", "--wait-client"],
     "--wait-client waits for a client of the --pty ports: give --pty"),
    (["monitor", "--port", "loop://", "--debug-port", " "], "--debug-port: empty port name"),
    (["flash", "--board", "control", "--port", ""], "--port: empty port name"),
    # (fuzz, session 37) any finite time was taken: 1e300 hung a session at speed 0;
    # the cap is a script's (script.MAX_SECONDS)
    (["send", "Status", "--port", "/nonexistent/ttyNOPE", "--timeout", "1e300"],
     "--timeout: must be at most 3600 seconds, got 1e300"),
    (["send", "Status", "--port", "/nonexistent/ttyNOPE", "--linger", "3600.5"],
     "--linger: must be at most 3600 seconds, got 3600.5"),
])
def test_bad_option_values_are_usage_errors(capsys, log_dir, argv, words):
    code, err = status(capsys, *argv)
    assert code == 2, err
    assert words in reason(err)
    assert not log_dir.exists()  # refused before any port opened


def test_send_without_a_function_says_what_to_give(capsys, log_dir):
    code, err = status(capsys, "send", "--scenario", "pair")
    assert code == 2
    assert reason(err).endswith("give a function (CODE [ARG...]) or --raw HEX")


def test_bench_without_a_name_asks_for_the_name_only(capsys):
    code, err = status(capsys, "bench")
    assert code == 2 and reason(err).endswith("the following arguments are required: NAME")


def test_an_empty_script_is_refused_before_booting(capsys, tmp_path, log_dir):
    script = tmp_path / "empty.hbs"
    script.write_text("# scenario: pair\n\n# nothing to do\n")
    for extra in ([], ["--check"]):
        code, err = status(capsys, "run", script, "--scenario", "pair", *extra)
        assert code == 1 and reason(err).endswith(f"{script}: no steps (only comments and "
                                                  "blank lines)")
    assert not log_dir.exists()


def test_monitor_on_a_missing_port_exits_4(capsys, log_dir):
    code, err = status(capsys, "monitor", "--port", "/nonexistent/ttyNOPE", "--duration", "3")
    assert code == 4 and "cannot open /nonexistent/ttyNOPE" in reason(err)
    code, err = status(capsys, "monitor", "--port", "loop://", "--debug-port",
                       "/nonexistent/ttyNOPE", "--duration", "3")
    assert code == 4 and "cannot open /nonexistent/ttyNOPE" in reason(err)


def test_monitor_debug_module_must_be_in_the_scenario(capsys, log_dir):
    code, err = status(capsys, "monitor", "--scenario", "pair", "--debug-module", "64",
                       "--duration", "1", "--no-log")
    assert code == 2 and reason(err).endswith("--debug-module 64: scenario pair has modules 1, 2")


@pytest.mark.parametrize("argv, words", [
    (["--scenario", "pair", "--debug-module", "9"],
     "--debug-module 9: scenario pair has modules 1, 2"),
    (["--port", "loop://", "--scenario", "pair"], "cannot be combined with --port"),
    (["--scenario", "pair", "--timeout", "1e300"],
     "--timeout: must be at most 3600 seconds, got 1e300"),
])
def test_console_usage_errors_exit_2_before_the_ui_starts(capsys, log_dir, monkeypatch,
                                                          argv, words):
    """docs/console.md: a usage error exits 2 before any port opens; the
    console showed it in the TUI and exited 2 only when the user quit."""
    from hexbot.host.console.app import HexBotConsole

    def started(self, *args, **kwargs):
        pytest.fail("the console's UI started")
    monkeypatch.setattr(HexBotConsole, "run", started)
    code, err = status(capsys, "console", *argv)
    assert code == 2, err
    assert reason(err).startswith("hexbot console: error: ") and words in reason(err)
    assert not log_dir.exists()


def test_console_log_dir_that_cannot_hold_a_session_exits_2_before_the_ui(
        capsys, tmp_path, monkeypatch):
    """docs/console.md: an explicit --log-dir where no session folder can be
    made is a usage error before any port opens (send and monitor said so;
    the console opened, showed it on the status line and exited 2 at q)."""
    from hexbot.host.console.app import HexBotConsole

    def started(self, *args, **kwargs):
        pytest.fail("the console's UI started")
    monkeypatch.setattr(HexBotConsole, "run", started)
    not_a_folder = tmp_path / "file"
    not_a_folder.write_text("x")
    code, err = status(capsys, "console", "--scenario", "pair", "--log-dir", not_a_folder)
    assert code == 2, err
    assert reason(err).startswith("hexbot console: error: --log-dir ")
    assert reason(err).endswith("cannot create a session folder: File exists")
    made = tmp_path / "new" / "logs"  # a folder still to be made is fine: it is made
    monkeypatch.setattr(HexBotConsole, "run", lambda self, *a, **k: None)
    code, err = status(capsys, "console", "--scenario", "pair", "--log-dir", made)
    assert code == 0, err


class _Writes(io.StringIO):
    """A stderr double that keeps every write() call apart."""

    def __init__(self) -> None:
        super().__init__()
        self.calls: list[str] = []

    def write(self, text: str) -> int:
        self.calls.append(text)
        return super().write(text)


def test_a_port_state_line_is_written_whole(monkeypatch):
    """The link's reader thread prints port states while the main thread
    prints the session log line: each line must be one write, newline
    included, or the two run together on a terminal."""
    fake = _Writes()
    monkeypatch.setattr(sys, "stderr", fake)
    cli_common._state_printer()(PortChanged("ir", LinkState.CONNECTED, "loop:// 300 8N1", 0.0))
    cli_common.err_line("session log: /tmp/x")
    assert fake.calls == ["ir: connected loop:// 300 8N1\n", "session log: /tmp/x\n"]


def test_a_port_lost_is_said_only_after_it_was_up(monkeypatch):
    """A port that never opened is the command's error line; saying "lost"
    first repeated it. A port that was up and went away is news."""
    fake = _Writes()
    monkeypatch.setattr(sys, "stderr", fake)
    show = cli_common._state_printer()
    show(PortChanged("ir", LinkState.LOST, "cannot open /dev/ttyUSB9: No such file", 0.0))
    assert fake.calls == []
    show(PortChanged("ir", LinkState.CONNECTED, "/dev/ttyUSB9 300 8N1", 1.0))
    show(PortChanged("ir", LinkState.LOST, "read failed: device reports readiness", 2.0))
    show(PortChanged("debug", LinkState.LOST, "cannot open /dev/ttyUSB8: No such file", 2.0))
    assert fake.calls == ["ir: connected /dev/ttyUSB9 300 8N1\n",
                          "ir: lost read failed: device reports readiness\n"]


@pytest.mark.parametrize("port, why", [
    ("/nonexistent/ttyNOPE", "cannot open /nonexistent/ttyNOPE: No such file or directory"),
    ("/dev/null", "cannot open /dev/null: not a serial port (Inappropriate ioctl for device)"),
])
def test_a_port_that_does_not_open_is_one_short_line(capsys, log_dir, port, why):
    """pyserial's text repeated the port and the errno ("could not open port
    X: [Errno 2] No such file or directory: 'X'"), and a "lost" line said it
    once more before the error."""
    code, err = status(capsys, "send", "Status", "--module", "2", "--port", port)
    assert code == 4
    assert err.strip().splitlines() == [f"hexbot send: error: {why}"]
