"""The program editor in headless Chromium against a real `eyesim run --program 1=robot.c`: open the
robot's program beside its LCD, make an error, Compile and see it marked at its line, fix it, save
with Ctrl-S, Compile, Restart, and see the LCD show the new program's output.

Screenshots go to $EYESIM_SCREENSHOTS when it is set (for looking at them)."""

import shutil
import sys
from pathlib import Path

import pytest
from browser import open_viewer, robot_panel
from browser import save_screenshot as screenshot
from test_scene_switch_browser import open_scene

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from support.programs import simulator_with_viewer  # noqa: E402

from eyesim.scene.builtins import SCENES_DIR  # noqa: E402

pytestmark = pytest.mark.browser

PROGRAM = """#include "eyebot.h"
int main(void) {
  LCDPrintf("version 1\\n");
  LCDArea(100, 100, 380, 200, RED, 1);
  for (;;) OSWait(100);
}
"""
# The LCD's colour in the middle of the area the program fills: [r, g, b] wanted.
LCD_COLOUR = """([r, g, b]) => {
    const image = document.querySelector('.robot-panel[data-robot="1"] img.lcd-image');
    if (!image || !image.complete || !image.naturalWidth) return false;
    const canvas = document.createElement("canvas");
    canvas.width = image.naturalWidth;
    canvas.height = image.naturalHeight;
    const context = canvas.getContext("2d");
    context.drawImage(image, 0, 0);
    const [red, green, blue] = context.getImageData(240, 150, 1, 1).data;
    return Math.abs(red - r) < 40 && Math.abs(green - g) < 40 && Math.abs(blue - b) < 40;
}"""
EDITOR = "window.eyesimProgramEditor?.state()"  # what the program editor shows


def replace_line(page, number: int, text: str) -> None:
    """Types `text` over line `number` of the editor, with the keyboard."""
    page.locator(".program-editor .cm-content").click()
    page.keyboard.press("Control+Home")
    for _ in range(number - 1):
        page.keyboard.press("ArrowDown")
    page.keyboard.press("End")
    page.keyboard.press("Shift+Home")  # to the line's first non-blank
    page.keyboard.insert_text(text)


def test_edit_compile_fix_save_and_restart_from_the_page(browser_context, tmp_path):
    (tmp_path / "robot.c").write_text(PROGRAM)
    shutil.copy(SCENES_DIR / "arena.wld", tmp_path)
    (tmp_path / "lab.sim").write_text("world arena.wld\nS4 500 500 0\n")
    with simulator_with_viewer("lab.sim", "--program", "1=robot.c", cwd=tmp_path) as (_, url):
        viewer = open_viewer(browser_context, url)
        page = viewer.page
        console_errors = []
        page.on("console", lambda message: console_errors.append(message.text) if message.type == "error" else None)
        page.set_viewport_size({"width": 1400, "height": 900})
        page.wait_for_function(LCD_COLOUR, arg=[255, 0, 0], timeout=60_000)

        robot_panel(page, 1).locator(".program-edit").click()
        page.wait_for_function(f"() => {EDITOR}?.file === 'robot.c'", timeout=30_000)
        editor = page.locator(".program-editor")
        assert editor.is_visible() and "version 1" in editor.locator(".cm-content").text_content()
        colours = page.evaluate("""() => new Set([...document.querySelectorAll('.program-editor .cm-line span')]
                                     .map((span) => getComputedStyle(span).color)).size""")
        assert colours >= 3, colours  # highlighted: keywords, strings, numbers, ... each in its colour
        # The editor is beside the robot's LCD, which stays in sight.
        lcd = robot_panel(page, 1).locator("img.lcd-image").bounding_box()
        box = editor.bounding_box()
        assert box["x"] + box["width"] <= lcd["x"] and box["width"] >= 400, (box, lcd)
        screenshot(page, "program-editor-opened")

        replace_line(page, 4, "LCDArea(100, 100, 380, 200, GREN, 1);")
        replace_line(page, 3, 'LCDPrintf("version 2\\n");')
        assert (
            page.evaluate(f"() => {EDITOR}")["dirty"] and "•" in editor.locator(".program-editor-title").text_content()
        )
        editor.locator(".program-editor-compile").click()
        page.wait_for_function(f"() => {EDITOR}.message.includes('did not compile')", timeout=60_000)
        marked = page.evaluate(f"() => {EDITOR}")["marked"]
        assert any(m["line"] == 4 and m["severity"] == "error" and "GREN" in m["message"] for m in marked), marked
        assert editor.locator(".cm-gutter-lint .cm-lint-marker-error").count() == 1
        assert "GREN" in editor.locator(".cm-lintRange-error").first.text_content()
        assert "robot.c:4:" in editor.locator(".program-editor-problems .error").first.text_content()
        assert "GREN" in (tmp_path / "robot.c").read_text()  # Compile saved the text first
        screenshot(page, "program-editor-error")

        replace_line(page, 4, "LCDArea(100, 100, 380, 200, GREEN, 1);")
        page.keyboard.press("Control+s")
        page.wait_for_function(f"() => {EDITOR}.message === 'saved robot.c' && !{EDITOR}.dirty")
        assert "GREEN, 1);" in (tmp_path / "robot.c").read_text()
        editor.locator(".program-editor-compile").click()
        page.wait_for_function(f"() => {EDITOR}.message === 'robot.c compiled'", timeout=60_000)
        assert page.evaluate(f"() => {EDITOR}")["marked"] == []
        assert editor.locator(".cm-lint-marker-error").count() == 0

        editor.locator(".program-editor-restart").click()
        page.wait_for_function(f"() => {EDITOR}.message === 'robot 1 runs robot.c'", timeout=60_000)
        page.wait_for_function(LCD_COLOUR, arg=[0, 255, 0], timeout=60_000)
        page.wait_for_function("() => window.eyesimViewer.consoleText(1) !== null")
        assert robot_panel(page, 1).locator(".program-state").text_content() == "running robot.c"
        screenshot(page, "program-editor-restarted")
        assert viewer.errors == [] and console_errors == []


