"""``hexbot send`` and ``hexbot monitor`` at their edges (session 35's
audit): what --dry-run prints for --unchecked frames, a function and --raw
together, and how a reply naming an unknown code or reason reads."""

from __future__ import annotations

import json
import threading

from hexbot.cli import main
from hexbot.protocol import wire


def test_dry_run_prints_an_unchecked_frame_instead_of_refusing_it(capsys):
    # the frame --unchecked would send (an argument out of range for the
    # firmware's own check): printed, nothing opened
    assert main(["send", "JxOpen", "9", "--unchecked", "--dry-run", "--no-log"]) == 0
    out = capsys.readouterr().out
    # named, with the check it skips (it printed only "raw 2a 01 09 ...")
    assert out.splitlines() == ["JxOpen(9) (unchecked: JxOpen: i (joint number) must be 1..6, "
                                "got 9): 2a 01 09 4e 4e 4e 4e 4e 4e 4e 23"]


def test_a_function_and_raw_bytes_together_are_a_usage_error(capsys, log_dir):
    code = main(["send", "Status", "--raw", "2a464e4e4e4e4e4e4e4e23", "--port", "loop://"])
    err = capsys.readouterr().err
    assert code == 2, err
    assert err.rstrip().endswith("give a function (CODE [ARG...]) or --raw HEX, not both")
    assert not log_dir.exists()  # refused before any port opened


def test_the_monitor_names_an_unknown_code_and_reason_by_their_numbers(
        responder, log_dir, capsys):
    # the reply again and again until the monitor ends: one written before
    # the monitor opened its port (a loaded machine) is flushed by the open
    done = threading.Event()

    def reply():
        while not done.wait(0.2):
            responder.write(wire.PREAMBLE + b"M05: ERR" + bytes([99, 42]) + wire.EOL)

    threading.Thread(target=reply, daemon=True).start()
    try:
        assert main(["monitor", "--duration", "1.0", "--port", responder.path]) == 0
    finally:
        done.set()
    lines = capsys.readouterr().out.splitlines()
    assert lines and {line.split(None, 2)[2] for line in lines} == {"M05 ERR 99 ?: reason 42"}, \
        lines


def test_an_unknown_function_name_is_refused_also_unchecked(capsys):
    # --unchecked lets any code number through, never a name the table lacks
    assert main(["send", "JxOpenn", "3", "--unchecked", "--dry-run", "--no-log"]) == 1
    err = capsys.readouterr().err
    assert err.rstrip().endswith("unknown function 'JxOpenn' (see `hexbot codes`)"), err


def test_arguments_may_be_written_in_hex(capsys):
    assert main(["send", "Select", "0x2", "0X0a", "--dry-run", "--no-log"]) == 0
    assert capsys.readouterr().out.splitlines() == [
        "Select(2, 10): 2a 45 02 0a 4e 4e 4e 4e 4e 4e 23"]


def test_json_error_replies_name_their_function_and_reason(responder, log_dir, capsys):
    assert main(["send", "JxOpen", "9", "--unchecked", "--json", "--module", "3",
                 "--port", responder.path]) == 1
    rows = [json.loads(line) for line in capsys.readouterr().out.splitlines()]
    (err,) = [r for r in rows if r["kind"] == "errorreply"]
    assert (err["module"], err["function"], err["reason"], err["reason_name"]) == (
        3, "JxOpen", 1, "ARG_RANGE")
