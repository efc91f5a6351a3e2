"""The scene editor, deeper, against the real simulator in headless Chromium: the property
inspector (a wall's ends, thickness, height and colour; a robot's pose), snapping while dragging
(grid, angle; Alt drags free), a robot dropped on another robot or into a wall moved clear with a
message, a saved file that loads back without `overlap` warnings, and one recording for a run
however much is edited in it.

Screenshots go to $EYESIM_SCREENSHOTS when it is set (for looking at them)."""

import signal
import sys
from pathlib import Path

import pytest
from browser import open_viewer, save_screenshot

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from support.programs import simulator_with_viewer  # noqa: E402

from eyesim.record.recording import Recording  # noqa: E402
from eyesim.scene import load_scene  # noqa: E402

pytestmark = pytest.mark.browser
SLOW = 60_000  # ms: worlds rebuilt on every edit, on a loaded 2-core machine
GRAB = (30, 20)  # mm from a robot's centre where the mouse takes it (on its top, seen from above)


@pytest.fixture
def room(tmp_path):
    """A 2 m room split by a wall along y = 1000, two S4s below it."""
    (tmp_path / "room.wld").write_text("floor 2000 2000\n0 1000 2000 1000\n")
    (tmp_path / "room.sim").write_text("world room.wld\nS4 500 500 0\nS4 1500 500 0\n")
    return tmp_path


def state(page) -> dict:
    return page.evaluate("() => window.eyesimEditor.current")


def edits(page) -> int:
    return page.evaluate("() => window.eyesimEditor.editCount")


def wait_for_edits(page, count: int) -> None:
    page.wait_for_function("n => window.eyesimEditor.editCount >= n", arg=count)


def screen_of(page, x_mm: float, y_mm: float) -> tuple[float, float]:
    point = page.evaluate("([x, y]) => window.eyesimViewer.worldScreenPosition(x, y, 0)", [x_mm / 1000, y_mm / 1000])
    return point["x"], point["y"]


def drag_robot(page, index: int, to: tuple[float, float], modifier: str | None = None) -> dict:
    """Drags robot `index` (0-based) so that its centre goes to `to` (mm), holding `modifier`; the
    robot as the editor has it after the drop."""
    count = edits(page)
    robot = state(page)["items"]["robots"][index]
    page.wait_for_function(
        "([id, x]) => Math.abs((window.eyesimViewer.displayedRobotPose(id)?.pos[0] ?? -1) - x) < 0.002",
        arg=[index + 1, robot["x"] / 1000],
    )
    start = screen_of(page, robot["x"] + GRAB[0], robot["y"] + GRAB[1])
    end = screen_of(page, to[0] + GRAB[0], to[1] + GRAB[1])
    if modifier:
        page.keyboard.down(modifier)
    page.mouse.move(*start)
    page.mouse.down()
    page.mouse.move(*end, steps=6)
    page.mouse.up()
    if modifier:
        page.keyboard.up(modifier)
    wait_for_edits(page, count + 1)
    return state(page)["items"]["robots"][index]


def set_snap(page, grid: int) -> None:
    page.fill("#editor-grid", str(grid))
    page.locator("#editor-grid").dispatch_event("change")


