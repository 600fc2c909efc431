"""JUnit XML of a hil-script sweep, so a CI server shows each case.

One ``testsuite`` per script, one ``testcase`` per firmware x scenario x
seed (classname ``FIRMWARE.SCENARIO``), with the failure's text and the
run's log. Written from the results table, so it always matches it.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from pathlib import Path

JUNIT_FILE = "junit.xml"


def case_name(row: dict) -> str:
    return f"seed {row['seed']}" if row.get("seed") is not None else "scenario seed"


def junit_xml(rows: list[dict]) -> ET.ElementTree:
    root = ET.Element("testsuites", name="hexbot sweep")
    by_script: dict[str, list[dict]] = {}
    for row in sorted(rows, key=lambda r: (r["script"], str(r.get("firmware")),
                                           str(r.get("scenario")), str(r.get("seed")))):
        by_script.setdefault(row["script"], []).append(row)
    for script, cases in by_script.items():
        suite = ET.SubElement(root, "testsuite", name=script, tests=str(len(cases)),
                              failures=str(sum(r["outcome"] == "failed" for r in cases)),
                              errors=str(sum(r["outcome"] == "error" for r in cases)),
                              time=f"{sum(r['seconds'] for r in cases):.3f}")
        for r in cases:
            firmware = r.get("firmware") or "default"
            scenario = r.get("scenario_run") or r.get("scenario")
            case = ET.SubElement(suite, "testcase", classname=f"{firmware}.{scenario}",
                                 name=case_name(r), time=f"{r['seconds']:.3f}")
            if r["outcome"] != "ok":
                tag = "failure" if r["outcome"] == "failed" else "error"
                ET.SubElement(case, tag, message=r["error"]).text = r["error"]
            if r.get("log"):
                ET.SubElement(case, "system-out").text = r["log"]
    ET.indent(root)
    return ET.ElementTree(root)


def write_junit(rows: list[dict], folder: Path) -> Path:
    path = folder / JUNIT_FILE
    junit_xml(rows).write(path, encoding="utf-8", xml_declaration=True)
    return path
