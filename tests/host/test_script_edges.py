"""HexBot scripts at their edges (a mutation audit): lines `--check` must
refuse with file:line, expectations that must fail when what they wait for
does not come, and the times a script waits. On the pty double (replies at
once; a test writes what the double does not say by itself) and on the
embedded simulator (virtual time) where the time a reply takes matters."""

from __future__ import annotations

import threading

import pytest

from hexbot.protocol import parser, wire


def _write(tmp_path, text, name="e.hbs"):
    path = tmp_path / name
    path.write_text(text)
    return path


def _after_frames(responder, count, data, delay_s=0.0):
    """Write ``data`` as the double, ``delay_s`` after it has received
    ``count`` frames (what the double does not say by itself, after the
    script's command)."""
    def later():
        for _ in range(500):
            if len(responder.received) >= count:
                threading.Event().wait(delay_s)
                responder.write(data)
                return
            threading.Event().wait(0.01)
    thread = threading.Thread(target=later, daemon=True)
    thread.start()
    return thread


# --- the check: malformed lines are refused with file:line, nothing is sent --


@pytest.mark.parametrize("line, problem", [
    # a negative time-out or wait would time every reply out at once / wait nothing
    ("timeout -1", "seconds must be more than 0, got '-1'"),
    ("wait -0.5", "seconds must be more than 0, got '-0.5'"),
    # 'wait 1 2' is a typo, not a wait of 1 s with a stray word
    ("wait 1 2", "wait takes one number of seconds"),
    # 'status 3' reads as "the status of 3" but would query every selected module
    ("status 3", "status takes no arguments"),
    # lattice joints are 1..6: 7 must not reach the rotation
    ("rotate cw 7 mobile 2 substrate 1", "joint must be 1..6, got 7"),
    # 'at' with one coordinate: a file:line error, not a crash
    ("expect status 1 at 0", "in expect status, unexpected 'at'"),
])
def test_the_check_refuses_with_file_and_line(tmp_path, cli_status, line, problem):
    code, err = cli_status("run", _write(tmp_path, f"echo hi\n{line}\n"), "--check")
    assert code == 1, err
    assert "e.hbs:2: " in err and problem in err, err


# (fuzz, session 37) each of these passed --check, then hung on the
# simulator's virtual clock (inf, 1e300), passed at once without judging
# anything (nan: every comparison false), or failed only at run time (0)
_BAD_TIMES = [
    ("timeout 0", "seconds must be more than 0, got '0'"),
    ("timeout nan", "seconds must be a finite number, got 'nan'"),
    ("timeout inf", "seconds must be a finite number, got 'inf'"),
    ("timeout 1e400", "seconds must be a finite number, got '1e400'"),
    ("wait 0", "seconds must be more than 0, got '0'"),
    ("wait nan", "seconds must be a finite number, got 'nan'"),
    ("wait inf", "seconds must be a finite number, got 'inf'"),
    ("wait 1e300", "seconds must be at most 3600 (an hour), got '1e300'"),
    ("wait 3600.5", "seconds must be at most 3600 (an hour), got '3600.5'"),
    ("expect quiet nan", "seconds must be a finite number, got 'nan'"),
    ("expect quiet inf", "seconds must be a finite number, got 'inf'"),
    ("expect placements 3 within inf", "within must be a finite number, got 'inf'"),
    ("expect text NEVER within 1e300", "within must be at most 3600 (an hour), got '1e300'"),
    ("expect ack Status within nan", "within must be a finite number, got 'nan'"),
    ("expect err Ref from 1 within -inf", "within must be a finite number, got '-inf'"),
]


@pytest.mark.parametrize("line, problem", _BAD_TIMES)
def test_the_check_refuses_a_time_that_is_not_finite_positive_and_at_most_an_hour(
        tmp_path, cli_status, line, problem):
    code, err = cli_status("run", _write(tmp_path, f"select 1\n{line}\n"), "--check")
    assert code == 1, err
    assert f"e.hbs:2: {problem}" in err, err


def test_a_run_refuses_a_bad_time_before_the_session_opens(tmp_path, log_dir, cli_status):
    # the run checks the whole file first: nothing boots, nothing is sent
    # (before, 'wait nan' printed "all 3 steps passed")
    # (only the time that passed vacuously here: on the old code 'inf' hung)
    code, err = cli_status("run", _write(tmp_path, "select 1\nwait nan\nexpect quiet nan\n"),
                           "--scenario", "pair")
    assert code == 1, err
    assert "e.hbs:2: seconds must be a finite number, got 'nan'" in err
    assert "e.hbs:3: seconds must be a finite number, got 'nan'" in err
    assert "passed" not in err and "booted" not in err and not log_dir.exists()


