"""HexBot scripts: checked whole before sending, run step by step, stop at
the first failed expectation with file and line."""

from __future__ import annotations

from pathlib import Path

import pytest

from hexbot.cli import main
from hexbot.errors import ScenarioError
from hexbot.host.script import parse_script

EXAMPLES = Path(__file__).parents[2] / "docs" / "examples"

GOOD = """\
# localize the flower and check two modules
timeout 3
select 1
Ref
select 0
localize
expect text LOCALIZED count 7
expect placements 7
status
expect status 1 localized at 0 0 yref 0 role S
expect status 3 localized at 0 1
"""


def _write(tmp_path, text):
    path = tmp_path / "t.hbs"
    path.write_text(text)
    return path


def test_good_script_passes(responder, log_dir, tmp_path, capsys):
    rc = main(["run", str(_write(tmp_path, GOOD)), "--port", responder.path])
    captured = capsys.readouterr()
    assert rc == 0, captured.err
    assert "all 10 steps passed" in captured.err
    assert " 10 ok    expect status 1 localized" in captured.out


def test_script_stops_at_first_failed_expectation(responder, log_dir, tmp_path, capsys):
    text = "select 2\nexpect ack 65 within 0.3\nJxOpenAll\n"
    rc = main(["run", str(_write(tmp_path, text)), "--port", responder.path])
    err = capsys.readouterr().err
    assert rc == 1
    assert "t.hbs:2: expect ack 65 within 0.3: no ACK 65 within 0.3 s" in err
    assert "1 of 3 steps passed" in err
    assert len(responder.received) == 1  # JxOpenAll was never sent


def test_status_mismatch_names_the_difference(responder, log_dir, tmp_path, capsys):
    text = "select 3\nstatus\nexpect status 3 localized\n"
    assert main(["run", str(_write(tmp_path, text)), "--port", responder.path]) == 1
    assert "module is not localized" in capsys.readouterr().err


def test_syntax_error_sends_nothing(responder, log_dir, tmp_path, capsys):
    text = "select 1\nRef\nrotate cw 9 mobile 2 substrate 1\n"
    rc = main(["run", str(_write(tmp_path, text)), "--port", responder.path])
    assert rc == 1
    assert "t.hbs:3: joint must be 1..6, got 9" in capsys.readouterr().err
    assert responder.received == []


@pytest.mark.parametrize("line, problem", [
    ("JxOpen 7", "must be 1..6, got 7"),
    ("Frobnicate 1", "unknown function 'Frobnicate'"),
    ("expect ack 65 from", "'from' needs a value"),
    ("expect status", "needs a module id"),
    ("expect colour red", "unknown expectation 'colour'"),
    ("wait soon", "seconds must be a number"),
    ("select", "needs at least one module id"),
    ("select 0 3", "cannot be combined"),
])
def test_parse_errors_name_line_and_problem(line, problem):
    with pytest.raises(ScenarioError) as info:
        parse_script(f"echo hi\n{line}\n", "x.hbs")
    assert str(info.value).startswith("x.hbs:2: ")
    assert problem in str(info.value)


def test_rotation_uses_orientations_from_status(responder, log_dir, tmp_path, capsys):
    text = ("select 0\nlocalize\nstatus\n"
            "rotate cw 5 mobile 3 substrate 1 verify status\nexpect ack CW from 1 3\n")
    rc = main(["run", str(_write(tmp_path, text)), "--port", responder.path])
    assert rc == 0, capsys.readouterr().err
    # responder: module 3 (at (0,1)) has Yref 2, module 1 (at (0,0), its side 5) Yref 0
    sent = [f for f in responder.received if f[1] in (67, 71)]
    # roles first, where the last status showed another: module 3 is M already
    assert [(f[1], f[2]) for f in sent[:-1]] == [(71, 2)]
    rotation = sent[-1]
    assert rotation[1] == 67
    assert rotation[2] == 5  # substrate si: ((5-1-0) mod 6)+1
    assert rotation[6] == 3  # mobile mi: ((5-1-2) mod 6)+1
    assert list(rotation[3:6]) == [8, 4, 10] and list(rotation[7:10]) == [8, 5, 9]


def test_rotation_is_refused_before_localizing(responder, log_dir, tmp_path, capsys):
    text = "rotate cw 5 mobile 3 substrate 1\n"
    assert main(["run", str(_write(tmp_path, text)), "--port", responder.path]) == 1
    assert "orientation of module 3 unknown: localize first" in capsys.readouterr().err
    assert responder.received == []


def test_rotation_with_a_substrate_elsewhere_is_refused(responder, log_dir, tmp_path, capsys):
    text = "select 0\nlocalize\nstatus\nrotate cw 2 mobile 3 substrate 1\n"
    assert main(["run", str(_write(tmp_path, text)), "--port", responder.path]) == 1
    assert "needs its substrate at (0, 2), module 1 is at (0, 0)" in capsys.readouterr().err


def test_localize_verification_catches_a_move_that_did_not_happen(responder, log_dir,
                                                                   tmp_path, capsys):
    # The responder acknowledges rotations but nobody moves: localizing
    # again finds module 3 where it was.
    text = "select 0\nlocalize\nstatus\nrotate cw 5 mobile 3 substrate 1 verify localize\n"
    assert main(["run", str(_write(tmp_path, text)), "--port", responder.path]) == 1
    err = capsys.readouterr().err
    assert "module 3 should be at (1, 0) facing 4 after CW about joint 5" in err
    assert "localize check finds it at (0, 1) facing 2" in err


@pytest.mark.parametrize("path", sorted(EXAMPLES.glob("*.hbs")), ids=lambda p: p.name)
def test_shipped_examples_parse(path, capsys):
    assert main(["run", str(path), "--check"]) == 0


def test_a_lost_port_ends_the_script_at_once_with_exit_4(responder, log_dir, tmp_path, capsys):
    import threading

    text = "select 2\nexpect ack 65 within 60\n"  # nobody will send ACK 65
    threading.Timer(0.5, responder.close).start()  # the cable is pulled
    rc = main(["run", str(_write(tmp_path, text)), "--port", responder.path])
    err = capsys.readouterr().err
    assert rc == 4, err  # not 1 (a failed step) and not after the 60 s wait
    assert "t.hbs: port lost" in err


def test_the_checker_reports_every_bad_line(tmp_path, capsys):
    """Issue 13, item 11: one error per run meant one edit-run cycle per typo."""
    text = "select 1\nJxOpen 7\nRef\nFrobnicate\nwait soon\n"
    assert main(["run", str(_write(tmp_path, text)), "--check"]) == 1
    err = capsys.readouterr().err
    assert "t.hbs:2: " in err and "must be 1..6, got 7" in err
    assert "t.hbs:4: unknown function 'Frobnicate'" in err
    assert "t.hbs:5: seconds must be a number" in err


def test_run_help_states_the_simulator_speed_it_uses(tmp_path, log_dir, capsys):
    """Issue 13, item 11: the help said one default speed, run used another."""
    import subprocess
    import sys

    helptext = subprocess.run([sys.executable, "-m", "hexbot.cli", "run", "--help"],
                              capture_output=True, text=True).stdout
    assert "0 for send/run/plan" in " ".join(helptext.split())
    assert main(["run", str(_write(tmp_path, "select 2\n")), "--scenario", "pair"]) == 0
    assert "ir: connected hexbot-sim://pair?speed=0 " in capsys.readouterr().err
