"""Programs, robot selection, cameras and settings from the page, in headless Chromium against a real
`eyesim run`: compile a C program from the page and watch the robot drive, stop and restart it, see
why a program crashed, pick a robot by clicking it in 3D among 20, switch the camera, change settings.

Screenshots go to $EYESIM_SCREENSHOTS when it is set (for looking at them)."""

import math
import shutil
import sys
from pathlib import Path

import pytest
from browser import open_viewer, robot_panel, robot_screen_position
from browser import save_screenshot as screenshot

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from support.programs import simulator_with_viewer  # noqa: E402

from eyesim.scene.builtins import SCENES_DIR  # noqa: E402

pytestmark = pytest.mark.browser

DRIVE = """#include "eyebot.h"
int main(void) { printf("driving\\n"); VWSetSpeed(150, 0); for (;;) OSWait(100); }
"""
BROKEN = """#include "eyebot.h"
int main(void) {
  int x = ;
  return 0;
}
"""
CRASH = """#include <stdio.h>
int main(void) { volatile int *p = 0; *p = 1; return 0; }
"""


def moved_since(page, start: list[float]) -> None:
    page.wait_for_function(
        "s => { const p = window.eyesimViewer.robotPose(1); return p && Math.hypot(p.pos[0] - s[0], p.pos[1] - s[1]) > 0.05; }",
        arg=start,
        timeout=20_000,
    )


def choose_and_click(panel, path: str, button: str) -> None:
    panel.locator(f'.program-choice option[data-path="{path}"]').wait_for(state="attached")
    panel.locator(".program-choice").select_option(value=f"0:{path}")
    panel.locator(f".program-{button}").click()


@pytest.fixture
def folder(tmp_path):
    (tmp_path / "drive.c").write_text(DRIVE)
    (tmp_path / "broken.c").write_text(BROKEN)
    (tmp_path / "crash.c").write_text(CRASH)
    (tmp_path / "give_up.py").write_text(
        "from eye import *\nprint('thinking')\nraise RuntimeError('the program gave up')\n"
    )
    return tmp_path


def test_compile_start_stop_and_restart_from_the_page(browser_context, folder):
    with simulator_with_viewer("default", cwd=folder) as (_, url):  # a scene named: no scene browser over the page
        viewer = open_viewer(browser_context, url)
        page = viewer.page
        panel = robot_panel(page, 1)

        choose_and_click(panel, "broken.c", "compile")
        page.wait_for_function("() => window.eyesimViewer.compilerLines(1).length > 0", timeout=60_000)
        lines = viewer.state("compilerLines", 1)
        assert any(line.startswith("broken.c:3:") and ": error: " in line for line in lines), lines
        assert "broken.c did not compile" in viewer.state("programMessage", 1)
        screenshot(page, "compile-error")

        choose_and_click(panel, "drive.c", "compile")
        page.wait_for_function("() => window.eyesimViewer.programMessage(1) === 'compiled drive'", timeout=60_000)
        assert panel.locator(".program-choice").input_value() == "0:drive"
        start = viewer.state("robotPose", 1)["pos"]
        panel.locator(".program-start").click()
        page.wait_for_function("() => window.eyesimViewer.programState(1)?.event === 'started'")
        moved_since(page, start)
        page.wait_for_function("() => window.eyesimViewer.consoleText(1).includes('driving')")
        screenshot(page, "driving")
        # The follow camera moves along with the driving robot.
        page.locator("#view-mode").select_option("follow")
        page.wait_for_function("() => window.eyesimViewer.cameraState().following === 1")
        camera = viewer.state("cameraState")["position"]
        page.wait_for_function(
            "c => { const p = window.eyesimViewer.cameraState().position; return Math.hypot(p[0] - c[0], p[2] - c[2]) > 0.05; }",
            arg=camera,
            timeout=20_000,
        )
        assert abs(viewer.state("cameraState")["position"][1] - camera[1]) < 0.01  # at the same height above the floor

        panel.locator(".program-stop").click()
        page.wait_for_function("() => window.eyesimViewer.programState(1)?.event === 'exited'")
        assert panel.locator(".program-state").text_content() == "drive stopped (SIGTERM)"
        stopped = viewer.state("robotPose", 1)["pos"]
        panel.locator(".program-restart").click()
        page.wait_for_function("() => window.eyesimViewer.programState(1)?.event === 'started'")
        moved_since(page, stopped)
        assert viewer.state("consoleText", 1).count("driving") == 2
        assert viewer.errors == []


def test_a_crash_and_a_traceback_show_why_the_program_ended(browser_context, folder):
    with simulator_with_viewer("default", cwd=folder) as (_, url):  # a scene named: no scene browser over the page
        viewer = open_viewer(browser_context, url)
        page = viewer.page
        panel = robot_panel(page, 1)
        choose_and_click(panel, "crash.c", "compile")
        page.wait_for_function("() => window.eyesimViewer.programMessage(1) === 'compiled crash'", timeout=60_000)
        panel.locator(".program-start").click()
        page.wait_for_function("() => window.eyesimViewer.consoleText(1).includes('crash crashed')")
        assert "eyesim: crash crashed: segmentation fault (SIGSEGV)" in viewer.state("consoleText", 1)
        page.wait_for_function("() => window.eyesimViewer.programState(1)?.exit_code === -11")
        assert panel.locator(".program-state").text_content() == "crash crashed: SIGSEGV"
        assert panel.locator(".program-state").get_attribute("data-kind") == "failed"
        screenshot(page, "crashed")

        choose_and_click(panel, "give_up.py", "start")
        page.wait_for_function(
            "() => window.eyesimViewer.programState(1)?.name === 'give_up.py' && "
            "window.eyesimViewer.programState(1)?.event === 'exited'"
        )
        console = viewer.state("consoleText", 1)
        assert "Traceback (most recent call last)" in console and "RuntimeError: the program gave up" in console
        assert panel.locator(".program-state").text_content() == "give_up.py exited with code 1"
        assert viewer.errors == []


