"""The grading report as one static HTML page (OUT/index.html) with its images beside it: a
table of every student's score, then per student each case with each check, its evidence,
the programs' output, the final LCD and the trajectory. No scripts, no network: it opens from
a file, a CI artifact or a course web space."""

from __future__ import annotations

import json
from html import escape
from pathlib import Path

from eyesim.paths import CASE_RECORDING as RECORDING

STYLE = """
body { font-family: system-ui, sans-serif; margin: 2em; color: #222; }
table { border-collapse: collapse; margin: 0.5em 0 1em; }
th, td { border: 1px solid #ccc; padding: 0.25em 0.6em; text-align: left; vertical-align: top; }
th { background: #f0f0f0; }
td.score, td.num { text-align: right; font-variant-numeric: tabular-nums; }
.pass { color: #1a7f37; font-weight: bold; }
.fail { color: #cf222e; font-weight: bold; }
.status { display: inline-block; padding: 0 0.4em; border-radius: 0.3em; font-size: 0.85em; background: #eee; }
.status.compile_error, .status.missing_sources, .status.grader_error { background: #ffd8d8; }
.status.timeout, .status.crashed, .status.cpu_limit { background: #fff1c2; }
.badge { display: inline-block; padding: 0 0.45em; border-radius: 0.3em; font-size: 0.85em; color: #fff; }
.badge.full { background: #1a7f37; } .badge.partial { background: #bf8700; } .badge.low { background: #cf222e; }
.replay code { background: #f6f8fa; padding: 0 0.3em; }
.student { border-top: 2px solid #888; margin-top: 2em; }
.case { margin-left: 1em; }
.images img { margin: 0.3em 0.6em 0.3em 0; border: 1px solid #ccc; vertical-align: top; }
pre { background: #f6f8fa; padding: 0.5em; overflow-x: auto; max-height: 20em; white-space: pre-wrap; }
"""


def _status(status: str) -> str:
    return f'<span class="status {escape(status)}">{escape(status.replace("_", " "))}</span>'


def _band(score: float) -> str:
    """The colour of a score's badge: full marks green, half or more amber, less red."""
    return "full" if score >= 0.999 else "partial" if score >= 0.5 else "low"


def _badge(case: dict) -> str:
    return f'<span class="badge {_band(case["score"])}">{100 * case["score"]:.0f}%</span>'


def _case_cell(case: dict | None) -> str:
    if case is None:
        return "<td>not graded</td>"
    extra = "" if case["status"] == "ok" else " " + _status(case["status"])
    return f'<td class="score">{_badge(case)}{extra}</td>'


def write_html(summary: dict, path: Path) -> None:
    cases = summary["cases"]
    parts = [
        f"<!doctype html><html lang='en'><head><meta charset='utf-8'><title>{escape(summary['title'])}</title>",
        f"<style>{STYLE}</style></head><body>",
        f"<h1>{escape(summary['title'])}</h1>",
        f"<p>{len(summary['students'])} submission(s), {len(cases)} case(s); graded on "
        f"{escape(summary['executor'])}. Spec: <code>{escape(summary['spec'])}</code></p>",
        "<table id='scores'><thead><tr><th>student</th><th>score</th><th>checks passed</th>"
        + "".join(f"<th>{escape(c['name'])} (×{c['weight']:g})</th>" for c in cases)
        + "</tr></thead><tbody>",
    ]
    for student in summary["students"]:
        by_case = {c["case"]: c for c in student["cases"]}
        anchor = f"student-{escape(student['name'])}"
        parts.append(
            f"<tr data-student='{escape(student['name'])}'><td><a href='#{anchor}'>{escape(student['name'])}</a></td>"
            f"<td class='score total'>{student['score']:.1f}</td>"
            f"<td class='num'>{student['passed_checks']}/{student['checks']}</td>"
            + "".join(_case_cell(by_case.get(c["name"])) for c in cases)
            + "</tr>"
        )
    parts.append("</tbody></table>")
    for student in summary["students"]:
        parts.append(_student_section(student))
    parts.append("</body></html>")
    path.write_text("\n".join(parts), encoding="utf-8")


def _student_section(student: dict) -> str:
    name = escape(student["name"])
    parts = [f"<section class='student' id='student-{name}'><h2>{name}: {student['score']:.1f} / 100</h2>"]
    for case in student["cases"]:
        status = "" if case["status"] == "ok" else " " + _status(case["status"])
        parts.append(
            f"<div class='case' data-case='{escape(case['case'])}'><h3>{escape(case['case'])}: "
            f"{_badge(case)}{status}</h3>"
        )
        recording = case.get("files", {}).get(RECORDING)
        if recording:
            parts.append(
                f"<p class='replay'><a class='replay-link' href='/replay-case?file={escape(recording)}'>"
                f"Watch the run</a> (when the report is served by <code>eyesim replay REPORT_FOLDER</code> "
                f"or <code>eyesim grade --serve</code>), or run <code>eyesim replay {escape(recording)}</code> "
                f"in the report's folder.</p>"
            )
        end = case.get("end")
        if end:
            parts.append(f"<p>Ran until {end['time']:.2f} s of simulation time ({escape(end['reason'])}).</p>")
        if case.get("hung"):
            parts.append(
                f"<p class='hung'>The run stood still: {escape(case['hung'])}.</p><ul>"
                + "".join(f"<li>{escape(line)}</li>" for line in end.get("stalled", []))
                + "</ul>"
            )
        for program, build in case.get("build", {}).items():
            if not build["ok"] or build["output"].strip():
                label = "does not build" if not build["ok"] else "built with messages"
                parts.append(
                    f"<details{' open' if not build['ok'] else ''}><summary>program {escape(program)} "
                    f"{label}</summary><pre>{escape(build['output'])}</pre></details>"
                )
        if case.get("error"):
            parts.append(f"<details open><summary>grader message</summary><pre>{escape(case['error'])}</pre></details>")
        parts.append(
            "<table class='checks'><thead><tr><th></th><th>check</th><th>weight</th><th>result</th>"
            "<th>evidence</th></tr></thead><tbody>"
        )
        for check in case["checks"]:
            mark = "<span class='pass'>✓</span>" if check["passed"] else "<span class='fail'>✗</span>"
            evidence = json.dumps(check.get("evidence", {}), sort_keys=True)
            evidence_cell = (
                f"<details><summary>show</summary><pre>{escape(evidence)}</pre></details>"
                if check.get("evidence")
                else ""
            )
            parts.append(
                f"<tr><td>{mark}</td><td>{escape(check['name'])}</td><td class='num'>{check['weight']:g}</td>"
                f"<td><pre>{escape(check['message'])}</pre></td><td>{evidence_cell}</td></tr>"
            )
        parts.append("</tbody></table>")
        for robot, program in sorted(case.get("programs", {}).items()):
            parts.append(
                f"<p>Robot {escape(robot)}, program {escape(program['name'])}: {escape(program['status'])}</p>"
            )
            for stream in ("stdout", "stderr"):
                if program.get(stream):
                    parts.append(
                        f"<details><summary>robot {escape(robot)} {stream}</summary>"
                        f"<pre>{escape(program[stream])}</pre></details>"
                    )
        images = [
            f"<img src='{escape(file)}' alt='{escape(name)}' title='{escape(name)}'>"
            for name, file in sorted(case.get("files", {}).items())
            if file.endswith((".png", ".svg"))
        ]
        if images:
            parts.append("<div class='images'>" + "".join(images) + "</div>")
        parts.append("</div>")
    parts.append("</section>")
    return "\n".join(parts)
