"""Opening another scene from the page, against the real simulator in headless Chromium: the new
scene's floor image shows (also after a reload), the robot panels start afresh (status, console,
camera image, program choice), robots are labelled with their id and program, the toolbar names
the scene; and editing a recorded run keeps one recording, which replays the edited scene.

Screenshots go to $EYESIM_SCREENSHOTS when it is set (for looking at them)."""

import base64
import io
import os
import re
import signal
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from browser import open_viewer, robot_panel, save_screenshot
from PIL import Image, ImageDraw

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from support.programs import eyesim_command, simulator_with_viewer  # noqa: E402

from eyesim.record.recording import Recording  # noqa: E402

pytestmark = pytest.mark.browser
SLOW = 60_000  # ms: programs starting, worlds built, on a loaded 2-core machine

RED = (200, 40, 40)
BLUE = (40, 70, 200)
# A tribot that takes pictures and talks; a car that says one thing.
TRIBOT = """from eye import *
CAMInit(QQVGA)
print("tribot says hello", flush=True)
while True:
    CAMGet()
    OSWait(50)
"""
CAR = """from eye import *
print("car ready", flush=True)
while True:
    OSWait(100)
"""
LONG_AGO = 1_600_000_000  # the images' modification time: a browser keeps such files for long


def floor_image(path: Path, colour: tuple, markings: bool) -> None:
    image = Image.new("RGB", (256, 256), colour)
    if markings:  # road markings: a dashed white centre line
        draw = ImageDraw.Draw(image)
        for y in range(0, 256, 32):
            draw.rectangle([124, y, 132, y + 18], fill=(255, 255, 255))
    image.save(path)
    os.utime(path, (LONG_AGO, LONG_AGO))


@pytest.fixture
def scenes(tmp_path):
    floor_image(tmp_path / "grass.png", RED, markings=False)
    floor_image(tmp_path / "road.png", BLUE, markings=True)
    (tmp_path / "lab.wld").write_text("floor 2000 2000\nfloor_texture grass.png\n")
    (tmp_path / "street.wld").write_text("floor 2000 2000\nfloor_texture road.png\n")
    (tmp_path / "tribot.py").write_text(TRIBOT)
    (tmp_path / "car.py").write_text(CAR)
    (tmp_path / "lab.sim").write_text("world lab.wld\nS4 400 400 0 tribot.py\n")
    (tmp_path / "street.sim").write_text("world street.wld\nCar 400 400 0 car.py\n")
    return tmp_path


def floor_colour(page) -> tuple[float, float, float]:
    """The mean colour of the middle of the 3D view (the floor, seen from above)."""
    data = page.evaluate("() => window.eyesimViewer.screenshot()")
    image = Image.open(io.BytesIO(base64.b64decode(data.split(",", 1)[1]))).convert("RGB")
    width, height = image.size
    middle = image.crop((int(width * 0.4), int(height * 0.4), int(width * 0.6), int(height * 0.6)))
    return tuple(np.asarray(middle, dtype=float).reshape(-1, 3).mean(axis=0))


def floor_is(page, blue: bool) -> None:
    """Once the floor image has loaded, the floor looks blue (the road) or red (the grass)."""
    page.wait_for_function(
        "() => window.eyesimViewer.webglActive() && window.eyesimViewer.floorTexture().loaded", timeout=SLOW
    )
    r, _, b = floor_colour(page)
    assert (b > r + 40) if blue else (r > b + 40), (blue, (r, b))


def open_scene(page, name: str) -> None:
    page.click("#open-scenes")
    page.wait_for_selector("#scene-browser[open]")
    page.fill("#scene-search", name)
    page.wait_for_function(
        """name => {
        const buttons = document.querySelectorAll('#scene-files button');
        return buttons.length === 1 && buttons[0].textContent.endsWith(name);
    }""",
        arg=name,
    )
    page.click("#scene-files button")
    page.wait_for_selector("#scene-browser", state="hidden", timeout=60_000)


