"""The robot editor in headless Chromium against the real simulator: build a robot with forms and
handles, test-drive it, save it, and run a C program on the saved robot in a scene."""

from __future__ import annotations

import math
import shutil
import subprocess
import sys
from pathlib import Path

import pytest
from support.scenes import arena
from support.viewer import viewer_simulation

import eyesim
from eyesim.scene import builtins

EXAMPLES = builtins.ROBOTS_DIR
SHOTS = Path(__file__).resolve().parents[2] / "build" / "screenshots"
READ_PSDS = r"""
#include <stdio.h>
#include "eyebot.h"
int main(void) {
    OSWait(100);
    printf("%d %d %d\n", PSDGet(1), PSDGet(2), PSDGet(3));
    return 0;
}
"""
DRIVE_1000 = r"""
#include "eyebot.h"
int main(void) {
    VWStraight(1000, 300);
    VWWait();
    return 0;
}
"""


@pytest.fixture
def editor(browser_context, tmp_path):
    """The robot editor page of a running simulator whose scene folder is `tmp_path`."""
    with viewer_simulation(arena(), root=tmp_path) as (sim, port, server):
        page = browser_context.new_page()
        errors: list[str] = []
        page.on("pageerror", lambda error: errors.append(str(error)))
        yield page, server, tmp_path
        page.close()
        assert not errors


def open_editor(page, server, source: str) -> None:
    page.goto(f"http://127.0.0.1:{server.port}/robot-editor.html?open={source}")
    settle(page)


def settle(page, checks_before: int = 0) -> None:
    """Waits until the editor has checked the robot as it stands now."""
    page.wait_for_function(
        "n => window.eyesimRobotEditor && eyesimRobotEditor.checks() > n && eyesimRobotEditor.idle()",
        arg=checks_before,
    )


def checks(page) -> int:
    return page.evaluate("eyesimRobotEditor.checks()")


def set_field(page, pointer: str, value) -> None:
    before = checks(page)
    field = page.locator(f'[data-pointer="{pointer}"]')
    if field.input_value() == str(value):
        return  # no change, nothing to check
    field.fill(str(value))
    field.press("Tab")
    settle(page, before)


def robot(page) -> dict:
    return page.evaluate("eyesimRobotEditor.robot()")


def shot(page, name: str) -> None:
    SHOTS.mkdir(parents=True, exist_ok=True)
    page.screenshot(path=str(SHOTS / f"robot-editor-{name}.png"))


