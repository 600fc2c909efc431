"""JUnit XML for a script run: one ``testcase`` per step, so a CI server
(GitLab, Jenkins, GitHub's test reporters) lists every step with its time
and shows the failing step's reason.

Times are the session clock's: simulated seconds on the simulator (the
same on every run, however loaded the CI machine is), wall seconds on
hardware. The schema is the common Jenkins/Surefire subset every reader
accepts: ``testsuites/testsuite/testcase`` with ``failure``, ``error``,
``skipped`` and ``system-out``.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from collections.abc import Sequence
from pathlib import Path

from hexbot.host.script import INTERRUPTED, StepResult, StepStatus

SKIPPED_REASON = "not run: an earlier step failed"


def testcase_name(result: StepResult) -> str:
    """``line 12: Localize`` — the line number keeps repeated steps apart."""
    return f"line {result.step.line}: {result.step.text}"


def suite_element(script: str, results: Sequence[StepResult]) -> ET.Element:
    counts = {status: sum(r.status is status for r in results) for status in StepStatus}
    suite = ET.Element("testsuite", {
        "name": script,
        "tests": str(len(results)),
        "failures": str(counts[StepStatus.FAILED]),
        "errors": str(counts[StepStatus.ERROR]),
        "skipped": str(counts[StepStatus.NOT_RUN]),
        "time": f"{sum(r.seconds for r in results):.3f}",
    })
    classname = Path(script).stem.replace(".", "_")
    for result in results:
        case = ET.SubElement(suite, "testcase", {
            "classname": classname,
            "name": testcase_name(result),
            "file": script,
            "line": str(result.step.line),
            "time": f"{result.seconds:.3f}",
        })
        if result.status is StepStatus.FAILED:
            ET.SubElement(case, "failure", {"message": result.message,
                                            "type": "ScriptFailed"}).text = result.message
        elif result.status is StepStatus.ERROR:
            kind = "Interrupted" if result.message == INTERRUPTED else "PortLost"
            ET.SubElement(case, "error", {"message": result.message,
                                          "type": kind}).text = result.message
        elif result.status is StepStatus.NOT_RUN:
            ET.SubElement(case, "skipped", {"message": SKIPPED_REASON})
        elif result.message:
            ET.SubElement(case, "system-out").text = result.message
    return suite


def write_junit(path: Path, script: str, results: Sequence[StepResult]) -> None:
    root = ET.Element("testsuites")
    root.append(suite_element(script, results))
    ET.indent(root)
    Path(path).write_bytes(ET.tostring(root, encoding="utf-8", xml_declaration=True) + b"\n")
