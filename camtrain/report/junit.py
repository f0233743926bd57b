"""JUnit XML for CI dashboards: one <testsuite> per deck, one <testcase> per design limit.

A deck that could not be run is one <testcase name="run"> with an <error>; a deck without limits
is one passing <testcase name="run">, so every deck shows up on the dashboard.
"""
from __future__ import annotations

import xml.etree.ElementTree as ET
from dataclasses import dataclass, field

from camtrain.report.limits import UNAVAILABLE, Check


@dataclass
class DeckReport:
    """What the JUnit report needs to know about one deck of a batch."""

    name: str                      # deck stem: the suite name
    path: str
    seconds: float = 0.0
    checks: list[Check] = field(default_factory=list)
    error: str | None = None       # the deck failed to load or run
    exit_code: int = 0


def junit_xml(decks: list[DeckReport]) -> str:
    root = ET.Element("testsuites", name="camtrain run --check")
    totals = {"tests": 0, "failures": 0, "errors": 0}
    for d in decks:
        suite = ET.SubElement(root, "testsuite", name=d.name, file=d.path,
                              time=f"{d.seconds:.3f}")
        counts = {"tests": 0, "failures": 0, "errors": 0, "skipped": 0}
        if d.error is not None:
            case = ET.SubElement(suite, "testcase", classname=d.name, name="run",
                                 time=f"{d.seconds:.3f}")
            ET.SubElement(case, "error", type=f"exit {d.exit_code}", message=d.error).text = d.error
            counts["tests"] += 1
            counts["errors"] += 1
        elif not d.checks:
            ET.SubElement(suite, "testcase", classname=d.name, name="run",
                          time=f"{d.seconds:.3f}")
            counts["tests"] += 1
        for c in d.checks:
            case = ET.SubElement(suite, "testcase", classname=d.name, name=c.limit, time="0")
            counts["tests"] += 1
            if not c.ok:
                kind = "unavailable" if c.status == UNAVAILABLE else "limit violated"
                ET.SubElement(case, "failure", type=kind, message=c.text()).text = c.text()
                counts["failures"] += 1
            else:
                ET.SubElement(case, "system-out").text = c.text()
        for k, v in counts.items():
            suite.set(k, str(v))
        for k in totals:
            totals[k] += counts[k]
    for k, v in totals.items():
        root.set(k, str(v))
    ET.indent(root)
    return '<?xml version="1.0" encoding="UTF-8"?>\n' + ET.tostring(root, encoding="unicode") + "\n"
