"""Dragging robots and objects with the mouse, scene warnings and the controls help, in headless
Chromium against the real simulator with a real C program."""

import math
import sys
from pathlib import Path

import pytest
from browser import open_viewer, soft_key

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from support.programs import build, simulator_with_viewer  # noqa: E402

pytestmark = pytest.mark.browser


@pytest.fixture(scope="module")
def simulator(tmp_path_factory):
    folder = tmp_path_factory.mktemp("interaction")
    program = build("report_pose", folder)
    (folder / "room.wld").write_text(
        "floor 2000 2000\nwobble 3\n0 0 2000 0\n2000 0 2000 2000\n2000 2000 0 2000\n0 2000 0 0\n"
    )
    (folder / "room.sim").write_text("world room.wld\nS4 500 500 0\nCan 1500 1500 0\n")
    with simulator_with_viewer(str(folder / "room.sim"), "--program", f"1={program}", cwd=folder) as (_, url):
        yield url


def _yaw(quat) -> float:
    w, x, y, z = quat
    return math.atan2(2 * (w * z + x * y), 1 - 2 * (y * y + z * z))


def _drag(viewer, start: dict, end: dict, shift: bool = False) -> None:
    mouse = viewer.page.mouse
    mouse.move(start["x"], start["y"])
    if shift:
        viewer.page.keyboard.down("Shift")
    mouse.down()
    assert viewer.state("dragging") is not None  # the press caught something
    mouse.move(end["x"], end["y"], steps=8)
    mouse.up()
    if shift:
        viewer.page.keyboard.up("Shift")


def test_dragging_moves_the_true_pose_while_paused_and_odometry_does_not_notice(browser_context, simulator):
    viewer = open_viewer(browser_context, simulator)
    page = viewer.page
    page.wait_for_function(
        "() => window.eyesimViewer.robotPose(1) !== null && window.eyesimViewer.objectPose(1) !== null"
    )
    page.click("#pause")
    page.wait_for_function("() => window.eyesimViewer.status()?.paused === true")
    paused_at = viewer.state("status")["time"]
    corner = viewer.state("worldScreenPosition", 0, 0, 0)

    _drag(viewer, viewer.state("worldScreenPosition", 0.5, 0.5, 0), viewer.state("worldScreenPosition", 1.2, 0.9, 0))
    assert viewer.state("dragging") is None
    page.wait_for_function("""() => { const p = window.eyesimViewer.robotPose(1).pos;
                                      return Math.hypot(p[0] - 1.2, p[1] - 0.9) < 0.01; }""")
    assert viewer.state("worldScreenPosition", 0, 0, 0) == corner  # the camera did not orbit meanwhile

    # Shift+drag 90 pixels to the right turns it 90 degrees clockwise, where it is.
    at = viewer.state("worldScreenPosition", 1.2, 0.9, 0)
    _drag(viewer, at, {"x": at["x"] + 90, "y": at["y"]}, shift=True)
    page.wait_for_function("""() => { const q = window.eyesimViewer.robotPose(1).quat;
                                      return Math.abs(Math.atan2(2 * (q[0] * q[3] + q[1] * q[2]),
                                                                 1 - 2 * (q[2] * q[2] + q[3] * q[3])) + Math.PI / 2) < 0.02; }""")
    pose = viewer.state("robotPose", 1)
    assert math.hypot(pose["pos"][0] - 1.2, pose["pos"][1] - 0.9) < 0.01

    can = viewer.state("objectPose", 1)["pos"]
    _drag(
        viewer, viewer.state("worldScreenPosition", can[0], can[1], 0), viewer.state("worldScreenPosition", 0.6, 1.5, 0)
    )
    page.wait_for_function("""() => { const p = window.eyesimViewer.objectPose(1).pos;
                                      return Math.hypot(p[0] - 0.6, p[1] - 1.5) < 0.01; }""")
    status = viewer.state("status")
    assert status["paused"] and status["time"] == paused_at  # all of it while time stood still

    # Dragging on the empty floor orbits the camera as before.
    mouse = page.mouse
    mouse.move(corner["x"] + 40, corner["y"] - 40)
    mouse.down()
    assert viewer.state("dragging") is None
    mouse.move(corner["x"] + 140, corner["y"] - 40, steps=5)
    mouse.up()
    page.wait_for_function(
        "c => { const p = window.eyesimViewer.worldScreenPosition(0, 0, 0); return Math.abs(p.x - c.x) > 5; }",
        arg=corner,
    )

    page.click("#pause")  # resume: the program reads the poses after KEY1
    soft_key(page, 1, 1).click()
    page.wait_for_function("() => window.eyesimViewer.programState(1)?.event === 'exited'", timeout=20_000)
    lines = dict(line.split(" ", 1) for line in viewer.state("consoleText", 1).splitlines())
    x, y, phi = map(int, lines["true"].split())
    assert abs(x - 1200) <= 10 and abs(y - 900) <= 10 and abs(phi - -90) <= 1
    assert lines["odometry"] == "0 0 0"
    x, y, _ = map(int, lines["object"].split())
    assert abs(x - 600) <= 10 and abs(y - 1500) <= 10
    assert viewer.errors == []


def test_scene_warnings_and_the_controls_help_show(browser_context, simulator):
    viewer = open_viewer(browser_context, simulator)
    page = viewer.page
    badge = page.locator(".warnings-badge")
    assert badge.inner_text() == "⚠ 1 scene warning"
    (warning,) = viewer.state("sceneWarnings")["warnings"]
    assert warning["file"].endswith("room.wld") and warning["line"] == 2
    assert not page.locator(".warnings-list").is_visible()
    badge.click()
    listed = page.locator(".warnings-list li")
    assert listed.count() == 1 and listed.first.is_visible()
    assert listed.first.inner_text().startswith("room.wld:2 unknown keyword 'wobble'")

    assert not viewer.state("helpVisible")
    page.keyboard.press("?")
    help_panel = page.locator(".help-panel")
    assert help_panel.is_visible() and "Shift+drag a robot or object" in help_panel.inner_text()
    page.locator(".help-button").click()
    assert not viewer.state("helpVisible") and not help_panel.is_visible()
    assert viewer.errors == []