def test_a_new_differential_robot_with_three_psds_and_a_camera_is_built_saved_and_read_by_a_c_program(editor):
    page, server, root = editor
    open_editor(page, server, "new:differential")
    assert robot(page)["drive"] == "differential"
    sensors = [("PSD_FRONT", 90, 0, 0), ("PSD_LEFT", 0, 75, 90), ("PSD_RIGHT", 0, -75, -90)]
    for index, (name, x, y, heading) in enumerate(sensors):
        before = checks(page)
        page.locator('button[data-add="psds"]').click()
        settle(page, before)
        for key, value in (("name", name), ("x", x), ("y", y), ("z", 40), ("heading", heading)):
            set_field(page, f"/psds/{index}/{key}", value)
    before = checks(page)
    page.locator('button[data-add="camera"]').click()
    settle(page, before)
    set_field(page, "/camera/x", 80)
    set_field(page, "/camera/z", 70)
    before = checks(page)
    page.locator('button[data-add="lidar"]').click()  # no required values: the scanner's defaults
    settle(page, before)
    set_field(page, "/lidar/points", 180)

    # A bad value: the loader's message at the field, and saving is off until it is fixed.
    set_field(page, "/mass", "-2")
    message = page.locator('[data-pointer="/mass"]').locator("xpath=..").locator(".field-message")
    assert message.inner_text() == "expected a number > 0, found -2"
    assert page.locator("#save").is_disabled()
    shot(page, "invalid-mass")
    set_field(page, "/mass", 0.7)
    assert not page.locator("#save").is_disabled()

    # The preview shows the built robot: three beams from where the PSDs are, the camera's frame.
    preview = page.evaluate("eyesimRobotEditor.preview()")
    origins = {beam["name"]: beam["origin"] for beam in preview["psds"]}
    centre = preview["snapshot"]["robots"][0]["pos"]
    assert origins["PSD_LEFT"] == pytest.approx([centre[0], centre[1] + 0.075, 0.04], abs=1e-4)
    assert preview["camera"]["position"] == pytest.approx([centre[0] + 0.08, centre[1], 0.07], abs=1e-4)
    assert preview["lidar"]["points"] == 180

    # A click on the right PSD's beam selects that PSD and its part of the form.
    beam = next(b for b in preview["psds"] if b["name"] == "PSD_RIGHT")
    on_beam = page.evaluate(
        "p => eyesimRobotEditor.screenOf(p)", [v + d * 0.2 for v, d in zip(beam["origin"], beam["direction"])]
    )
    page.mouse.click(on_beam["x"], on_beam["y"])
    assert page.locator("#selection").inner_text() == "Selected /psds/2"
    assert "selected" in page.locator('fieldset[data-pointer="/psds/2"]').get_attribute("class")

    # Select the front PSD and drag its handle: it moves on the robot, and the form follows.
    page.evaluate("eyesimRobotEditor.select('/psds/0')")
    start = page.evaluate("eyesimRobotEditor.handleAt('/psds/0', 'move')")
    page.mouse.move(start["x"], start["y"])
    page.mouse.down()
    target = page.evaluate("p => eyesimRobotEditor.screenOf(p)", [centre[0] + 0.09, centre[1] + 0.04, 0.04])
    before = checks(page)
    for step in range(1, 6):
        page.mouse.move(
            start["x"] + (target["x"] - start["x"]) * step / 5, start["y"] + (target["y"] - start["y"]) * step / 5
        )
    page.mouse.up()
    settle(page, before)
    moved = robot(page)["psds"][0]
    assert moved["x"] == pytest.approx(90, abs=4) and moved["y"] == pytest.approx(40, abs=4)
    assert page.locator('[data-pointer="/psds/0/y"]').input_value() == str(moved["y"]).removesuffix(".0")
    beam = page.evaluate("eyesimRobotEditor.preview()")["psds"][0]
    assert beam["origin"][1] - centre[1] == pytest.approx(moved["y"] / 1000, abs=1e-4)
    shot(page, "psd-moved")

    # Test drive: the arrow key drives it forward through VW; PSD read-outs follow.
    page.locator("#try").click()
    page.wait_for_function("() => eyesimRobotEditor.drive() !== null")
    page.locator("#preview").click(position={"x": 5, "y": 5})
    start_pose = page.evaluate("eyesimRobotEditor.drive().snapshot.robots[0].pos")
    page.keyboard.down("ArrowUp")
    page.wait_for_function(
        "x => eyesimRobotEditor.drive().snapshot.robots[0].pos[0] > x + 0.1", arg=start_pose[0], timeout=30_000
    )
    page.keyboard.up("ArrowUp")
    assert page.locator(".psd-readings .reading").count() == 3
    page.wait_for_function("() => eyesimRobotEditor.drive().readings.camera !== undefined")
    lidar = page.evaluate("eyesimRobotEditor.drive().readings.lidar")
    assert len(lidar) == 180 and min(lidar) < 2000  # the arena's walls are within reach
    shot(page, "test-drive")
    page.locator("#end-try").click()

    # Save: a .robi that `eyesim check` accepts.
    page.locator("#save-path").fill("Tri.robi")
    page.locator("#save").click()
    page.wait_for_function("() => document.querySelector('#editor-status').textContent.startsWith('Saved')")
    saved = root / "Tri.robi"
    check = subprocess.run([sys.executable, "-m", "eyesim", "check", str(saved)], capture_output=True, text=True)
    assert check.returncode == 0, check.stdout + check.stderr

    # Saving again asks first; saying no leaves the file as it was.
    text = saved.read_text()
    set_field(page, "/mass", 0.9)
    page.once("dialog", lambda dialog: dialog.dismiss())
    page.locator("#save").click()
    page.wait_for_function("() => document.querySelector('#editor-status').textContent.startsWith('Not saved')")
    assert saved.read_text() == text

    # In a scene, facing walls at known distances, a C program reads the three PSDs.
    (root / "psd.sim").write_text(
        "# walls at 400 mm ahead, 300 mm left, 500 mm right\nworld room.wld\nrobi Tri.robi\nTri 1000 600 0\n"
    )
    (root / "room.wld").write_text("floor 2000 2000\n1400 0 1400 2000\n0 900 2000 900\n0 100 2000 100\n")
    with eyesim.Simulation(root / "psd.sim") as sim:
        sim.c_program(1, READ_PSDS)
        sim.run(until=5)
        front, left, right = (int(v) for v in sim.robot(1).stdout.split())
    wall_thickness = 5  # half of a 10 mm wall
    x, y = moved["x"], moved["y"]
    assert front == pytest.approx(400 - x - wall_thickness, abs=3)
    assert left == pytest.approx(300 - 75 - wall_thickness, abs=3)
    assert right == pytest.approx(500 - 75 - wall_thickness, abs=3)
    assert math.isfinite(y)


