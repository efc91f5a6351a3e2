"""Live controls that do what they say, against the real simulator in headless Chromium: Step ›
while paused runs one physics step (Shift: 10 ms), Record video records the live 3D view, the
controls are off while the simulator is away, Reset view brings the camera back, and an LCD stays
480x320 when its program takes camera images.

Screenshots go to $EYESIM_SCREENSHOTS when it is set (for looking at them)."""

import base64
import sys
from pathlib import Path

import pytest
from browser import open_viewer, robot_panel, save_screenshot

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from support.programs import simulator_with_viewer  # noqa: E402

pytestmark = pytest.mark.browser
SLOW = 60_000  # ms: programs starting, worlds built, on a loaded 2-core machine

DRIVE = """from eye import *
VWSetSpeed(300, 0)
while True:
    OSWait(100)
"""
CAMERA = """from eye import *
CAMInit(QVGA)
LCDMenu("A", "B", "C", "END")
frames = 0
while True:
    CAMGet()
    frames += 1
    LCDSetPrintf(0, 0, "frames %d", frames)
"""
STEP_S = 0.002  # the physics step


@pytest.fixture
def folder(tmp_path):
    (tmp_path / "drive.py").write_text(DRIVE)
    (tmp_path / "camera.py").write_text(CAMERA)
    (tmp_path / "lab.sim").write_text("S4 500 1000 0 drive.py\nS4 500 400 0 camera.py\n")
    return tmp_path


def status(page) -> dict:
    return page.evaluate("() => window.eyesimViewer.status()")


def wait_for_status(page, condition: str, arg=None) -> dict:
    page.wait_for_function(f"a => {{ const s = window.eyesimViewer.status(); return s && ({condition}); }}", arg=arg)
    return status(page)


def test_step_while_paused_runs_one_physics_step(browser_context, folder):
    with simulator_with_viewer("lab.sim", cwd=folder) as (_, url):
        viewer = open_viewer(browser_context, url)
        page = viewer.page
        page.set_default_timeout(SLOW)
        page.wait_for_function("() => (window.eyesimViewer.robotPose(1)?.pos[0] ?? 0) > 0.55")  # it drives
        page.click("#pause")
        paused = wait_for_status(page, "s.paused")
        # Paused: time and the robot stand still (a later status says the same).
        page.wait_for_function("t => window.eyesimViewer.robotPose(1)?.time === t", arg=paused["time"])
        x0 = viewer.state("robotPose", 1)["pos"][0]
        assert page.locator("#tl-forward").is_enabled()

        page.click("#tl-forward")
        stepped = wait_for_status(page, "s.paused && s.time > a", paused["time"])
        assert stepped["time"] == pytest.approx(paused["time"] + STEP_S, abs=1e-9)
        assert viewer.state("timeline")["mode"] == "live"  # the simulation moved on, the page follows it
        page.wait_for_function("t => window.eyesimViewer.robotPose(1)?.time >= t", arg=stepped["time"])
        x1 = viewer.state("robotPose", 1)["pos"][0]
        assert 0 < x1 - x0 < 0.01  # 2 ms at 0.3 m/s: under a millimetre

        page.click("#tl-forward", modifiers=["Shift"])  # 10 ms
        longer = wait_for_status(page, "s.paused && s.time > a", stepped["time"])
        assert longer["time"] == pytest.approx(stepped["time"] + 0.010, abs=1e-9)
        assert page.locator("#pause").text_content() == "Resume"
        assert viewer.errors == []


def test_record_video_records_the_live_3d_view(browser_context, folder):
    with simulator_with_viewer("lab.sim", cwd=folder) as (_, url):
        viewer = open_viewer(browser_context, url)
        page = viewer.page
        page.set_default_timeout(SLOW)
        button = page.locator("#tl-video")
        assert button.is_visible() and button.is_enabled()
        with page.expect_download() as download:
            button.click()
            assert button.text_content() == "Stop video"
            start = status(page)["time"]
            wait_for_status(page, "s.time > a + 1", start)  # a second of the robots driving
            button.click()
        assert button.text_content() == "Record video"
        assert download.value.suggested_filename.startswith("eyesim-video-t")
        page.wait_for_function("() => window.eyesimViewer.lastVideoSize() > 1000")
        video = base64.b64decode(page.evaluate("() => window.eyesimViewer.lastVideo()"))
        assert video[:4] == b"\x1a\x45\xdf\xa3"  # WebM (Matroska)
        assert viewer.state("timeline")["mode"] == "live"
        assert viewer.errors == []


