"""The real simulator with every kind of robot, watched in headless Chromium: the viewer draws the
robots' moving parts, the objects and the water, and a can carried by the arm moves on screen."""

import subprocess
import sys
from pathlib import Path

import pytest
from browser import open_viewer

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from support.programs import eyesim_command, simulator_with_viewer  # noqa: E402

from eyesim.scene import builtins  # noqa: E402

pytestmark = pytest.mark.browser

ROOT = Path(__file__).resolve().parents[2]
ROBOTS = builtins.ROBOTS_DIR


@pytest.fixture
def simulator(tmp_path):
    program = tmp_path / "arm_pick"
    source = ROOT / "tests" / "parts" / "arm" / "programs" / "arm_pick.c"
    built = subprocess.run(eyesim_command("cc", str(source), "-o", str(program)), capture_output=True, text=True)
    assert built.returncode == 0, built.stderr
    (tmp_path / "pool.wld").write_text(
        "floor 4000 4000\n"
        + "".join(
            f"{a} {b} {c} {d} 10 1200\n"
            for a, b, c, d in ((0, 0, 4000, 0), (4000, 0, 4000, 4000), (4000, 4000, 0, 4000), (0, 4000, 0, 0))
        )
    )
    (tmp_path / "all.sim").write_text(
        "world pool.wld\n"
        + "".join(f"robi {ROBOTS / name}.robi\n" for name in ("Reacher", "Car", "Mecanum", "Minnow", "Picker"))
        + "Reacher 1500 1500 0\nCan 1500 1800 0\nCar 500 500 0\nMecanum 3000 600 0\nMinnow 3000 3000 0\n"
        "Picker 700 3000 0\n"
    )
    with simulator_with_viewer(
        str(tmp_path / "all.sim"), "--speed", "4", "--program", f"1={program}", cwd=tmp_path
    ) as (_, url):
        yield url


def test_the_viewer_draws_every_archetype_and_follows_the_carried_can(browser_context, simulator):
    viewer = open_viewer(browser_context, simulator)
    assert viewer.state("scene")["robots"] == 5 and viewer.state("scene")["objects"] == 1
    extras = viewer.state("robotBodiesAndWater")
    # Reacher: 3 links and 2 fingers; Car and Mecanum: 4 wheels each; Picker: 3 links and 2 fingers
    assert extras == {"bodies": 5 + 4 + 4 + 5, "water": 1.2}
    # The can (centre 61 mm up at rest, at x 1.5 m, y 1.8 m) is lifted, then swung round by the arm.
    viewer.page.wait_for_function("() => window.eyesimViewer.objectPose(1)?.pos[2] > 0.15", timeout=60_000)
    viewer.page.wait_for_function(
        "() => { const p = window.eyesimViewer.objectPose(1).pos; return Math.hypot(p[0] - 1.5, p[1] - 1.8) > 0.2; }",
        timeout=60_000,
    )
    assert viewer.state("objectPose", 1)["pos"][2] > 0.15  # still held
    assert viewer.errors == []
