"""The viewer in headless Chromium against a fake simulator: scene, motion, LCD, keys, console, toolbar."""

from __future__ import annotations

import io
import math
import time

import pytest
from browser import (
    TIMEOUT_MS,
    launch_browser,
    lcd_image,
    open_viewer,
    read_lcd_pixels,
    robot_panel,
    robot_screen_position,
    soft_key,
    wait_for_lcd,
)
from fake_viewer_server import (
    CONSOLE_LINES,
    LCD_MARKS,
    MENU_LABELS,
    ROBOT_ID,
    ROBOT_NAME,
    FakeViewerServer,
    lcd_png,
    robot_info,
    robot_pose,
    scene_message,
)
from PIL import Image, ImageChops

pytestmark = pytest.mark.browser


def console(text: str, stream: str = "stdout", robot: int = ROBOT_ID) -> dict:
    return {"type": "console", "robot": robot, "stream": stream, "text": text}


def is_key(robot: int, key: int):
    return lambda command: command == {"type": "key", "robot": robot, "key": key}


def key_commands(server: FakeViewerServer) -> list[dict]:
    return [c for c in server.commands if isinstance(c, dict) and c.get("type") == "key"]


def heading(quat: list[float]) -> float:
    w, x, y, z = quat
    return math.atan2(2 * (w * z + x * y), 1 - 2 * (y * y + z * z))


def angle_between(a: float, b: float) -> float:
    return abs(math.remainder(a - b, math.tau))


def test_page_loads_and_connects(viewer):
    page = viewer.page
    assert viewer.state("connectionState") == "open"
    assert viewer.state("webglActive") is True
    assert page.locator("#connection").text_content() == "connected"
    assert page.locator("canvas.world-canvas").is_visible()
    assert page.locator("#pause").is_enabled()
    assert viewer.errors == []


def test_scene_builds(viewer):
    assert viewer.state("scene") == {
        "robots": 1,
        "walls": 4,
        "objects": 2,
        "markers": 1,
        "floor": {"width": 2, "height": 1.5},
    }
    assert viewer.state("robotIds") == [ROBOT_ID]
    assert robot_panel(viewer.page, ROBOT_ID).locator(".robot-name").text_content() == ROBOT_NAME
    # labelled with its id and the program it runs (the fake server says demo.py started)
    assert viewer.page.locator(".world-labels .robot-label").all_text_contents() == [f"{ROBOT_ID} · demo.py"]


def test_robot_pose_follows_snapshots(viewer):
    first = viewer.state("robotPose", ROBOT_ID)
    pos, quat = robot_pose(first["time"])
    assert first["pos"] == pytest.approx(pos, abs=1e-12)
    assert first["quat"] == pytest.approx(quat, abs=1e-12)

    viewer.page.wait_for_function(f"() => window.eyesimViewer.robotPose({ROBOT_ID}).time > {first['time'] + 0.2}")
    later = viewer.state("robotPose", ROBOT_ID)
    assert later["time"] > first["time"]
    assert later["pos"] != first["pos"]

    # What is drawn lies on the robot's circle, facing along it, a little behind the newest pose
    # (never ahead: no extrapolation). Both are read at the same moment.
    shown, newest = viewer.page.evaluate(
        "robot => [window.eyesimViewer.displayedRobotPose(robot), window.eyesimViewer.robotPose(robot)]",
        ROBOT_ID,
    )
    x, y, z = shown["pos"]
    assert math.hypot(x - 1.0, y - 0.75) == pytest.approx(0.4, abs=1e-3)
    assert z == pytest.approx(0.0)
    shown_angle = math.atan2(y - 0.75, x - 1.0)
    assert angle_between(heading(shown["quat"]), shown_angle + math.pi / 2) < 1e-3
    lag = math.remainder(0.5 * newest["time"] - shown_angle, math.tau)
    assert -1e-6 <= lag < 0.5 * 0.6, "at most ~0.6 s behind at 0.5 rad/s"

    # ... and on the canvas, where the debug handle says.
    screen_x, screen_y = robot_screen_position(viewer.page, ROBOT_ID)
    canvas = viewer.page.locator("canvas.world-canvas").bounding_box()
    assert canvas["x"] < screen_x < canvas["x"] + canvas["width"]
    assert canvas["y"] < screen_y < canvas["y"] + canvas["height"]


def test_lcd_shows_the_png_pixel_for_pixel(viewer):
    wait_for_lcd(viewer.page, ROBOT_ID)
    sent = Image.open(io.BytesIO(lcd_png())).convert("RGB")

    decoded = read_lcd_pixels(viewer.page, ROBOT_ID)
    assert decoded.size == (480, 320)
    assert ImageChops.difference(decoded, sent).getbbox() is None
    for xy, rgb in LCD_MARKS.items():
        assert decoded.getpixel(xy) == rgb

    # At 1:1 on screen, too: the page shows exactly the pixels sent.
    image = lcd_image(viewer.page, ROBOT_ID)
    box = image.bounding_box()
    assert (box["width"], box["height"]) == (480, 320)
    on_screen = Image.open(io.BytesIO(image.screenshot())).convert("RGB")
    assert ImageChops.difference(on_screen, sent).getbbox() is None


