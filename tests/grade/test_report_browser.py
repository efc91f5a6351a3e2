"""The grading report as a coordinator sees it: opened from its file in headless Chromium."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "web"))
from browser import chromium_available, launch_browser  # noqa: E402

pytestmark = pytest.mark.browser


def test_the_report_shows_every_students_score_and_images(graded_lab, tmp_path):
    out, report, _ = graded_lab
    assert chromium_available(), "the browser tests need Chromium at /usr/bin/chromium"
    with launch_browser(webgl=False) as context:
        page = context.new_page()
        errors = []
        page.on("pageerror", lambda error: errors.append(str(error)))
        page.goto((out / "index.html").as_uri())
        rows = page.locator("#scores tbody tr")
        assert rows.count() == len(report["students"]) == 7
        shown = {
            rows.nth(i).locator("td").nth(0).inner_text(): rows.nth(i).locator("td.total").inner_text()
            for i in range(rows.count())
        }
        assert shown == {s["name"]: f"{s['score']:.1f}" for s in report["students"]}
        assert shown["good"] == "100.0" and shown["compile_error"] == "0.0"
        assert "compile error" in page.locator("tr[data-student='compile_error']").inner_text()
        # the student's section: the failed check with its reason, and the images loaded
        page.locator("a[href='#student-bumper']").click()
        section = page.locator("#student-bumper")
        assert "robot 1 touched walls 1 time(s): wall 2 at" in section.inner_text()
        images = section.locator("img")
        assert images.count() == 4  # LCD and trajectory of both cases
        for i in range(images.count()):
            assert images.nth(i).evaluate("image => image.complete && image.naturalWidth > 0")
        page.screenshot(path=str(tmp_path / "report.png"), full_page=True)
        assert errors == []