def test_another_scene_shows_its_own_floor_and_starts_the_panels_afresh(browser_context, scenes):
    with simulator_with_viewer("lab.sim", cwd=scenes) as (_, url):
        viewer = open_viewer(browser_context, url)
        page = viewer.page
        page.set_default_timeout(SLOW)
        page.select_option("#view-mode", "top")
        floor_is(page, blue=False)
        assert page.inner_text("#scene-name") == "lab.sim"
        # The tribot runs, talks and takes pictures.
        page.wait_for_function(
            "() => window.eyesimViewer.consoleText(1).includes('tribot says hello') && "
            "window.eyesimViewer.cameraImages(1) > 0",
            timeout=SLOW,
        )
        panel = robot_panel(page, 1)
        page.wait_for_function("() => window.eyesimViewer.robotLabels()[1] === '1 · tribot.py'", timeout=SLOW)
        page.wait_for_function(
            "() => document.querySelector('.program-choice').value.endsWith('tribot.py')", timeout=SLOW
        )
        save_screenshot(page, "scene-switch-1-lab")

        open_scene(page, "street.sim")
        page.wait_for_function("() => window.eyesimViewer.consoleText(1).includes('car ready')", timeout=SLOW)
        assert page.inner_text("#scene-name") == "street.sim"
        # Nothing of the tribot's: its output, its last picture, its state, its program.
        assert "tribot" not in viewer.state("consoleText", 1)
        assert viewer.state("cameraImages", 1) == 0 and panel.locator(".camera-view").is_hidden()
        assert panel.locator(".program-state").text_content() == "running car.py"
        page.wait_for_function("() => document.querySelector('.program-choice').value.endsWith('car.py')", timeout=SLOW)
        page.wait_for_function("() => window.eyesimViewer.robotLabels()[1] === '1 · car.py'", timeout=SLOW)
        assert "Car" in panel.locator(".robot-type").text_content()
        floor_is(page, blue=True)
        save_screenshot(page, "scene-switch-2-street")

        # A reload shows the road too (the browser's cache has the lab's image under another URL).
        page.reload()
        page.wait_for_function(
            "() => window.eyesimViewer?.connectionState() === 'open' && window.eyesimViewer.scene().floor !== null",
            timeout=SLOW,
        )
        page.select_option("#view-mode", "top")
        floor_is(page, blue=True)
        assert viewer.errors == []


def test_editing_a_recorded_run_keeps_one_recording_that_replays_the_edits(browser_context, scenes):
    """One editing session (several edits) and the run after it: one .mcap file, whose replay shows
    the scene as it was before the edits and as they left it."""
    (scenes / "lab.sim").write_text("world lab.wld\nS4 400 400 0\n")
    with simulator_with_viewer("lab.sim", "--record", "run.mcap", cwd=scenes) as (process, url):
        page = open_viewer(browser_context, url).page
        page.set_default_timeout(SLOW)
        page.wait_for_function("() => window.eyesimViewer.status()?.time > 0.3", timeout=SLOW)
        page.click("#edit-scene")
        page.wait_for_selector("#editor:not([hidden])", timeout=SLOW)
        page.wait_for_function("() => document.querySelectorAll('#editor-robot-type option').length > 1", timeout=SLOW)
        for count, x in ((2, "800"), (3, "1200")):  # two robots added, each moved: four edits
            page.select_option("#editor-robot-type", "S4")
            page.click("#editor-add-robot")
            page.wait_for_function(
                "n => window.eyesimEditor.current.items.robots.length === n", arg=count, timeout=SLOW
            )
            page.click(f"#editor-items li[data-kind=robot][data-index='{count - 1}']")
            page.fill("#editor-x", x)
            page.fill("#editor-y", "1500")
            page.click("#editor-apply")
            page.wait_for_function(
                "([n, x]) => window.eyesimEditor.current.items.robots[n - 1].x === Number(x)",
                arg=[count, x],
                timeout=SLOW,
            )
        page.click("#edit-scene")  # done: the run goes on
        page.wait_for_selector("#editor", state="hidden", timeout=SLOW)
        edited_at = page.evaluate("() => window.eyesimViewer.status().time")
        page.wait_for_function("t => window.eyesimViewer.status().time > t + 0.5", arg=edited_at, timeout=SLOW)
        process.send_signal(signal.SIGINT)  # the run ends: the recording is finished
        assert process.wait(timeout=30) == 128 + signal.SIGINT
    assert sorted(p.name for p in scenes.glob("*.mcap")) == ["run.mcap"]
    with Recording(scenes / "run.mcap") as recording:
        assert [s.robot_ids for s in recording.segments][0] == [1]
        assert recording.segments[-1].robot_ids == [1, 2, 3]
        last = recording.segment_at(recording.end_us)
        assert [round(r["pos"][0], 2) for r in recording.snapshot_at(recording.end_us)["robots"]] == [0.4, 0.8, 1.2]
        assert recording.end_us > last.start_us + 400_000
        start_us = recording.start_us

    # The replay: one robot before the edits, three after them.
    replay = subprocess.Popen(
        eyesim_command("replay", "run.mcap", "--viewer-port", "0"),
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        cwd=scenes,
    )
    try:
        url = re.search(r"(http://\S+)", replay.stdout.readline()).group(1)
        viewer = open_viewer(browser_context, url)
        page = viewer.page
        page.set_default_timeout(SLOW)
        assert viewer.state("robotIds") == [1] and viewer.state("timeline")["start"] == start_us / 1e6
        page.locator("#tl-scrub").fill("10000")  # the end
        page.wait_for_function(
            "() => window.eyesimViewer.robotIds().length === 3 && window.eyesimViewer.robotPose(3) !== null",
            timeout=SLOW,
        )
        assert round(viewer.state("robotPose", 3)["pos"][0], 2) == 1.2
        save_screenshot(page, "scene-switch-3-replay-after-edits")
        page.locator("#tl-scrub").fill("0")
        page.wait_for_function("() => window.eyesimViewer.robotIds().length === 1")
        assert viewer.errors == []
    finally:
        replay.terminate()
        replay.wait(timeout=10)