def test_inspector_snapping_moved_clear_clean_save_and_one_recording(browser_context, room):
    with simulator_with_viewer("room.sim", "--record", "run.mcap", cwd=room) as (process, url):
        viewer = open_viewer(browser_context, url)
        page = viewer.page
        page.set_default_timeout(SLOW)
        page.select_option("#view-mode", "top")
        page.wait_for_function("() => window.eyesimViewer.status()?.time > 0.2")
        page.click("#edit-scene")
        page.wait_for_selector("#editor:not([hidden])")
        page.wait_for_function("() => document.querySelectorAll('#editor-robot-type option').length > 1")
        assert page.input_value("#editor-grid") == "10" and page.input_value("#editor-angle") == "15"
        assert page.is_checked("#editor-snap")

        # The inspector: the wall's ends, size and colour, applied to the scene.
        page.click("#editor-items li[data-kind=wall][data-index='0']")
        assert page.is_visible("#editor-thickness") and page.is_visible("#editor-color")
        assert not page.is_visible("#editor-phi")
        assert (
            page.input_value("#editor-thickness"),
            page.input_value("#editor-height"),
            page.input_value("#editor-color"),
        ) == ("10", "300", "#c8c8c8")
        assert page.inner_text("#editor-length") == "length 2000"
        page.fill("#editor-x2", "1600")
        page.fill("#editor-thickness", "40")
        page.fill("#editor-height", "120")
        page.fill("#editor-color", "#10c820")
        count = edits(page)
        page.click("#editor-apply")
        wait_for_edits(page, count + 1)
        assert state(page)["items"]["walls"] == [
            {"x1": 0, "y1": 1000, "x2": 1600, "y2": 1000, "thickness": 40, "height": 120, "color": [16, 200, 32]}
        ]
        assert page.inner_text("#editor-length") == "length 1600"
        # a robot: its pose in numbers; its size and colour are its type's: the floor it takes is shown
        page.click("#editor-items li[data-kind=robot][data-index='1']")
        assert not page.is_visible("#editor-thickness") and not page.is_visible("#editor-color")
        assert page.inner_text("#editor-footprint") == "180 × 150 mm"
        page.fill("#editor-phi", "90")
        page.click("#editor-apply")
        wait_for_edits(page, count + 2)
        assert state(page)["items"]["robots"][1]["phi"] == 90
        save_screenshot(page, "scene-inspector-1-wall")

        # Snapping: on a 250 mm grid the robot lands on it; Alt drags it free; Shift turns by 15°.
        set_snap(page, 250)
        robot = drag_robot(page, 0, (1130, 640))
        assert (robot["x"], robot["y"]) == (1250, 750)
        robot = drag_robot(page, 0, (640, 610), "Alt")
        assert abs(robot["x"] - 640) < 30 and abs(robot["y"] - 610) < 30 and robot["x"] % 250 != 0
        set_snap(page, 10)
        count = edits(page)
        start = screen_of(page, robot["x"] + GRAB[0], robot["y"] + GRAB[1])
        page.keyboard.down("Shift")
        page.mouse.move(*start)
        page.mouse.down()
        page.mouse.move(start[0] + 37, start[1], steps=5)  # 37 px: 37° free, 30° on the 15° steps
        page.mouse.up()
        page.keyboard.up("Shift")
        wait_for_edits(page, count + 1)
        assert state(page)["items"]["robots"][0]["phi"] == -30

        # Dropped on robot 2: robot 1 moves clear, robot 2 stays, the page says so.
        robot = drag_robot(page, 0, (1490, 520))
        other = state(page)["items"]["robots"][1]
        assert (other["x"], other["y"]) == (1500, 500)
        assert abs(robot["x"] - 1500) > 100 or abs(robot["y"] - 500) > 80
        message = page.inner_text("#editor-message")
        assert "Robot 1 (S4) overlapped robot 'S4': moved to" in message, message
        page.wait_for_function(
            "([x, y]) => { const p = window.eyesimViewer.displayedRobotPose(1)?.pos;"
            " return p && Math.abs(p[0] - x) < 0.002 && Math.abs(p[1] - y) < 0.002; }",
            arg=[robot["x"] / 1000, robot["y"] / 1000],
        )
        save_screenshot(page, "scene-inspector-2-moved-clear")
        # Into the wall: robot 2 comes out on the side it was dropped on.
        robot = drag_robot(page, 1, (1000, 990))
        assert robot["x"] == 1000 and robot["y"] < 1000 - 20 - 75
        assert "Robot 2 (S4) overlapped the wall from (0, 1000) to (1600, 1000)" in page.inner_text("#editor-message")

        # More edits of every kind: a wall drawn, undone, redone; the floor.
        count = edits(page)
        page.click("#editor-draw-wall")
        a, b = screen_of(page, 200, 1500), screen_of(page, 800, 1500)
        page.mouse.move(*a)
        page.mouse.down()
        page.mouse.move(*b, steps=4)
        page.mouse.up()
        wait_for_edits(page, count + 1)
        page.click("#editor-draw-wall")
        assert len(state(page)["items"]["walls"]) == 2
        page.click("#editor-undo")
        wait_for_edits(page, count + 2)
        page.click("#editor-redo")
        wait_for_edits(page, count + 3)
        page.fill("#editor-floor-width", "2500")
        page.click("#editor-set-floor")
        wait_for_edits(page, count + 4)
        edited = state(page)["items"]

        # Saved, the scene loads back without an overlap warning, as the editor showed it.
        page.click("#editor-save")
        page.fill("#save-name", "saved.sim")
        page.click("#save-confirm")
        wait_for_edits(page, count + 5)
        page.wait_for_function("() => document.querySelector('#scene-name').textContent === 'saved.sim'")
        saved = load_scene(room / "saved.sim")
        assert [d.code for d in saved.warnings] == []
        assert [(r.pose.x, r.pose.y, r.pose.phi) for r in saved.robots] == [
            (r["x"], r["y"], r["phi"]) for r in edited["robots"]
        ]
        wall = saved.world.walls[0]
        assert (wall.x2, wall.thickness, wall.height, wall.color) == (1600, 40, 120, (16, 200, 32))
        save_screenshot(page, "scene-inspector-3-saved")

        # Done: the run goes on, into the same recording.
        page.click("#edit-scene")
        page.wait_for_selector("#editor", state="hidden")
        time = page.evaluate("() => window.eyesimViewer.status().time")
        page.wait_for_function("t => window.eyesimViewer.status().time > t + 0.3", arg=time)
        assert viewer.errors == []
        process.send_signal(signal.SIGINT)
        assert process.wait(timeout=30) == 128 + signal.SIGINT
    assert sorted(p.name for p in room.glob("*.mcap")) == ["run.mcap"]
    with Recording(room / "run.mcap") as recording:
        assert len(recording.segments) >= 10  # the scene as it started, then one for each edit
        end = recording.snapshot_at(recording.end_us)["robots"]
        assert len(end) == 2
        for recorded, placed in zip(end, edited["robots"]):  # standing where they were put, give or take a mm
            assert abs(recorded["pos"][0] * 1000 - placed["x"]) < 2 and abs(recorded["pos"][1] * 1000 - placed["y"]) < 2