def test_the_s4_with_bigger_wheels_still_drives_1000_mm_with_vwstraight(editor):
    page, server, root = editor
    open_editor(page, server, "builtin:S4")
    assert robot(page)["wheels"]["diameter"] == 54
    set_field(page, "/wheels/diameter", 80)
    page.locator("#save-path").fill("S4big.robi")
    page.locator("#save").click()
    page.wait_for_function("() => document.querySelector('#editor-status').textContent.startsWith('Saved')")
    shot(page, "s4-wheels")
    assert "wheel 80 " in (root / "S4big.robi").read_text()
    (root / "drive.sim").write_text("world room.wld\nrobi S4big.robi\nS4 300 1000 0\n")
    (root / "room.wld").write_text("floor 2000 2000\n")
    with eyesim.Simulation(root / "drive.sim") as sim:
        sim.c_program(1, DRIVE_1000)
        sim.run(until=20)
        assert sim.robot(1).exit_code == 0
        assert sim.robot(1).pose.x - 300 == pytest.approx(1000, abs=15)


def test_the_arm_on_a_base_moves_its_joints_with_sliders_in_the_test_drive(editor):
    page, server, root = editor
    shutil.copy(EXAMPLES / "Picker.robi", root / "Picker.robi")
    open_editor(page, server, "file:Picker.robi")
    assert [j["name"] for j in robot(page)["arm"]["joints"]] == ["BASE", "SHOULDER", "WRIST"]
    page.locator("#try").click()
    page.wait_for_function("() => eyesimRobotEditor.drive() !== null")
    shoulder = page.locator('input[type="range"][data-servo="2"]')
    assert page.locator('input[type="range"][data-servo]').count() == 4  # three joints and the gripper
    before = page.evaluate("eyesimRobotEditor.drive().snapshot.bodies")
    shoulder.fill("230")
    page.wait_for_function(
        """before => eyesimRobotEditor.drive().snapshot.bodies.some((body, i) =>
               Math.abs(body.pos[2] - before[i].pos[2]) > 0.02)""",
        arg=before,
        timeout=30_000,
    )
    shot(page, "arm-sliders")
    page.locator("#end-try").click()


def test_paths_outside_the_scene_folder_are_refused(editor):
    page, server, root = editor
    open_editor(page, server, "builtin:LabBot")
    for path in ("../out.robi", "/tmp/out.robi"):
        page.locator("#save-path").fill(path)
        page.locator("#save").click()
        page.wait_for_function("() => document.querySelector('#editor-status').classList.contains('error')")
        assert "scene folder" in page.locator("#editor-status").inner_text()
        page.evaluate("document.querySelector('#editor-status').classList.remove('error')")
    assert not (root.parent / "out.robi").exists()


def test_a_part_the_schema_gains_appears_in_the_editor_without_editor_code(editor, monkeypatch):
    """The forms come from the published schema alone: a part added to it gets its section, its
    fields with their units, and the loader's checks."""
    from eyesim.scene import json_format

    published = json_format.schema("robot")
    extended = {
        **published,
        "properties": {**published["properties"], "sonar": {"$ref": "#/$defs/sonar"}},
        "$defs": {
            **published["$defs"],
            "sonar": {
                "type": "object",
                "description": "an ultrasonic range finder",
                "required": ["range"],
                "additionalProperties": False,
                "properties": {"range": {"type": "number", "exclusiveMinimum": 0, "description": "mm"}},
            },
        },
    }
    monkeypatch.setattr(json_format, "schema", lambda kind: extended if kind == "robot" else published)
    page, server, _ = editor
    open_editor(page, server, "builtin:S4")
    section = page.locator('section[data-pointer="/sonar"]')
    assert "an ultrasonic range finder" in section.inner_text()
    before = checks(page)
    section.locator('button[data-add="sonar"]').click()
    settle(page, before)
    assert robot(page)["sonar"] == {"range": 1}
    set_field(page, "/sonar/range", 0)
    row = page.locator('[data-pointer="/sonar/range"]').locator("xpath=..")
    assert row.locator(".field-unit").inner_text() == "mm"
    assert row.locator(".field-message").inner_text() == "expected a number > 0, found 0"


def test_the_viewer_links_to_the_editor(editor, browser_context):
    page, server, _ = editor
    page.goto(f"http://127.0.0.1:{server.port}/")
    with browser_context.expect_page() as opened:
        page.locator("#robot-editor-link").click()
    tab = opened.value
    tab.wait_for_function("() => window.eyesimRobotEditor && eyesimRobotEditor.checks() > 0")
    assert tab.evaluate("eyesimRobotEditor.robot().name") == "S4"  # the editor starts from the S4
    tab.close()
