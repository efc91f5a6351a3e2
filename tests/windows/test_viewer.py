"""The viewer served by the Windows simulator under Wine, in Linux's headless Chromium: the robot
drives, its LCD shows what its C program drew, and a soft key clicked in the page reaches the
program."""

from __future__ import annotations

import sys

import numpy as np
import pytest
from wine_sim import HERE, PROGRAMS, OutputReader, no_process_left, wait_until

sys.path.insert(0, str(HERE.parent / "web"))
from browser import chromium_available, launch_browser, open_viewer, read_lcd_pixels, soft_key  # noqa: E402

pytestmark = pytest.mark.browser


def test_the_viewer_shows_the_robot_and_its_lcd(windows, tmp_path, artifact):
    if not chromium_available():
        pytest.fail("the viewer test needs Chromium at /usr/bin/chromium (make test installs it as root)")
    program = windows.compile_c(PROGRAMS / "viewer_lcd.c", tmp_path / "viewer_lcd.exe", "-Wall", "-Werror")
    with no_process_left(windows.path(tmp_path)):
        process = windows.start(
            "run", "--port", "0", "--viewer-port", "0", "--program", f"1={program.name}", cwd=tmp_path
        )
        output = OutputReader(process)
        try:
            url = output.wait_for(r"viewer: (http://\S+)", timeout=120).group(1)
            with launch_browser() as context:
                context.set_default_timeout(60_000)  # Wine on a busy machine: everything takes longer
                viewer = open_viewer(context, url)
                page = viewer.page
                assert viewer.state("robotIds") == [1]

                page.wait_for_function("() => window.eyesimViewer.robotPose(1) !== null")
                start = viewer.state("robotPose", 1)["pos"]
                page.wait_for_function(
                    "x0 => { const p = window.eyesimViewer.robotPose(1); return p && p.pos[0] > x0 + 0.05; }",
                    arg=start[0],
                )

                page.wait_for_function("() => (window.eyesimViewer?.lcdUpdates(1) ?? 0) >= 1")
                page.wait_for_function("() => window.eyesimViewer.menuLabels(1)[0] === 'GO'")

                def lcd_drawn():
                    lcd = np.asarray(read_lcd_pixels(page, 1))
                    text = (lcd[0:13] > 200).all(axis=2).sum() > 40  # "Hello from Windows" on the first row
                    square = (lcd[125:175, 205:275] == [0, 0, 255]).all()  # LCDArea(200, 120, 279, 179, BLUE, 1)
                    return text and square

                wait_until(lcd_drawn, 60, "the LCD to show the program's text and blue square", interval=0.2)
                screenshot = artifact("windows-viewer.png")
                page.screenshot(path=str(screenshot))
                print(f"screenshot of the Windows simulator's viewer: {screenshot}")

                soft_key(page, 1, 1).click()
                # Under Wine on a busy machine the round trip through the program takes seconds.
                page.wait_for_function("() => window.eyesimViewer.consoleText(1).includes('got key 1')")
                page.wait_for_function("() => window.eyesimViewer.programState(1)?.event === 'exited'")
                assert viewer.state("programState", 1)["exit_code"] == 0
                assert viewer.errors == []
            output.wait_for(r"got key 1", timeout=30)
        finally:
            process.terminate()  # Wine ends the Windows process (and the job of its program, if any)
            process.wait(timeout=60)
