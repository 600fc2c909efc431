"""JUnit reports of scripts at their edges (a mutation audit): a lost port
is an `error` (not a `failure`) with its counts, each case's `line`, and
the reply of a passed step in pytest's own --junitxml."""

from __future__ import annotations

import threading
import xml.etree.ElementTree as ET

import pytest

from hexbot.cli import main

pytest_plugins = ["pytester"]


def _suite(xml_path):
    suite = ET.parse(xml_path).getroot().find("testsuite")
    return suite, suite.findall("testcase")


def test_a_lost_port_is_a_junit_error_with_the_steps_line(responder, log_dir, tmp_path, capsys):
    # CI must tell "the step could not be judged" (error) from "the robot
    # answered wrong" (failure); each case names its script line
    script = tmp_path / "lost.hbs"
    script.write_text("# pull the cable during the wait\n\nselect 2\n"
                      "expect ack 65 within 60\necho never\n")

    def pull():
        for _ in range(500):
            if responder.received:  # the Select went out
                break
            threading.Event().wait(0.01)
        threading.Event().wait(0.3)
        responder.close()

    threading.Thread(target=pull, daemon=True).start()
    out = tmp_path / "r.xml"
    assert main(["run", str(script), "--port", responder.path, "--junit", str(out)]) == 4
    suite, cases = _suite(out)
    assert (suite.get("tests"), suite.get("failures"), suite.get("errors"),
            suite.get("skipped")) == ("3", "0", "1", "1")
    assert [c.get("line") for c in cases] == ["3", "4", "5"]
    assert cases[1].find("failure") is None
    error = cases[1].find("error")
    assert error is not None and "port lost" in error.get("message")
    assert cases[2].find("skipped") is not None


@pytest.mark.filterwarnings("ignore::pytest.PytestAssertRewriteWarning")
def test_pytest_junitxml_carries_a_passed_steps_reply(pytester):
    # hexbot run --junit puts the reply in system-out; under pytest it is the
    # case's 'reply' property
    pytester.makefile(".hbs", test_sel="# scenario: pair\nselect 1\n")
    report = pytester.path / "report.xml"
    result = pytester.runpytest_subprocess("-p", "no:cacheprovider", f"--junitxml={report}")
    result.assert_outcomes(passed=1)
    (case,) = ET.parse(report).getroot().iter("testcase")
    props = {p.get("name"): p.get("value") for p in case.iter("property")}
    assert "ACK 69" in props.get("reply", ""), props
