"""The robot editor, polished, against the real simulator in headless Chromium: only the parts
the chosen drive can use are offered, PSD presets put a sensor on the chassis' edge facing out,
"Save as" follows the robot's name, and "Add to scene" places the robot in the running scene on
a free spot.

Screenshots go to $EYESIM_SCREENSHOTS when it is set (for looking at them)."""

import sys
from pathlib import Path

import pytest
from browser import open_viewer, save_screenshot

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from support.programs import simulator_with_viewer  # noqa: E402

from eyesim.scene import load_scene  # noqa: E402

pytestmark = pytest.mark.browser
SLOW = 60_000  # ms


@pytest.fixture
def room(tmp_path):
    """A 2 m room with an S4 on the spot where added robots are put first: the floor's centre."""
    (tmp_path / "room.wld").write_text("floor 2000 2000\n")
    (tmp_path / "room.sim").write_text("world room.wld\nS4 1000 1000 0\n")
    return tmp_path


def open_robot(page, base: str, source: str) -> None:
    page.goto(f"{base}robot-editor.html?open={source}")
    page.wait_for_function(
        "() => window.eyesimRobotEditor && eyesimRobotEditor.checks() > 0 && eyesimRobotEditor.idle()"
    )


def settled(page, before: int) -> None:
    page.wait_for_function("n => eyesimRobotEditor.checks() > n && eyesimRobotEditor.idle()", arg=before)


def checks(page) -> int:
    return page.evaluate("eyesimRobotEditor.checks()")


def offered(page) -> dict[str, bool]:
    """Which drive-dependent parts and values the form shows."""
    keys = ["wheels", "steering", "axis_offset", "thrusters", "buoyancy", "drag", "start_depth", "arm"]
    return {key: page.locator(f'[data-pointer="/{key}"]').count() > 0 for key in keys}


def choose_drive(page, drive: str) -> None:
    before = checks(page)
    page.select_option('select[data-pointer="/drive"]', drive)
    settled(page, before)


def test_parts_by_drive_psd_presets_file_name_and_add_to_scene(browser_context, room):
    with simulator_with_viewer("room.sim", cwd=room) as (_, url):
        base = url.split("?")[0]
        page = browser_context.new_page()
        page.set_default_timeout(SLOW)
        errors: list[str] = []
        page.on("pageerror", lambda error: errors.append(str(error)))

        # A differential robot: wheels, its axle, an arm (a mobile manipulator, as the Picker);
        # no thrusters, buoyancy or steering.
        open_robot(page, base, "builtin:S4")
        assert offered(page) == {
            "wheels": True,
            "steering": False,
            "axis_offset": True,
            "thrusters": False,
            "buoyancy": False,
            "drag": False,
            "start_depth": False,
            "arm": True,
        }
        save_screenshot(page, "robot-editor-parts-1-differential")
        # Another drive offers other parts; the S4's wheels stay shown while it has them (to be removed).
        choose_drive(page, "submarine")
        assert offered(page) == {
            "wheels": True,
            "steering": False,
            "axis_offset": False,
            "thrusters": True,
            "buoyancy": True,
            "drag": True,
            "start_depth": True,
            "arm": False,
        }
        choose_drive(page, "ackermann")
        assert offered(page)["steering"] and not offered(page)["thrusters"]
        choose_drive(page, "arm")
        assert offered(page) == {
            "wheels": True,
            "steering": False,
            "axis_offset": False,
            "thrusters": False,
            "buoyancy": False,
            "drag": False,
            "start_depth": False,
            "arm": True,
        }
        open_robot(page, base, "new:submarine")
        assert page.locator('[data-add="thrusters"]').count() == 1
        assert offered(page)["wheels"] is False and offered(page)["arm"] is False
        save_screenshot(page, "robot-editor-parts-2-submarine")

        # PSD presets: on the S4's chassis box (x -100..80, y -75..75 mm), facing out.
        open_robot(page, base, "builtin:S4")
        for index, preset, (x, y, heading) in (
            (0, "back", (-100, 0, 180)),
            (1, "left", (-10, 75, 90)),
            (2, "right", (-10, -75, -90)),
            (3, "front", (80, 0, 0)),
        ):
            before = checks(page)
            page.click(f'fieldset[data-pointer="/psds/{index}"] button[data-preset="{preset}"]')
            settled(page, before)
            psd = page.evaluate("i => eyesimRobotEditor.robot().psds[i]", index)
            assert (psd["x"], psd["y"], psd["heading"]) == (x, y, heading)
            assert page.input_value(f'[data-pointer="/psds/{index}/x"]') == str(x)
        preview = page.evaluate("eyesimRobotEditor.preview()")
        centre = preview["snapshot"]["robots"][0]["pos"]
        beams = {beam["id"]: beam for beam in preview["psds"]}
        back = beams[page.evaluate("eyesimRobotEditor.robot().psds[0].id")]
        assert back["origin"][:2] == pytest.approx([centre[0] - 0.1, centre[1]], abs=1e-4)
        assert back["direction"][:2] == pytest.approx([-1, 0], abs=1e-3)  # out of the back, not through the robot
        assert back["hit"] is None or back["hit"] > 0.05
        save_screenshot(page, "robot-editor-parts-3-psd-presets")

        # "Save as" follows the robot's name, until a name of one's own is typed.
        assert page.input_value("#save-path") == "S4.robi"
        before = checks(page)
        page.fill('[data-pointer="/name"]', "Scout 2")
        page.press('[data-pointer="/name"]', "Tab")
        settled(page, before)
        assert page.input_value("#save-path") == "Scout_2.robi"
        page.fill("#save-path", "scout.robi")
        before = checks(page)
        page.fill('[data-pointer="/name"]', "Scout")
        page.press('[data-pointer="/name"]', "Tab")
        settled(page, before)
        assert page.input_value("#save-path") == "scout.robi"

        # Add to scene: saved, then placed in the running scene clear of the S4 on the centre.
        page.click("#add-to-scene")
        page.wait_for_function("() => eyesimRobotEditor.added() === 1")
        status = page.inner_text("#editor-status")
        assert status.startswith("Added to the scene as robot 2 at (") and "clear of what was there" in status
        scene = page.evaluate("() => fetch('/scenes/state').then(r => r.json())")
        assert not scene["editing"]  # the scene runs on as it did
        first, added = scene["items"]["robots"]
        assert added["type"] == "Scout" and (first["x"], first["y"]) == (1000, 1000)
        assert abs(added["x"] - 1000) >= 180 or abs(added["y"] - 1000) >= 150
        assert (room / "scout.robi").is_file()
        assert errors == []

        viewer = open_viewer(browser_context, url)
        viewer.page.wait_for_function("() => window.eyesimViewer.robotIds().length === 2")
        save_screenshot(viewer.page, "robot-editor-parts-4-added-to-scene")
        assert viewer.errors == []
        # The scene as it runs now, saved, names the new robot file and loads without overlaps.
        saved = viewer.page.evaluate(
            "() => fetch('/scenes/save', {method: 'POST', body: JSON.stringify("
            "{root: 0, path: 'with_scout.sim', format: 'sim'})}).then(r => r.json())"
        )
        assert saved["saved"], saved
        again = load_scene(room / "with_scout.sim")
        assert [r.type_name for r in again.robots] == ["S4", "Scout"] and again.warnings == ()
