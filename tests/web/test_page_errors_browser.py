"""No browser console error, failed request or 404 on the live viewer, the replay, the robot editor
and the grading report (with the replay it links to), against the real programs in headless
Chromium; a replay asks for nothing only a live run has (/scenes/, /api/) and offers no robot
editor, whose page it does not serve."""

from __future__ import annotations

import re
import subprocess
import sys
from dataclasses import dataclass, field
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from support.grading import ARRIVE_SPEC, GETS_LOST, grade_class  # noqa: E402
from support.programs import eyesim_command, simulator_with_viewer  # noqa: E402
from support.recordings import record_tour  # noqa: E402

pytestmark = pytest.mark.browser

PROGRAM = """from eye import *
CAMInit(QQVGA)
LCDMenu("GO", "", "", "END")
print("hello", flush=True)
while True:
    CAMGet()
    LCDSetPrintf(0, 0, "running")
    OSWait(100)
"""


@dataclass
class Problems:
    """What went wrong in a tab: console errors, uncaught exceptions, failed or refused requests."""

    console: list[str] = field(default_factory=list)
    responses: list[str] = field(default_factory=list)
    requests: list[str] = field(default_factory=list)

    def watch(self, page) -> None:
        page.on("console", lambda m: m.type == "error" and self.console.append(f"{m.text} ({m.location})"))
        page.on("pageerror", lambda error: self.console.append(str(error)))
        page.on("requestfailed", lambda r: self.responses.append(f"{r.url}: {r.failure}"))
        page.on("response", lambda r: r.status >= 400 and self.responses.append(f"{r.status} {r.url}"))
        page.on("request", lambda r: self.requests.append(r.url))

    def assert_none(self) -> None:
        assert self.console == [] and self.responses == [], (self.console, self.responses)


def watched_page(context, problems: Problems):
    page = context.new_page()
    page.set_default_timeout(60_000)  # programs starting on a loaded 2-core machine
    problems.watch(page)
    return page


def test_the_live_viewer_and_the_robot_editor_have_no_errors(browser_context, tmp_path):
    (tmp_path / "camera.py").write_text(PROGRAM)
    with simulator_with_viewer("default", "--program", "1=camera.py", cwd=tmp_path) as (_, url):
        problems = Problems()
        page = watched_page(browser_context, problems)
        page.goto(url)
        page.wait_for_function(
            "() => window.eyesimViewer?.connectionState() === 'open' && "
            "window.eyesimViewer.lcdUpdates(1) > 1 && window.eyesimViewer.cameraImages(1) > 1 && "
            "window.eyesimViewer.consoleText(1).includes('hello')"
        )
        page.wait_for_selector("#edit-scene:not([hidden])")
        # What a student clicks first: the settings, the plots, the scene browser, the I/O.
        page.click("#settings-toggle")
        page.wait_for_function("() => window.eyesimViewer.settingsShown().settings !== null")
        page.click("#plots-toggle")
        page.locator("input[data-signal='robot/1/x']").check()
        page.wait_for_function("() => window.eyesimViewer.plotted().length === 1")
        page.click("#open-scenes")
        page.wait_for_function("() => document.querySelectorAll('#scene-files button').length > 0")
        page.keyboard.press("Escape")
        page.locator(".robot-io summary").click()
        problems.assert_none()

        with page.expect_popup() as popup:
            page.click("#robot-editor-link")
        editor = popup.value
        editor.set_default_timeout(60_000)
        problems.watch(editor)
        editor.wait_for_function(
            "() => window.eyesimRobotEditor && eyesimRobotEditor.checks() > 0 && eyesimRobotEditor.idle()"
        )
        editor.wait_for_function("() => eyesimRobotEditor.preview() !== null")
        problems.assert_none()


def test_the_replay_has_no_errors_and_asks_for_nothing_only_a_live_run_has(browser_context, tmp_path):
    tour = record_tour(tmp_path, robots=2)
    replay = subprocess.Popen(
        eyesim_command("replay", str(tour), "--viewer-port", "0"),
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )
    try:
        url = re.search(r"(http://\S+)", replay.stdout.readline()).group(1)
        problems = Problems()
        page = watched_page(browser_context, problems)
        page.goto(url)
        page.wait_for_function(
            "() => window.eyesimViewer?.timeline().mode === 'replay' && "
            "window.eyesimViewer.framesShown() > 0 && window.eyesimViewer.lcdUpdates(1) > 0"
        )
        page.locator("#tl-scrub").fill("5000")
        page.wait_for_function("() => window.eyesimViewer.framesShown() > 1")
        page.click("#plots-toggle")
        page.locator("input[data-signal='robot/1/x']").check()
        page.wait_for_function("() => window.eyesimViewer.plotted().length === 1")
        for hidden in (
            "#robot-editor-link",
            "#settings-toggle",
            "#pause",
            "#reset",
            "#open-scenes",
            "#edit-scene",
            ".program-controls",
        ):
            assert page.locator(hidden).first.is_hidden(), hidden
        asked = [u for u in problems.requests if "/scenes/" in u or "/api/" in u or "robot-editor" in u]
        assert asked == []
        problems.assert_none()
    finally:
        replay.terminate()
        replay.wait(timeout=10)


def test_the_grading_report_and_the_replay_it_links_have_no_errors(browser_context, tmp_path):
    out = grade_class(tmp_path, ARRIVE_SPEC, {"lost": GETS_LOST})
    server = subprocess.Popen(
        eyesim_command("replay", str(out), "--viewer-port", "0"),
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )
    try:
        report_url = re.search(r"(http://\S+)", server.stdout.readline()).group(1)
        problems = Problems()
        page = watched_page(browser_context, problems)
        page.goto(report_url)
        page.wait_for_selector("#student-lost a.replay-link")
        page.wait_for_load_state("load")
        problems.assert_none()
        page.locator("#student-lost a.replay-link").click()
        page.wait_for_function(
            "() => window.eyesimViewer?.connectionState() === 'open' && "
            "window.eyesimViewer.timeline()?.mode === 'replay' && "
            "window.eyesimViewer.framesShown() > 0"
        )
        problems.assert_none()
    finally:
        server.terminate()
        server.wait(timeout=10)