def test_settings_from_the_page_take_effect(browser_context, folder):
    with simulator_with_viewer("default", cwd=folder) as (_, url):  # a scene named: no scene browser over the page
        viewer = open_viewer(browser_context, url)
        page = viewer.page
        page.wait_for_function("() => window.eyesimViewer.raySegments() > 0")  # the arena has VIS
        page.locator("#settings-toggle").click()
        page.wait_for_function("() => window.eyesimViewer.settingsShown().settings !== null")
        assert page.locator(".settings-panel .setting-clock").text_content().startswith("Clock: realtime, 1× speed")
        page.locator(".setting-vis").uncheck()
        page.locator(".setting-trace").check()
        page.locator(".setting-psd-noise").fill("4.5")
        page.locator(".setting-seed").fill("42")
        page.locator(".settings-apply").click()
        page.wait_for_function("() => window.eyesimViewer.settingsShown().settings?.seed === 42")
        assert viewer.state("settingsShown")["settings"]["psd_noise"] == 4.5
        page.wait_for_function("() => window.eyesimViewer.raySegments() === 0")
        screenshot(page, "settings")

        page.locator(".setting-seed").fill("-3")
        page.locator(".settings-apply").click()
        assert page.locator(".settings-message").text_content() == "Random seed: enter a whole number, 0 or more"
        # Another tab opening the settings sees what was applied.
        other = open_viewer(browser_context, url)
        other.page.locator("#settings-toggle").click()
        other.page.wait_for_function("() => window.eyesimViewer.settingsShown().settings?.seed === 42")
        assert other.page.locator(".setting-trace").is_checked() and not other.page.locator(".setting-vis").is_checked()
        page.locator("#speed").select_option("max")
        page.wait_for_function("() => window.eyesimViewer.status()?.speed === 'max'")
        assert viewer.errors == [] and other.errors == []


def twenty_robots(folder: Path) -> Path:
    shutil.copy(SCENES_DIR / "arena.wld", folder / "arena.wld")
    rows = (250, 650, 1100, 1750)  # clear of the arena's inner walls
    lines = ["world arena.wld"] + [f"S4 {300 + 350 * (i % 5)} {rows[i // 5]} {18 * i}" for i in range(20)]
    (folder / "many.sim").write_text("\n".join(lines) + "\n")
    return folder / "many.sim"


def test_click_a_robot_among_twenty_and_follow_it_or_look_down(browser_context, folder):
    scene = twenty_robots(folder)
    with simulator_with_viewer(str(scene), cwd=folder) as (_, url):
        viewer = open_viewer(browser_context, url)
        page = viewer.page
        assert len(viewer.state("robotIds")) == 20
        assert viewer.state("sceneWarnings")["warnings"] == []
        assert viewer.state("expandedPanels") == [1]
        page.wait_for_function("() => window.eyesimViewer.robotScreenPosition(13) !== null")
        x, y = robot_screen_position(page, 13)
        page.mouse.click(x, y)
        page.wait_for_function("() => window.eyesimViewer.selectedRobot() === 13")
        assert viewer.state("expandedPanels") == [13]
        page.wait_for_function("() => document.querySelectorAll('.robot-label.selected').length === 1")
        label = page.locator(".robot-label.selected").bounding_box()
        x, y = robot_screen_position(page, 13)
        assert abs(label["x"] + label["width"] / 2 - x) < 15 and label["y"] < y  # robot 13's, above it
        assert robot_panel(page, 13).locator(".lcd").is_visible()
        assert not robot_panel(page, 1).locator(".lcd").is_visible()
        assert robot_panel(page, 20).locator(".robot-name").is_visible()
        screenshot(page, "twenty-robots")

        robot_panel(page, 4).locator(".robot-header").click()
        assert viewer.state("expandedPanels") == [4]

        page.locator("#view-mode").select_option("top")
        camera = viewer.state("cameraState")
        assert camera["mode"] == "top"
        assert camera["direction"][1] < -0.999  # straight down (three.js y is up)
        screenshot(page, "top-down")

        page.locator("#view-mode").select_option("follow")
        page.wait_for_function("() => window.eyesimViewer.cameraState().following === 4")
        page.wait_for_function(
            "() => { const c = window.eyesimViewer.cameraState(); "
            "const p = window.eyesimViewer.displayedRobotPose(4).pos; "
            "return Math.hypot(c.position[0] - p[0], c.position[2] + p[1]) < 1.1; }"
        )
        camera = viewer.state("cameraState")
        pose = viewer.state("displayedRobotPose", 4)["pos"]
        # Behind the robot and above it, at the follow distance.
        distance = math.dist(camera["position"], [pose[0], pose[2], -pose[1]])
        assert 1.0 < distance < 1.4 and camera["position"][1] > pose[2] + 0.5
        screenshot(page, "follow")
        robot_panel(page, 9).locator(".robot-header").click()
        page.wait_for_function("() => window.eyesimViewer.cameraState().following === 9")
        assert viewer.errors == []
