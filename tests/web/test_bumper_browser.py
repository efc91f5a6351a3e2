"""The bumper part in headless Chromium against the real simulator, with no line of the viewer or
the editors about it: with VIS the viewer draws a pressed strip (in the colour its component
gives), and the robot editor shows its settings from the robot schema, checks them and keeps them.

Screenshots go to $EYESIM_SCREENSHOTS when it is set (for looking at them)."""

import sys
from pathlib import Path

import pytest
from browser import open_viewer, save_screenshot

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from support.programs import simulator_with_viewer  # noqa: E402
from support.rooms import square_room, write_scene  # noqa: E402
from support.worlds import EXAMPLE_ROBOTS  # noqa: E402

pytestmark = pytest.mark.browser
SLOW = 60_000  # ms
FRONT = 90  # mm: the S4's front edge, where its front bumper sits
BUMPER_BOT = (EXAMPLE_ROBOTS / "S4.robi").read_text().replace("name S4", "name BumperBot") + (
    f"bumper 1 {FRONT} 0 0 140\nbumper 2 -{FRONT} 0 180 140\n"
)


@pytest.fixture
def room(tmp_path):
    """A 1 m room: a BumperBot whose program pushes it into the east wall, another standing free."""
    (tmp_path / "bumperbot.robi").write_text(BUMPER_BOT)
    (tmp_path / "push.py").write_text("from eye import *\nVWSetSpeed(100, 0)\nwhile True:\n    OSWait(100)\n")
    write_scene(
        tmp_path,
        square_room(1000),
        ["BumperBot 700 500 0 push.py", "BumperBot 300 600 0"],
        settings="VIS",
        extra=["robi bumperbot.robi"],
    )
    return tmp_path


def test_the_viewer_draws_the_pressed_bumper(browser_context, room):
    with simulator_with_viewer("scene.sim", cwd=room) as (_, url):
        viewer = open_viewer(browser_context, url)
        page = viewer.page
        page.wait_for_function("() => window.eyesimViewer.sensorRays().some(r => r.kind === 'bumper')", timeout=SLOW)
        rays = viewer.state("sensorRays")
        bumpers = [(r["robot"], r["id"], r["color"]) for r in rays if r["kind"] == "bumper"]
        assert bumpers == [(1, 1, [255, 143, 0])]  # robot 2 and robot 1's back strip are free
        # each robot's 4 PSD beams and the pressed strip's mark (6 lines from its top edge's middle)
        assert viewer.state("raySegments") == 2 * 4 + 6
        save_screenshot(page, "bumper-pressed")
        assert viewer.errors == []


def test_the_robot_editor_shows_checks_and_keeps_the_bumpers(browser_context, room):
    with simulator_with_viewer("scene.sim", cwd=room) as (_, url):
        page = browser_context.new_page()
        page.set_default_timeout(SLOW)
        errors: list[str] = []
        page.on("pageerror", lambda error: errors.append(str(error)))
        page.goto(f"{url.split('?')[0]}robot-editor.html?open=file:bumperbot.robi")
        page.wait_for_function(
            "() => window.eyesimRobotEditor && eyesimRobotEditor.checks() > 0 && eyesimRobotEditor.idle()"
        )
        assert page.locator('fieldset[data-pointer="/bumpers/1"]').count() == 1
        assert page.locator('[data-pointer="/bumpers/0/width"]').input_value() == "140"
        assert page.locator('[data-pointer="/bumpers/1/angle"]').input_value() == "180"

        def change(pointer: str, value: str) -> None:
            before = page.evaluate("eyesimRobotEditor.checks()")
            field = page.locator(f'[data-pointer="{pointer}"]')
            field.fill(value)
            field.press("Tab")
            page.wait_for_function("n => eyesimRobotEditor.checks() > n && eyesimRobotEditor.idle()", arg=before)

        change("/bumpers/0/width", "120")
        assert page.evaluate("eyesimRobotEditor.robot()")["bumpers"][0]["width"] == 120
        change("/bumpers/1/id", "1")  # the loader's own check: ids differ
        problem = page.locator('#problems li[data-pointer="/bumpers/1"]')
        assert "bumper id 1 is already used" in problem.inner_text()
        assert "invalid" in page.locator('fieldset[data-pointer="/bumpers/1"]').get_attribute("class")
        save_screenshot(page, "robot-editor-bumpers")
        assert errors == []