def test_controls_are_off_while_the_simulator_is_away(browser_context, folder):
    with simulator_with_viewer("lab.sim", cwd=folder) as (process, url):
        viewer = open_viewer(browser_context, url)
        page = viewer.page
        page.set_default_timeout(SLOW)
        page.wait_for_selector("#edit-scene:not([hidden])")
        page.wait_for_function("() => !document.querySelector('.program-restart').disabled")
        page.locator(".robot-io summary").first.click()
        controls = [
            "#pause",
            "#speed",
            "#reset",
            "#tl-back",
            "#tl-play",
            "#tl-forward",
            "#tl-scrub",
            "#open-scenes",
            "#edit-scene",
            ".soft-key",
            ".program-restart",
            ".program-choice",
            ".ir-button",
            ".serial-input",
            ".analog-channel input",
        ]
        for selector in controls:
            assert page.locator(selector).first.is_enabled(), selector
        process.terminate()
        process.wait(timeout=10)
        page.wait_for_function("() => window.eyesimViewer.connectionState() === 'closed'")
        off = [s for s in controls if page.locator(s).first.is_disabled()]
        assert off == controls
        assert page.locator("#connection").text_content() == "disconnected, reconnecting…"
        save_screenshot(page, "live-controls-disconnected")


def test_reset_view_brings_the_camera_back(browser_context, folder):
    with simulator_with_viewer("lab.sim", cwd=folder) as (_, url):
        viewer = open_viewer(browser_context, url)
        page = viewer.page
        page.set_default_timeout(SLOW)
        page.wait_for_function("() => window.eyesimViewer.webglActive()")
        start = viewer.state("cameraState")
        box = page.locator("#world canvas").first.bounding_box()
        corner = (box["x"] + 30, box["y"] + box["height"] - 30)  # off the floor's middle, where the robots are
        page.mouse.move(*corner)
        page.mouse.down()
        page.mouse.move(corner[0] + 200, corner[1] - 80, steps=8)  # orbit
        page.mouse.up()
        page.mouse.wheel(0, -400)  # and zoom in
        page.wait_for_function(
            "p => window.eyesimViewer.cameraState().position.some((v, i) => Math.abs(v - p[i]) > 0.05)",
            arg=start["position"],
        )
        page.select_option("#view-mode", "follow")
        page.click("#reset-view")
        back = viewer.state("cameraState")
        assert back["mode"] == "free" and page.locator("#view-mode").input_value() == "free"
        assert back["position"] == pytest.approx(start["position"], abs=1e-6)
        assert back["direction"] == pytest.approx(start["direction"], abs=1e-6)


@pytest.mark.parametrize("size", [{"width": 1024, "height": 700}, {"width": 1400, "height": 900}])
def test_the_lcd_stays_480_by_320_beside_camera_images(browser_context, folder, size):
    with simulator_with_viewer("lab.sim", cwd=folder) as (_, url):
        viewer = open_viewer(browser_context, url)
        page = viewer.page
        page.set_default_timeout(SLOW)
        page.set_viewport_size(size)
        page.locator(".robot-panel[data-robot='2'] .robot-header").click()
        page.wait_for_function("() => window.eyesimViewer.cameraImages(2) > 1 && window.eyesimViewer.lcdUpdates(2) > 1")
        panel = robot_panel(page, 2)
        lcd = panel.locator("img.lcd-image").bounding_box()
        assert (lcd["width"], lcd["height"]) == (480, 320)
        camera = panel.locator("img.camera-image").bounding_box()
        assert camera["width"] > 100 and camera["y"] >= lcd["y"] + lcd["height"]  # under it, not squeezing it
        assert "320 x 240" in panel.locator(".camera-caption").text_content()
        save_screenshot(page, f"live-controls-camera-{size['width']}")
        assert viewer.errors == []
