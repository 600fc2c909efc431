"""CI reports of scripts: `hexbot run --junit` and `test_*.hbs` under pytest,
both on the simulator's hexbot-sim:// port (virtual time)."""

from __future__ import annotations

import xml.etree.ElementTree as ET

import pytest

from hexbot.cli import main

pytest_plugins = ["pytester"]

# Module 2 of the pair answers its status unlocalized: line 4 fails.
FAILING = """# scenario: pair
select 2
status
expect status 2 localized
echo never reached
"""


def _cases(xml_path):
    suite = ET.parse(xml_path).getroot().find("testsuite")
    return suite, suite.findall("testcase")


def test_run_junit_has_one_case_per_step_with_the_failure_reason(tmp_path, log_dir, capsys):
    script = tmp_path / "status.hbs"
    script.write_text(FAILING)
    out = tmp_path / "out.xml"
    assert main(["run", str(script), "--junit", str(out)]) == 1
    suite, cases = _cases(out)
    assert [c.get("name") for c in cases] == [
        "line 2: select 2", "line 3: status", "line 4: expect status 2 localized",
        "line 5: echo never reached"]
    assert (suite.get("tests"), suite.get("failures"), suite.get("skipped")) == ("4", "1", "1")
    assert cases[0].find("failure") is None and "ACK 69" in cases[0].findtext("system-out")
    failure = cases[2].find("failure")
    assert failure is not None
    assert failure.get("message") == (f"{script}:4: expect status 2 localized: module is "
                                      "not localized (STA id 2 role M not localized "
                                      "last error NONE)")
    assert cases[3].find("skipped") is not None
    # simulated seconds: the Select waited for its ACK, which takes the IR
    # link's time on the robot's clock
    assert float(cases[0].get("time")) > 0.1
    assert abs(float(suite.get("time")) - sum(float(c.get("time")) for c in cases)) < 0.01


def test_run_junit_of_a_passing_script(tmp_path, log_dir):
    script = tmp_path / "ok.hbs"
    script.write_text("# scenario: pair\nselect 1\nRef\n")
    out = tmp_path / "out.xml"
    assert main(["run", str(script), "--junit", str(out)]) == 0
    suite, cases = _cases(out)
    assert (suite.get("tests"), suite.get("failures"), suite.get("errors")) == ("2", "0", "0")
    assert all(c.find("failure") is None and c.find("skipped") is None for c in cases)


@pytest.mark.filterwarnings("ignore::pytest.PytestAssertRewriteWarning")
def test_pytest_collects_hbs_scripts_one_test_per_step(pytester):
    pytester.makefile(".hbs", test_status=FAILING)
    pytester.makefile(".hbs", test_ref="# scenario: pair\nselect 1\nRef\n")
    pytester.makefile(".hbs", helper="select 1\n")  # not test_*: not collected
    report = pytester.path / "report.xml"
    result = pytester.runpytest_subprocess("-p", "no:cacheprovider", f"--junitxml={report}")
    result.assert_outcomes(passed=4, failed=1, skipped=1)
    result.stdout.fnmatch_lines(["*test_status.hbs:4: expect status 2 localized: "
                                 "module is not localized*"])
    cases = ET.parse(report).getroot().iter("testcase")
    by_name = {c.get("name"): c for c in cases}
    assert set(by_name) == {"line 2: select 2", "line 3: status",
                            "line 4: expect status 2 localized", "line 5: echo never reached",
                            "line 2: select 1", "line 3: Ref"}
    assert by_name["line 4: expect status 2 localized"].find("failure") is not None
    assert by_name["line 5: echo never reached"].find("skipped") is not None


def test_pytest_reports_a_bad_script_line_as_a_collection_error(pytester):
    pytester.makefile(".hbs", test_bad="select 1\nfrobnicate 3\n")
    result = pytester.runpytest_subprocess("-p", "no:cacheprovider")
    result.stdout.fnmatch_lines(["*test_bad.hbs:2: *frobnicate*"])
    assert result.ret == pytest.ExitCode.INTERRUPTED


def test_pytest_reports_a_scenario_line_naming_no_file_as_a_collection_error(pytester):
    # the file is the script's neighbour: missing there, the script is not run
    # on some other cluster (nor fails in its set-up, step by step)
    pytester.makefile(".hbs", test_rig="# scenario: rig.toml\nselect 1\n")
    result = pytester.runpytest_subprocess("-p", "no:cacheprovider")
    result.stdout.fnmatch_lines(["*test_rig.hbs:1: scenario: *rig.toml: no such scenario file*"])
    assert result.ret == pytest.ExitCode.INTERRUPTED


def test_run_junit_is_written_when_the_port_does_not_open(tmp_path, log_dir):
    # "written also on failure": a port that never opened wrote no report
    script = tmp_path / "status.hbs"
    script.write_text(FAILING)
    out = tmp_path / "out.xml"
    assert main(["run", str(script), "--port", str(tmp_path / "no-such-tty"),
                 "--junit", str(out)]) == 4
    suite, cases = _cases(out)
    assert (suite.get("tests"), suite.get("errors"), suite.get("skipped")) == ("4", "1", "3")
    error = cases[0].find("error")
    assert error.get("type") == "PortLost" and "cannot open" in error.get("message")


def test_run_junit_records_a_ctrl_c_mid_script_as_interrupted(tmp_path, log_dir, monkeypatch):
    from hexbot.host.script import ScriptRunner

    real = ScriptRunner.run_step

    def ctrl_c_at_the_third(self, step):
        if step.line == 4:
            raise KeyboardInterrupt
        return real(self, step)

    monkeypatch.setattr(ScriptRunner, "run_step", ctrl_c_at_the_third)
    script = tmp_path / "status.hbs"
    script.write_text(FAILING)
    out = tmp_path / "out.xml"
    assert main(["run", str(script), "--junit", str(out)]) == 130
    suite, cases = _cases(out)
    assert (suite.get("errors"), suite.get("skipped")) == ("1", "1")
    error = cases[2].find("error")
    assert (error.get("type"), error.get("message")) == ("Interrupted", "interrupted (Ctrl-C)")


def test_run_junit_is_written_on_ctrl_c_during_the_boot(tmp_path):
    # a real SIGINT while the simulated modules boot (paced at real time)
    import os
    import signal
    import subprocess
    import sys
    from pathlib import Path

    script = tmp_path / "status.hbs"
    script.write_text(FAILING)
    out = tmp_path / "out.xml"
    hexbot = Path(sys.executable).with_name("hexbot")
    proc = subprocess.Popen([str(hexbot), "run", str(script), "--sim-speed", "1", "--no-log",
                             "--junit", str(out)], stderr=subprocess.PIPE, text=True,
                            start_new_session=True,
                            preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
    try:
        lines = []
        for line in proc.stderr:  # the port is open: the modules boot for ~8 s now
            lines.append(line)
            if line.startswith("ir: connected"):
                break
        os.killpg(proc.pid, signal.SIGINT)
        err = "".join(lines) + proc.stderr.read()
        proc.wait(timeout=120)
    finally:
        if proc.poll() is None:
            os.killpg(proc.pid, signal.SIGKILL)
            proc.wait()
    assert proc.returncode == 130, err
    assert "Traceback" not in err
    suite, cases = _cases(out)
    assert (suite.get("tests"), suite.get("errors"), suite.get("skipped")) == ("4", "1", "3")
    assert cases[0].find("error").get("type") == "Interrupted"