def test_a_drop_with_no_free_place_near_it_is_refused_and_the_object_goes_back(browser_context, tmp_path):
    """A can dropped into the middle of a block of S4s 10 mm apart (no room for it within five of
    its sizes): refused with the reason, and the can is back where it was."""
    robots = "".join(f"S4 {600 + 190 * i} {500 + 160 * j} 0\n" for i in range(5) for j in range(6))
    (tmp_path / "block.sim").write_text(f"{robots}Can 1700 1700 0\n")
    with simulator_with_viewer("block.sim", cwd=tmp_path) as (_, url):
        viewer = open_viewer(browser_context, url)
        page = viewer.page
        page.set_default_timeout(SLOW)
        page.select_option("#view-mode", "top")
        page.click("#edit-scene")
        page.wait_for_selector("#editor:not([hidden])")
        page.wait_for_function("() => window.eyesimEditor.current?.editing")
        count = edits(page)
        start, end = screen_of(page, 1700 + 10, 1700 + 10), screen_of(page, 970 + 10, 900 + 10)
        page.mouse.move(*start)
        page.mouse.down()
        page.mouse.move(*end, steps=6)
        # the physics has the can in the block while the button is down
        page.wait_for_function("() => Math.abs((window.eyesimViewer.objectPose(1)?.pos[0] ?? 0) - 0.97) < 0.01")
        page.mouse.up()
        wait_for_edits(page, count + 1)
        message = page.inner_text("#editor-message")
        assert (
            "object 'Can' at (970, 900) overlaps robot 'S4' and there is no free place within 5 of its sizes" in message
        ), message
        assert state(page)["items"]["objects"][0]["x"] == 1700
        page.wait_for_function(
            "() => { const p = window.eyesimViewer.objectPose(1)?.pos;"
            " return p && Math.abs(p[0] - 1.7) < 0.002 && Math.abs(p[1] - 1.7) < 0.002; }"
        )
        save_screenshot(page, "scene-inspector-4-refused")
        assert viewer.errors == []
