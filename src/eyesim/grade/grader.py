"""A grading run: every submission x every case of a spec, on an executor, stored case by case,
then summarised as report.json, junit.xml and index.html in the output directory."""

from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path

from eyesim.grade.plots import trajectory_plot
from eyesim.grade.progress import Progress
from eyesim.grade.report_html import write_html
from eyesim.grade.spec import GradingSpec
from eyesim.grade.store import ResultStore
from eyesim.grade.submissions import Submission
from eyesim.grade.summary import summarise, write_json, write_junit


class Interrupted(Exception):
    def __init__(self, stored: int, total: int):
        super().__init__(
            f"interrupted: {stored} of {total} case(s) are stored; run the same command again to grade the rest"
        )


@dataclass
class GradingRun:
    summary: dict
    out: Path
    ran: int  # cases run now
    reused: int  # cases whose stored results were still valid


def tasks_for(
    spec: GradingSpec, submission: Submission, require_isolation: bool = False, keep_recordings: str = "failed"
) -> list[dict]:
    """What each case process is sent. With `require_isolation` a worker that cannot sandbox the
    case refuses it (sandbox.py); `keep_recordings` (failed, all, none): which cases' MCAP
    recordings come back with their results."""
    tasks = []
    for case in spec.cases:
        used = {entry["program"] for entry in case.robots}
        tasks.append(
            {
                "student": submission.name,
                "submission_files": submission.files,
                "case": case,
                "programs": {name: spec.programs[name] for name in sorted(used)},
                "python_checks": spec.python_checks,
                "require_isolation": require_isolation,
                "keep_recording": keep_recordings,
                "key": {"spec": spec.digest, "submission": submission.digest, "case": case.name},
            }
        )
    return tasks


def grade(
    spec: GradingSpec,
    submissions: list[Submission],
    out: Path,
    executor,
    resume: bool = True,
    progress_stream=None,
    require_isolation: bool = False,
    keep_recordings: str = "failed",
) -> GradingRun:
    """Grade; results already stored for the same spec and submission are reused when `resume`.
    A KeyboardInterrupt stops the run; what finished is stored."""
    out.mkdir(parents=True, exist_ok=True)
    store = ResultStore(out)
    results: dict[tuple[str, str], dict] = {}
    pending = []
    for submission in submissions:
        for task in tasks_for(spec, submission, require_isolation, keep_recordings):
            stored = store.load(task["student"], task["case"].name, task["key"]) if resume else None
            if stored is not None:
                results[(task["student"], task["case"].name)] = stored
            else:
                pending.append(task)
    progress = Progress(len(pending) + len(results), progress_stream)
    for result in results.values():
        progress.advance(result, reused=True)
    reused = len(results)
    if pending:
        progress.message(f"grading {len(pending)} case(s) on {executor.description}")
    try:
        for result in executor.run(pending):
            stored = store.save(result)
            plot = out / "cases" / result["student"] / result["case"] / "trajectory.svg"
            if result.get("robots"):
                try:
                    trajectory_plot(spec.case(result["case"]).scene, stored, plot)
                    stored["files"]["trajectory.svg"] = plot.relative_to(out).as_posix()
                    store.path(result["student"], result["case"]).write_text(
                        json.dumps(stored, indent=1, sort_keys=True)
                    )
                except Exception as error:  # a plot is a nicety; the result stands without it
                    progress.message(f"no trajectory plot for {result['student']}/{result['case']}: {error}")
            results[(result["student"], result["case"])] = stored
            progress.advance(stored)
    except KeyboardInterrupt:
        executor.close(abort=True)
        raise Interrupted(len(results), progress.total) from None
    executor.close()
    summary = summarise(spec, results, [s.name for s in submissions], executor.description)
    write_json(summary, out / "report.json")
    write_junit(summary, out / "junit.xml")
    write_html(summary, out / "index.html")
    return GradingRun(summary, out, len(results) - reused, reused)