def test_an_err_expectation_with_within_and_no_reason_passes_the_check(tmp_path, cli_status):
    # 'within' after the code is an option, not an unknown error reason
    code, err = cli_status("run", _write(tmp_path, "expect err Ref within 2\n"
                                                   "expect err Ref from 1 within 2\n"), "--check")
    assert code == 0, err


# --- expectations that must fail ------------------------------------------


def test_expect_text_without_a_count_fails_when_the_text_never_comes(responder, log_dir,
                                                                     tmp_path, cli_status):
    # count defaults to 1: with no LOCALIZED at all the step must fail, not pass
    text = "select 2\nexpect text LOCALIZED within 0.3\n"
    code, err = cli_status("run", _write(tmp_path, text), "--port", responder.path)
    assert code == 1, err
    assert "e.hbs:2: expect text LOCALIZED within 0.3: saw 0 of 1 'LOCALIZED'" in err


def test_expect_err_with_a_reason_fails_on_an_err_of_another_reason(responder, log_dir,
                                                                    tmp_path, cli_status):
    # module 2 answers ERR Ref ARG_RANGE: 'expect err Ref BUSY' must not pass on it
    _after_frames(responder, 2, parser.reply_error(65, 1, "M", 2))
    text = "select 2\npost Ref\nexpect err Ref BUSY within 2\n"
    code, err = cli_status("run", _write(tmp_path, text), "--port", responder.path)
    assert code == 1, err
    assert "e.hbs:3: expect err Ref BUSY within 2: no ERR 65 within 2 s" in err


@pytest.mark.parametrize(("text", "said"), [
    # only module 1 is selected: the ACK of module 3 never comes
    ("select 1\nRef\nexpect ack Ref from 1 3 within 0.3\n",
     "e.hbs:3: expect ack Ref from 1 3 within 0.3: no ACK 65 from 3 within 0.3 s"),
    # the double's module 3 has Yref 2
    ("select 3\nstatus\nexpect status 3 yref 4\n",
     "e.hbs:3: expect status 3 yref 4: module is yref 2"),
    # one module localized: 2 placements is one too many
    ("select 2\nLocalize\nexpect placements 2 within 0.3\n",
     "e.hbs:3: expect placements 2 within 0.3: 1 of 2 modules reported a position"),
    # "everything received since the last sent command": the ACK of the Ref
    # sent before the post is not an answer to anything after it
    ("select 2\nRef\npost Status\nexpect ack Ref within 0.3\n",
     "e.hbs:4: expect ack Ref within 0.3: no ACK 65 within 0.3 s"),
])
def test_an_expectation_the_replies_do_not_meet_fails(responder, log_dir, tmp_path,
                                                      cli_status, text, said):
    code, err = cli_status("run", _write(tmp_path, text), "--port", responder.path)
    assert code == 1, err
    assert said in err


def test_expect_quiet_fails_on_garbage(responder, log_dir, tmp_path, cli_status):
    # bytes that decode as no reply are no quiet line (written half a second
    # after the Select, inside the 3 s: room for a loaded machine)
    _after_frames(responder, 1, wire.PREAMBLE + b"M0\x01\x02zz" + wire.EOL, delay_s=0.5)
    text = "select 2\nexpect quiet 3\n"
    code, err = cli_status("run", _write(tmp_path, text), "--port", responder.path)
    assert code == 1, err
    assert "e.hbs:2: expect quiet 3: " in err


# --- times: on the simulator, in virtual time ------------------------------


def test_within_waits_longer_than_the_timeout(tmp_path, log_dir, cli_status):
    # the pair's localization flood takes ~23 s of robot time: 'within 60'
    # must wait for module 2's report although the script's timeout is 1 s
    text = "select 1\nRef\nselect 0\npost Localize\ntimeout 1\nexpect text LOCALIZED within 60\n"
    code, err = cli_status("run", _write(tmp_path, text), "--scenario", "pair")
    assert code == 0, err


def test_timeout_bounds_the_wait_for_replies(tmp_path, log_dir, cli_status):
    # no module 9: the Select waits the script's 7 s, not the protocol's bound
    code, err = cli_status("run", _write(tmp_path, "timeout 7\nselect 9\n"), "--scenario", "pair")
    assert code == 3, err
    assert "no reply from module 9 within 7.0 s" in err