def test_menu_labels_show_on_the_buttons(viewer):
    viewer.page.wait_for_function(f"() => window.eyesimViewer.menuLabels({ROBOT_ID})[0] !== ''")
    assert viewer.state("menuLabels", ROBOT_ID) == MENU_LABELS
    labels = robot_panel(viewer.page, ROBOT_ID).locator(".soft-key-label").all_text_contents()
    assert labels == MENU_LABELS
    names = robot_panel(viewer.page, ROBOT_ID).locator(".soft-key-name").all_text_contents()
    assert names == ["KEY1", "KEY2", "KEY3", "KEY4"]


def test_soft_key_buttons_send_keys(viewer, fake_server):
    soft_key(viewer.page, ROBOT_ID, 1).click()
    fake_server.wait_for_command(is_key(ROBOT_ID, 1))
    soft_key(viewer.page, ROBOT_ID, 2).click()  # an empty label is still a key
    fake_server.wait_for_command(is_key(ROBOT_ID, 2))
    assert key_commands(fake_server) == [
        {"type": "key", "robot": ROBOT_ID, "key": 1},
        {"type": "key", "robot": ROBOT_ID, "key": 2},
    ]


def test_clicking_the_lcd_menu_bar_presses_that_quarters_key(viewer, fake_server):
    image = lcd_image(viewer.page, ROBOT_ID)
    image.click(position={"x": 100, "y": 150})  # above the menu bar: not a key
    image.click(position={"x": 300, "y": 300})  # third quarter of the bar
    fake_server.wait_for_command(is_key(ROBOT_ID, 4))
    image.click(position={"x": 470, "y": 319})  # fourth quarter, bottom-right pixel
    fake_server.wait_for_command(is_key(ROBOT_ID, 8))
    assert [c["key"] for c in key_commands(fake_server)] == [4, 8]


def test_console_and_program_state(viewer, fake_server):
    page = viewer.page
    expected = "".join(CONSOLE_LINES)
    page.wait_for_function(f"() => window.eyesimViewer.consoleText({ROBOT_ID}) === {expected!r}")
    state = robot_panel(page, ROBOT_ID).locator(".program-state")
    assert state.text_content() == "running demo.py"
    running = {"event": "started", "name": "demo.py", "exit_code": None}
    assert viewer.state("programState", ROBOT_ID) == running

    fake_server.send(console("Traceback: oops\n", stream="stderr"))
    exited = {"type": "program", "robot": ROBOT_ID, "event": "exited", "name": "demo.py", "exit_code": 3}
    fake_server.send(exited)
    page.wait_for_function(f"() => window.eyesimViewer.programState({ROBOT_ID})?.event === 'exited'")
    assert state.text_content() == "demo.py exited with code 3"
    assert viewer.state("consoleText", ROBOT_ID) == expected + "Traceback: oops\n"
    assert robot_panel(page, ROBOT_ID).locator(".console .stderr").text_content() == "Traceback: oops\n"


def test_console_keeps_only_recent_output(viewer, fake_server):
    for i in range(12):
        fake_server.send(console(f"{i:02d}" * 2500))
    viewer.page.wait_for_function(f"() => window.eyesimViewer.consoleText({ROBOT_ID}).endsWith('11')")
    text = viewer.state("consoleText", ROBOT_ID)
    assert len(text) <= 50_000
    assert text.endswith("11" * 2500)
    assert "00" not in text


def test_pause_resume_speed_and_reset_send_commands(viewer, fake_server):
    page = viewer.page
    page.click("#pause")
    fake_server.wait_for_command(lambda c: c == {"type": "pause"})
    page.wait_for_function("() => document.querySelector('#pause').textContent === 'Resume'")
    assert viewer.state("status")["paused"] is True

    page.click("#pause")
    fake_server.wait_for_command(lambda c: c == {"type": "resume"})
    page.wait_for_function("() => document.querySelector('#pause').textContent === 'Pause'")

    page.select_option("#speed", "2")
    fake_server.wait_for_command(lambda c: c == {"type": "speed", "value": 2})
    page.wait_for_function("() => window.eyesimViewer.status().speed === 2")

    page.click("#reset")
    fake_server.wait_for_command(lambda c: c == {"type": "reset"})


def test_status_shows_time_rate_and_a_speed_not_in_the_list(viewer, fake_server):
    page = viewer.page
    fake_server.periodic_status = False
    status = {"type": "status", "time": 12.5, "paused": False, "speed": "max", "clock": "deterministic"}
    fake_server.send({**status, "real_time_factor": 7.25})
    page.wait_for_function("() => window.eyesimViewer.status().speed === 'max'")
    assert page.locator("#sim-time").text_content() == "t = 12.50 s"
    assert page.locator("#real-time-factor").text_content() == "7.25× real time"
    assert page.locator("#clock").text_content() == "deterministic"
    assert page.locator("#speed").input_value() == "max"


