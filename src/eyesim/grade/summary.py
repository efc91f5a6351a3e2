"""From stored case results to the grading's summary (report.json): per student the weighted
score and every case; and the JUnit XML that CI systems show (report_junit)."""

from __future__ import annotations

import json
import xml.etree.ElementTree as ET
from pathlib import Path


def student_score(cases: list[dict]) -> float:
    """0..100: the cases' scores weighted by the cases' weights."""
    total = sum(c["weight"] for c in cases)
    return 100 * sum(c["weight"] * c["score"] for c in cases) / total if total else 0.0


def summarise(spec, results: dict[tuple[str, str], dict], students: list[str], executor: str) -> dict:
    rows = []
    for student in students:
        cases = [results[(student, case.name)] for case in spec.cases if (student, case.name) in results]
        rows.append(
            {
                "name": student,
                "score": round(student_score(cases), 2),
                "complete": len(cases) == len(spec.cases),
                "passed_checks": sum(c["passed"] for case in cases for c in case["checks"]),
                "checks": sum(len(case["checks"]) for case in cases),
                "cases": cases,
            }
        )
    return {
        "title": spec.title,
        "spec": str(spec.path),
        "spec_digest": spec.digest,
        "executor": executor,
        "cases": [
            {"name": c.name, "weight": c.weight, "scene": c.scene_path, "time_limit": c.time} for c in spec.cases
        ],
        "students": rows,
    }


def write_json(summary: dict, path: Path) -> None:
    path.write_text(json.dumps(summary, indent=1, sort_keys=True))


def deterministic_view(result: dict) -> dict:
    """A case result without what depends on where and when it ran (for comparing runs)."""
    return {key: value for key, value in result.items() if key not in ("timing", "files")}


def write_junit(summary: dict, path: Path) -> None:
    """One testsuite per student, one testcase per check (classname student.case); checks
    that were not run because the program did not build are errors, failed checks failures."""
    suites = ET.Element("testsuites", name=summary["title"])
    totals = {"tests": 0, "failures": 0, "errors": 0}
    for student in summary["students"]:
        suite = ET.SubElement(suites, "testsuite", name=student["name"])
        counts = {"tests": 0, "failures": 0, "errors": 0}
        for case in student["cases"]:
            seconds = case.get("timing", {}).get("case_seconds", 0.0) / max(len(case["checks"]), 1)
            for check in case["checks"]:
                counts["tests"] += 1
                element = ET.SubElement(
                    suite,
                    "testcase",
                    classname=f"{student['name']}.{case['case']}",
                    name=check["name"],
                    time=f"{seconds:.3f}",
                )
                if check["passed"]:
                    continue
                is_error = case["status"] in ("compile_error", "missing_sources", "grader_error")
                counts["errors" if is_error else "failures"] += 1
                detail = ET.SubElement(
                    element,
                    "error" if is_error else "failure",
                    message=check["message"][:500],
                    type=case["status"] if is_error else check["kind"],
                )
                detail.text = _details(case, check)
        for key, value in counts.items():
            suite.set(key, str(value))
            totals[key] += value
        suite.set("score", f"{student['score']:.2f}")
    for key, value in totals.items():
        suites.set(key, str(value))
    ET.indent(suites)
    ET.ElementTree(suites).write(path, encoding="utf-8", xml_declaration=True)


def _details(case: dict, check: dict) -> str:
    lines = [check["message"]]
    if check.get("evidence"):
        lines.append("evidence: " + json.dumps(check["evidence"], sort_keys=True)[:2000])
    for name, build in case.get("build", {}).items():
        if not build["ok"]:
            lines.append(f"build of {name}:\n{build['output']}")
    if case.get("error"):
        lines.append(case["error"])
    return "\n".join(lines)
