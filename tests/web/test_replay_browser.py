"""`eyesim replay` in headless Chromium: scrub a recording of a real C program to a time and see the
recorded pose, LCD, console and path; plot signals, picked from the list or by clicking a robot or a
PSD beam; screenshots and a WebM video. And a live run scrubbed back over its recent history."""

from __future__ import annotations

import base64
import io
import re
import subprocess
import sys
from pathlib import Path

import imageio_ffmpeg
import numpy as np
import pytest
from browser import WORLD_VIEW_SIZED, open_viewer, read_lcd_pixels
from PIL import Image

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from support.programs import build, eyesim_command, simulator_with_viewer  # noqa: E402
from support.recordings import record_tour  # noqa: E402

from eyesim.paths import DATA_DIR
from eyesim.record import Recording

pytestmark = pytest.mark.browser


@pytest.fixture(scope="module")
def tour(tmp_path_factory):
    return record_tour(tmp_path_factory.mktemp("replay"), robots=2)


@pytest.fixture
def replay(tour):
    process = subprocess.Popen(
        eyesim_command("replay", str(tour), "--viewer-port", "0"),
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )
    try:
        match = re.search(r"(http://\S+)", process.stdout.readline())
        assert match, process.stderr.read()
        yield match.group(1)
    finally:
        process.terminate()
        process.wait(timeout=10)


def scrub_to(page, seconds: float, exact: bool = True) -> None:
    """Drags the timeline's slider to `seconds` (as near as its steps allow) and waits for its frame,
    whose snapshot is at that very time (`exact`, a recording) or the last one before it (live history)."""
    frames = page.evaluate("() => window.eyesimViewer.framesShown()")
    page.evaluate(
        """t => {
        const slider = document.querySelector('#tl-scrub');
        const { start, end } = window.eyesimViewer.timeline();
        slider.value = String(Math.round((t - start) / (end - start) * Number(slider.max)));
        slider.dispatchEvent(new Event('input'));
    }""",
        seconds,
    )
    page.wait_for_function(
        """([t, frames, exact]) => Math.abs(window.eyesimViewer.timeline().time - t) < 0.001 &&
        window.eyesimViewer.framesShown() > frames &&
        (!exact || Math.abs(window.eyesimViewer.robotPose(1).time - window.eyesimViewer.timeline().time) < 1e-6)""",
        arg=[seconds, frames, exact],
    )


def psd_beams(page) -> list[dict]:
    """The PSD beams drawn now: robot, psd and the beam's start (the sensor) and end on the page (CSS px)."""
    return page.evaluate("""() => window.eyesimViewer.sensorRays().filter(r => r.kind === 'psd').map(r => ({
        robot: r.robot, psd: r.psd,
        start: window.eyesimViewer.worldScreenPosition(...r.origin),
        end: window.eyesimViewer.worldScreenPosition(...r.ends)}))""")


def segment_distance(point: np.ndarray, start: np.ndarray, end: np.ndarray) -> float:
    along = end - start
    t = np.clip(np.dot(point - start, along) / max(np.dot(along, along), 1e-9), 0, 1)
    return float(np.linalg.norm(start + t * along - point))


STANDING_STILL = """() => {
    const pose = window.eyesimViewer.robotPose(1), last = window.lastPlace;
    if (!last || Math.hypot(...pose.pos.map((v, i) => v - last.pos[i])) > 1e-4) window.lastPlace = pose;
    return pose.time - window.lastPlace.time >= 0.2;
}"""  # robot 1 has moved under 0.1 mm for 0.2 s of simulation time


def click_beside_psd_beam(page, robot: int, psd: int, beside: float = 4.0) -> None:
    """Clicks `beside` pixels off the drawn beam of the robot's PSD, at a point of its outer part
    that is at least 12 px from every other PSD beam (so only this one can be meant)."""
    beams = psd_beams(page)
    corner = lambda p: np.array([p["x"], p["y"]])  # noqa: E731
    target = next(b for b in beams if b["robot"] == robot and b["psd"] == psd)
    start, end = corner(target["start"]), corner(target["end"])
    others = [(corner(b["start"]), corner(b["end"])) for b in beams if b is not target]
    normal = np.array([start[1] - end[1], end[0] - start[0]]) / np.linalg.norm(end - start)
    for fraction in np.linspace(0.2, 0.95, 31):
        point = start + fraction * (end - start) + beside * normal
        if all(segment_distance(point, a, b) > 12 for a, b in others):
            page.mouse.click(*point)
            return
    raise AssertionError(f"robot {robot}'s PSD {psd} beam runs too near other beams to click")


def decoded(png_base64: str) -> np.ndarray:
    return np.asarray(Image.open(io.BytesIO(base64.b64decode(png_base64))).convert("RGB"))


