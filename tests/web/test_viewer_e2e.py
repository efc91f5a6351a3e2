"""The real simulator with a real C program, watched and driven from headless Chromium."""

import sys
from pathlib import Path

import numpy as np
import pytest
from browser import open_viewer, read_lcd_pixels, soft_key, wait_for_lcd

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from support.programs import build, simulator_with_viewer  # noqa: E402

pytestmark = pytest.mark.browser


@pytest.fixture
def simulator(tmp_path):
    program = build("lcd_and_key", tmp_path)
    with simulator_with_viewer("--program", f"1={program}", cwd=tmp_path) as running:
        yield running


def test_the_page_shows_the_robot_driving_and_its_lcd_and_key1_reaches_the_program(browser_context, simulator):
    process, url = simulator
    viewer = open_viewer(browser_context, url)
    page = viewer.page
    assert viewer.state("robotIds") == [1]

    page.wait_for_function("() => window.eyesimViewer.robotPose(1) !== null")
    start = viewer.state("robotPose", 1)["pos"]
    page.wait_for_function(
        "x0 => { const p = window.eyesimViewer.robotPose(1); return p && p.pos[0] > x0 + 0.05; }", arg=start[0]
    )

    wait_for_lcd(page, 1)
    page.wait_for_function("() => window.eyesimViewer.menuLabels(1)[0] === 'GO'")
    lcd = np.asarray(read_lcd_pixels(page, 1))
    assert (lcd[0:13] > 200).all(axis=2).sum() > 40  # "Hello browser" in white on the first row

    soft_key(page, 1, 1).click()
    page.wait_for_function("() => window.eyesimViewer.consoleText(1).includes('got key 1')")
    page.wait_for_function("() => window.eyesimViewer.programState(1)?.event === 'exited'")
    assert viewer.state("programState", 1)["exit_code"] == 0
    assert viewer.errors == []