def test_malformed_and_unknown_messages_are_ignored(viewer, fake_server):
    before = viewer.state("ignoredMessages")
    junk = [
        "not json",
        "[1, 2]",
        {"type": "mystery", "robot": ROBOT_ID},
        {"type": "snapshot", "time": 1, "robots": "everywhere"},
        {"type": "lcd", "robot": ROBOT_ID, "png": "not base64!"},
        {"type": "menu", "robot": ROBOT_ID, "labels": ["only one"]},
        {"type": "scene", "floor": {"width": -1, "height": 1}, "walls": [], "robots": []},
        {"type": "status", "time": "soon"},
    ]
    for message in junk:
        fake_server.send(message)
    # One bad wall is skipped; the rest of the scene still builds.
    scene = scene_message(walls=5)
    scene["walls"][4]["height"] = "tall"
    fake_server.send(scene)
    # Messages for a robot the scene does not have are dropped quietly.
    fake_server.send(console("lost\n", robot=99))
    fake_server.send(console("still alive\n"))

    viewer.page.wait_for_function(
        "robot => window.eyesimViewer.consoleText(robot).endsWith('still alive\\n')", arg=ROBOT_ID
    )
    assert viewer.state("ignoredMessages") - before == len(junk)
    assert viewer.state("scene")["walls"] == 4
    assert viewer.state("menuLabels", ROBOT_ID) == MENU_LABELS
    assert viewer.state("connectionState") == "open"
    assert viewer.errors == []


def test_a_new_scene_rebuilds_the_world_and_the_panels(viewer, fake_server):
    page = viewer.page
    page.wait_for_function(f"() => window.eyesimViewer.consoleText({ROBOT_ID}) !== ''")
    console_before = viewer.state("consoleText", ROBOT_ID)
    fake_server.send(scene_message(robots=[robot_info(), robot_info(2, "Explorer")], walls=6))
    page.wait_for_function("() => window.eyesimViewer.scene().walls === 6")
    assert viewer.state("scene")["robots"] == 2
    assert viewer.state("robotIds") == [ROBOT_ID, 2]
    assert page.locator(".robot-panel").count() == 2
    assert robot_panel(page, 2).locator(".robot-name").text_content() == "Explorer"
    assert viewer.state("consoleText", ROBOT_ID).startswith(console_before), "robot 1 keeps its console"

    fake_server.send(scene_message())
    page.wait_for_function("() => window.eyesimViewer.scene().robots === 1")
    assert page.locator(".robot-panel").count() == 1
    # name labels are placed by the next drawn frame (the view draws on demand)
    page.wait_for_function("() => document.querySelectorAll('.world-labels .robot-label').length === 1")
    assert page.locator(".world-labels .robot-label").count() == 1


def test_reconnects_when_the_simulator_goes_away(viewer, fake_server):
    page = viewer.page
    fake_server.drop_connections()
    page.wait_for_function("() => window.eyesimViewer.connections() === 2", timeout=TIMEOUT_MS)
    assert fake_server.connections == 2
    assert viewer.state("connectionState") == "open"
    assert page.locator("#connection").text_content() == "connected"
    soft_key(page, ROBOT_ID, 3).click()
    fake_server.wait_for_command(is_key(ROBOT_ID, 4))


def test_floor_texture_is_loaded(browser_context):
    with FakeViewerServer(texture=True) as server:
        viewer = open_viewer(browser_context, server.url)
        try:
            deadline = time.monotonic() + 5
            while server.texture_requests == 0 and time.monotonic() < deadline:
                time.sleep(0.05)
            assert server.texture_requests == 1
            assert viewer.errors == []
        finally:
            viewer.page.close()


def test_panels_work_without_webgl(playwright, fake_server):
    with launch_browser(webgl=False, playwright=playwright) as context:
        viewer = open_viewer(context, fake_server.url)
        page = viewer.page
        assert viewer.state("webglActive") is False
        assert "3D view unavailable" in page.locator(".world-notice").text_content()
        assert page.locator("canvas").count() == 0
        assert robot_screen_position(page, ROBOT_ID) is None

        wait_for_lcd(page, ROBOT_ID)
        sent = Image.open(io.BytesIO(lcd_png())).convert("RGB")
        assert ImageChops.difference(read_lcd_pixels(page, ROBOT_ID), sent).getbbox() is None
        soft_key(page, ROBOT_ID, 1).click()
        fake_server.wait_for_command(is_key(ROBOT_ID, 1))
        page.wait_for_function(f"() => window.eyesimViewer.consoleText({ROBOT_ID}) !== ''")
        page.wait_for_function(f"() => window.eyesimViewer.displayedRobotPose({ROBOT_ID}) !== null")
        assert viewer.errors == []