def test_a_refused_file_and_a_robot_without_a_program_say_why(browser_context, tmp_path):
    shutil.copy(SCENES_DIR / "arena.wld", tmp_path)
    (tmp_path / "lab.sim").write_text("world arena.wld\nS4 500 500 0\n")
    (tmp_path / "street.sim").write_text("world arena.wld\nCar 500 500 0\n")
    (tmp_path / "wander.py").write_text("from eye import *\nLCDPrintf('wander')\nif True\n    pass\n")
    with simulator_with_viewer("lab.sim", cwd=tmp_path) as (_, url):
        viewer = open_viewer(browser_context, url)
        page = viewer.page
        panel = robot_panel(page, 1)
        panel.locator(".program-edit").click()
        page.wait_for_function(f"() => {EDITOR}?.message.startsWith('robot 1 has no program')")
        # A Python source chosen in the editor's list: Compile checks it with py_compile.
        editor = page.locator(".program-editor")
        editor.locator(".program-editor-file option[value='0:wander.py']").wait_for(state="attached")
        editor.locator(".program-editor-file").select_option("0:wander.py")
        page.wait_for_function(f"() => {EDITOR}.file === 'wander.py'")
        editor.locator(".program-editor-compile").click()
        page.wait_for_function(f"() => {EDITOR}.message.includes('did not compile')", timeout=30_000)
        assert [(m["line"], m["severity"]) for m in page.evaluate(f"() => {EDITOR}")["marked"]] == [(3, "error")]
        screenshot(page, "program-editor-python")
        # At 1024x700 the editor takes the 3D view's place, its controls inside it, the LCD beside it.
        page.set_viewport_size({"width": 1024, "height": 700})
        page.wait_for_function(
            "() => document.querySelector('.program-editor').getBoundingClientRect().right <= "
            "document.querySelector('.robots').getBoundingClientRect().left"
        )
        box = editor.bounding_box()
        for control in (
            "program-editor-file",
            "program-editor-save",
            "program-editor-compile",
            "program-editor-restart",
            "program-editor-close",
            "cm-content",
        ):
            inner = editor.locator(f".{control}").bounding_box()
            assert box["x"] <= inner["x"] and inner["x"] + inner["width"] <= box["x"] + box["width"] + 0.5, control
            assert box["y"] <= inner["y"] < box["y"] + box["height"], control
        screenshot(page, "program-editor-1024x700")
        # Another scene: its robot 1 is not the one the editor was opened for; the file stays open.
        open_scene(page, "street.sim")
        page.wait_for_function(f"() => {EDITOR}.robot === null && {EDITOR}.file === 'wander.py'")
        assert "is gone" in page.evaluate(f"() => {EDITOR}")["message"]
        assert editor.locator(".program-editor-restart").is_disabled()
        assert not editor.locator(".program-editor-compile").is_disabled()
        screenshot(page, "program-editor-scene-switched")
        assert viewer.errors == []
