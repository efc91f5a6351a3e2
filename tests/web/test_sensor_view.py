"""The sensor examples in the browser: with VIS and TRACE the viewer draws lidar and PSD rays and
the robots' paths, and a robot's panel shows what its camera took."""

import subprocess
import sys
from pathlib import Path

import pytest
from browser import open_viewer, robot_panel, save_screenshot

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from support.programs import eyesim_command, simulator_with_viewer  # noqa: E402
from eyesim.paths import EXAMPLES_DIR  # noqa: E402

pytestmark = pytest.mark.browser
EXAMPLES = EXAMPLES_DIR


@pytest.fixture
def simulator(tmp_path):
    for name in ("lidar_map", "colour_track"):
        built = subprocess.run(
            eyesim_command("cc", str(EXAMPLES / "programs" / f"{name}.c"), "-o", str(tmp_path / name)),
            capture_output=True,
            text=True,
        )
        assert built.returncode == 0, built.stderr
    scene = tmp_path / "lab.sim"
    scene.write_text(
        f'world "{EXAMPLES / "scenes" / "sensor_lab.wld"}"\nsettings VIS TRACE\n'
        "LabBot 600 1500 0 lidar_map\nS4 700 350 90 colour_track\n"
    )
    with simulator_with_viewer(str(scene), cwd=tmp_path) as (_, url):
        yield url


def test_rays_paths_and_camera_images_show(browser_context, simulator):
    viewer = open_viewer(browser_context, simulator)
    page = viewer.page
    # LabBot's 360 lidar beams and both robots' 4 PSD beams each, once the lidar program scans
    page.wait_for_function("() => window.eyesimViewer.raySegments() >= 360 + 8", timeout=30_000)
    page.wait_for_function("() => window.eyesimViewer.tracePoints(1) > 10", timeout=30_000)
    page.wait_for_function("() => window.eyesimViewer.cameraImages(2) > 0", timeout=30_000)
    assert viewer.state("cameraImages", 1) == 0  # LabBot's program never took a picture
    # Opening the S4's panel shows its camera image under its LCD, which stays 480x320.
    panel = robot_panel(page, 2)
    panel.locator(".robot-header").click()
    lcd = panel.locator(".lcd-image").bounding_box()
    camera = panel.locator(".camera-image").bounding_box()
    assert (lcd["width"], lcd["height"]) == (480, 320)
    assert camera["y"] >= lcd["y"] + lcd["height"] and camera["width"] > 100
    save_screenshot(page, "camera-under-lcd")
    assert viewer.errors == []