def test_scrubbing_shows_the_recorded_pose_lcd_console_and_path(browser_context, replay, tour):
    viewer = open_viewer(browser_context, replay)
    page = viewer.page
    page.wait_for_function("() => window.eyesimViewer.framesShown() >= 1")
    assert viewer.state("timeline")["mode"] == "replay"
    with Recording(tour) as recording:
        for seconds in (1.3, 0.6):  # forward, then back
            scrub_to(page, seconds)
            shown = viewer.state("timeline")["time"]
            at = round(shown * 1e6)
            expected = recording.snapshot_at(at)["robots"][0]
            received = viewer.state("robotPose", 1)
            assert received["pos"] == expected["pos"] and received["quat"] == expected["quat"]
            lcd_at = recording.image_time(1, "lcd", at)
            page.wait_for_function("() => window.eyesimViewer.lcdUpdates(1) >= 1")
            lcd = np.asarray(read_lcd_pixels(page, 1))
            assert np.array_equal(lcd, decoded(recording.image(1, "lcd", lcd_at)["data"]))
        # In realtime the program starts when the machine lets it (0.1-0.3 s): one or two steps by 0.7 s
        assert viewer.state("consoleText", 1) in ("step 1\n", "step 1\nstep 2\n")
        halfway = viewer.state("tracePoints", 1)
        scrub_to(page, recording.end_us / 1e6)
        assert viewer.state("consoleText", 1).endswith("done\n")
        assert viewer.state("programState", 1) == {"event": "exited", "name": "record_tour", "exit_code": 0}
        assert 10 < halfway < viewer.state("tracePoints", 1)
    page.screenshot(path=str(tour.parent / "replay-page.png"))
    assert viewer.errors == []
    page.close()


def test_plots_show_signals_picked_from_the_list_and_by_clicking_a_robot(browser_context, replay):
    viewer = open_viewer(browser_context, replay)
    page = viewer.page
    page.click("#plots-toggle")
    page.check("input[data-signal='robot/1/psd.1']")
    page.wait_for_function("() => window.eyesimViewer.plotted().length === 1")
    assert viewer.state("plotted") == [{"id": "robot/1/psd.1", "points": 4}]
    assert page.locator(".plot-chart canvas").count() == 1
    page.wait_for_function(WORLD_VIEW_SIZED)
    where = viewer.state("robotScreenPosition", 2)
    page.mouse.click(where["x"], where["y"])
    page.wait_for_function("() => window.eyesimViewer.plotted().length === 4")
    assert [p["id"] for p in viewer.state("plotted")] == ["robot/1/psd.1", "robot/2/x", "robot/2/y", "robot/2/psd.1"]
    assert viewer.state("timeline")["mode"] == "replay"  # the click picked, it did not move anything
    assert viewer.errors == []
    page.close()


def test_clicking_a_psd_beam_or_its_sensor_plots_that_psds_readings(browser_context, replay, tour):
    viewer = open_viewer(browser_context, replay)
    page = viewer.page
    page.click("#plots-toggle")
    scrub_to(page, 0.6)
    page.wait_for_function("() => window.eyesimViewer.sensorRays().length === 12")  # 3 robots' 4 PSDs
    page.wait_for_function(WORLD_VIEW_SIZED)
    shown = viewer.state("timeline")
    click_beside_psd_beam(page, robot=2, psd=1)
    page.wait_for_function("() => window.eyesimViewer.plotted().length === 1")
    assert viewer.state("plotted") == [{"id": "robot/2/psd.1", "points": 4}]  # the PSD, not robot 2's x and y

    sensor = next(b for b in psd_beams(page) if b["robot"] == 1 and b["psd"] == 1)["start"]
    page.mouse.click(sensor["x"], sensor["y"])  # where the sensor sits on the robot
    page.wait_for_function("() => window.eyesimViewer.plotted().length === 2")
    assert [p["id"] for p in viewer.state("plotted")] == ["robot/2/psd.1", "robot/1/psd.1"]

    click_beside_psd_beam(page, robot=1, psd=2)  # PSD_LEFT: record_tour never reads it
    page.wait_for_function("() => window.eyesimViewer.plotNotice() !== ''")
    assert viewer.state("plotNotice") == "Robot 1's PSD 2 has no readings: its program has not read it."
    assert len(viewer.state("plotted")) == 2
    assert viewer.state("timeline") == shown  # the clicks picked, they did not move anything
    page.screenshot(path=str(tour.parent / "psd-click.png"))
    assert viewer.errors == []
    page.close()


def test_clicking_a_psd_beam_in_a_live_run_plots_it_without_moving_the_robot(browser_context, tmp_path):
    program = build("record_tour", tmp_path)
    scene = tmp_path / "vis.sim"
    scene.write_text(f"world {DATA_DIR / 'scenes' / 'arena.wld'}\nsettings VIS\nS4 500 500 0\n")
    with simulator_with_viewer(str(scene), "--program", f"1={program}", cwd=tmp_path) as (_, url):
        viewer = open_viewer(browser_context, url)
        page = viewer.page
        page.click("#plots-toggle")
        page.wait_for_function("() => window.eyesimViewer.consoleText(1).includes('done')", timeout=20_000)
        page.wait_for_function(WORLD_VIEW_SIZED)
        page.wait_for_function(STANDING_STILL)  # it may coast a little after its last VWSetSpeed
        pose = viewer.state("robotPose", 1)["pos"]
        click_beside_psd_beam(page, robot=1, psd=1)
        page.wait_for_function("() => window.eyesimViewer.plotted().length === 1")
        assert viewer.state("plotted") == [{"id": "robot/1/psd.1", "points": 4}]
        assert viewer.state("dragging") is None  # a press on the beam did not grab the robot under it
        assert np.allclose(viewer.state("robotPose", 1)["pos"], pose, atol=1e-3)  # nor move it
        assert viewer.state("timeline")["mode"] == "live"
        assert viewer.errors == []
        page.close()


