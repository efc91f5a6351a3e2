"""A teacher sees why a case failed: the failing case's recording is kept, the report links to it,
and `eyesim replay REPORT_FOLDER` serves the report and opens the replay from that link."""

from __future__ import annotations

import json
import re
import subprocess
import sys
from pathlib import Path

import pytest
from support.grading import ARRIVE_SPEC, ARRIVES, GETS_LOST, grade_class
from support.programs import eyesim_command

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "web"))
from browser import chromium_available, launch_browser  # noqa: E402

pytestmark = pytest.mark.browser


def test_a_failing_case_is_replayed_from_the_report(tmp_path):
    assert chromium_available(), "the browser tests need Chromium at /usr/bin/chromium"
    out = grade_class(tmp_path, ARRIVE_SPEC, {"good": ARRIVES, "lost": GETS_LOST})
    report = json.loads((out / "report.json").read_text())
    lost = next(s for s in report["students"] if s["name"] == "lost")["cases"][0]
    good = next(s for s in report["students"] if s["name"] == "good")["cases"][0]
    assert lost["score"] == 0 and "case.mcap" in lost["files"]
    assert good["score"] == 1 and "case.mcap" not in good["files"]  # only failed cases keep theirs

    server = subprocess.Popen(
        eyesim_command("replay", str(out), "--viewer-port", "0"),
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )
    try:
        report_url = re.search(r"(http://\S+)", server.stdout.readline()).group(1)
        with launch_browser() as context:
            page = context.new_page()
            errors = []
            page.on("pageerror", lambda error: errors.append(str(error)))
            page.goto(report_url)
            badge = page.locator("tr[data-student='lost'] .badge")
            assert badge.inner_text() == "0%" and "low" in badge.get_attribute("class")
            assert "full" in page.locator("tr[data-student='good'] .badge").get_attribute("class")
            page.screenshot(path=str(tmp_path / "report-badges.png"))
            print(f"screenshot: {tmp_path / 'report-badges.png'}")
            page.locator("#student-lost a.replay-link").click()
            page.wait_for_function(
                "() => window.eyesimViewer?.connectionState() === 'open' && "
                "window.eyesimViewer.timeline()?.mode === 'replay'"
            )
            shown = page.evaluate("() => window.eyesimViewer.timeline()")
            assert shown["end"] == pytest.approx(lost["end"]["time"], abs=0.05)  # the lost student's run
            assert page.evaluate("() => window.eyesimViewer.robotIds()") == [1]
            page.screenshot(path=str(tmp_path / "replay-from-report.png"))
            print(f"screenshot: {tmp_path / 'replay-from-report.png'}")
            assert errors == []
    finally:
        server.terminate()
        server.wait(timeout=10)