def test_screenshots_and_a_webm_video_of_the_replay(browser_context, replay, tour, tmp_path):
    viewer = open_viewer(browser_context, replay)
    page = viewer.page
    page.wait_for_function("() => window.eyesimViewer.framesShown() >= 1 && window.eyesimViewer.lcdUpdates(1) >= 1")
    with page.expect_download() as shot:
        page.click("#shot-3d")
    canvas = page.locator(".world-canvas").bounding_box()
    picture = Image.open(shot.value.path())
    assert picture.format == "PNG" and abs(picture.width - canvas["width"]) <= 1
    with page.expect_download() as lcd:
        page.locator('.robot-panel[data-robot="1"] .save-lcd').click()
    assert Image.open(lcd.value.path()).size == (480, 320)

    with page.expect_download(timeout=30_000) as video:
        page.click("#tl-video")  # plays the whole recording once, recording the 3D view
    assert viewer.state("timeline")["time"] == viewer.state("timeline")["end"]
    path = tmp_path / "replay.webm"
    path.write_bytes(Path(video.value.path()).read_bytes())
    assert path.stat().st_size == viewer.state("lastVideoSize")
    frames, seconds = imageio_ffmpeg.count_frames_and_secs(str(path))
    size = next(imageio_ffmpeg.read_frames(str(path)))["size"]
    assert frames >= 5 and 1.0 < seconds < 4.0  # the 2 s recording played at 1x
    assert abs(size[0] - canvas["width"]) <= 1 and abs(size[1] - canvas["height"]) <= 1
    assert viewer.errors == []
    page.close()


def test_a_live_run_can_be_scrubbed_back_and_then_follows_the_present_again(browser_context, tmp_path):
    program = build("record_tour", tmp_path)
    with simulator_with_viewer("--program", f"1={program}", cwd=tmp_path) as (_, url):
        viewer = open_viewer(browser_context, url)
        page = viewer.page
        page.wait_for_function("() => window.eyesimViewer.consoleText(1).includes('done')", timeout=20_000)
        assert viewer.state("timeline")["mode"] == "live"
        page.click("#tl-play")  # "Look back"
        scrub_to(page, 0.7, exact=False)
        assert viewer.state("timeline")["mode"] == "review"
        # In realtime the program starts when the machine lets it (0.1-0.3 s): one or two steps by 0.7 s
        assert viewer.state("consoleText", 1) in ("step 1\n", "step 1\nstep 2\n")
        assert abs(viewer.state("robotPose", 1)["time"] - 0.7) < 0.05
        page.click("#plots-toggle")
        page.check("input[data-signal='robot/1/odometry.x']")
        page.wait_for_function("() => (window.eyesimViewer.plotted()[0]?.points ?? 0) > 30")
        page.click("#tl-live")
        page.wait_for_function(
            "() => window.eyesimViewer.timeline().mode === 'live' && "
            "window.eyesimViewer.consoleText(1).endsWith('done\\n') && "
            "window.eyesimViewer.robotPose(1).time > 2"
        )
        assert viewer.errors == []
        page.close()


def test_another_recording_can_be_opened_from_the_page(browser_context, replay, tmp_path):
    from eyesim.core.clock import DETERMINISTIC, Clock
    from eyesim.core.engine import Simulation
    from eyesim.record import Recorder
    from eyesim.scene import DEFAULT_SCENE, load_scene

    sim = Simulation(load_scene(DEFAULT_SCENE), Clock(DETERMINISTIC))  # one robot, half a second
    with Recorder(sim, tmp_path / "arena.mcap"):
        sim.run(until=0.5)
    (tmp_path / "notes.mcap").write_text("time_s,robot\n")
    viewer = open_viewer(browser_context, replay)
    page = viewer.page
    page.wait_for_function("() => window.eyesimViewer.framesShown() >= 1")
    assert viewer.state("robotIds") == [1, 2, 3]
    page.set_input_files("#tl-file", str(tmp_path / "notes.mcap"))
    page.wait_for_function("() => window.eyesimViewer.uploadStatus().includes('not an MCAP file')")
    assert viewer.state("timeline")["end"] > 2  # still the tour
    page.set_input_files("#tl-file", str(tmp_path / "arena.mcap"))
    page.wait_for_function("() => window.eyesimViewer.uploadStatus() === 'showing arena.mcap'")
    page.wait_for_function(
        "() => window.eyesimViewer.robotIds().length === 1 && window.eyesimViewer.timeline().end === 0.5"
    )
    assert page.locator("#tl-title").inner_text() == "replay of arena.mcap"
    assert viewer.errors == []
    page.close()
