"""The viewer's layout from 1024x700 to 1920x1080, against the real simulator in headless Chromium:
the toolbar is visible in one or two rows, the page itself never scrolls (panels scroll inside),
every LCD is drawn at 480x320 or more, no control sticks out of its panel, nothing overlaps; a wide
screen shows robots side by side; the scene editor and the plots fit at 1024x700.

The screenshots are saved (in $EYESIM_SCREENSHOTS, else the test's temporary folder) and their
paths printed: `pytest -s` shows them."""

import os
import sys
from pathlib import Path

import pytest
from browser import open_viewer

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from support.programs import simulator_with_viewer  # noqa: E402

pytestmark = pytest.mark.browser
SLOW = 60_000  # ms: programs starting, worlds built, on a loaded 2-core machine

SIZES = [(1024, 700), (1366, 768), (1920, 1080)]
CAMERA = """from eye import *
CAMInit(QVGA)
LCDMenu("GO", "STOP", "", "END")
while True:
    CAMGet()
    LCDSetPrintf(0, 0, "camera running")
    OSWait(100)
"""
DRIVE = """from eye import *
LCDMenu("A", "", "", "END")
print("driving", flush=True)
VWSetSpeed(100, 20)
while True:
    OSWait(200)
"""

# Every box the layout is made of, and every control, as the page lays them out.
MEASURE = """() => {
  const box = (e) => { const r = e.getBoundingClientRect(); return {x: r.left, y: r.top, w: r.width, h: r.height}; };
  const shown = (e) => e.getClientRects().length > 0 && getComputedStyle(e).visibility !== 'hidden';
  const toolbarItems = [];
  for (const child of document.querySelector('#toolbar').children) {
    const items = getComputedStyle(child).display === 'contents' ? [...child.children] : [child];
    toolbarItems.push(...items.filter(shown).map(box));
  }
  const controls = (root) => [...root.querySelectorAll('button, select, input:not([type=file]), a, img.lcd-image')]
    .filter(shown).map((e) => ({...box(e), what: e.id || e.className || e.tagName}));
  const parts = {};
  for (const id of ['toolbar', 'timeline', 'world', 'robots', 'plots', 'editor']) {
    const e = document.getElementById(id);
    if (e && shown(e)) parts[id] = box(e);
  }
  const containers = ['#toolbar', '#timeline', '.robot-panel.expanded', '#editor', '#plots']
    .flatMap((s) => [...document.querySelectorAll(s)]).filter(shown)
    .map((e) => ({...box(e), what: e.id || e.className, controls: controls(e)}));
  return {
    viewport: {w: innerWidth, h: innerHeight},
    scroll: {height: document.documentElement.scrollHeight, width: document.documentElement.scrollWidth},
    toolbarItems, parts, containers,
    panels: [...document.querySelectorAll('.robot-panel.expanded')].filter(shown).map(box),
    lcds: [...document.querySelectorAll('.robot-panel.expanded img.lcd-image')].filter(shown).map(box),
  };
}"""


def rows(items: list[dict]) -> int:
    """How many rows boxes lie in (tops within 6 px of each other share one)."""
    tops = sorted(round(item["y"]) for item in items)
    count, last = 0, None
    for top in tops:
        if last is None or top - last > 6:
            count += 1
            last = top
    return count


def overlap(a: dict, b: dict) -> float:
    width = min(a["x"] + a["w"], b["x"] + b["w"]) - max(a["x"], b["x"])
    height = min(a["y"] + a["h"], b["y"] + b["h"]) - max(a["y"], b["y"])
    return max(0.0, width) * max(0.0, height)


def check_layout(page, size: tuple[int, int]) -> dict:
    layout = page.evaluate(MEASURE)
    width, height = size
    assert layout["viewport"] == {"w": width, "h": height}
    # The page never scrolls: everything fits, panels scroll inside themselves.
    assert layout["scroll"] == {"height": height, "width": width}
    page.mouse.wheel(0, 2000)
    assert page.evaluate("() => window.scrollY") == 0
    # The toolbar: visible at the top, in one or two rows.
    toolbar = layout["parts"]["toolbar"]
    assert toolbar["y"] == 0 and toolbar["h"] < 100
    assert 1 <= rows(layout["toolbarItems"]) <= 2, layout["toolbarItems"]
    for item in layout["toolbarItems"]:
        assert item["x"] >= 0 and item["x"] + item["w"] <= width + 0.5 and item["y"] + item["h"] <= toolbar["h"]
    # Every open panel's LCD at 1:1 or larger (the scene editor takes the panels' place while editing).
    assert layout["lcds"] or "editor" in layout["parts"]
    assert all(lcd["w"] >= 480 and lcd["h"] >= 320 for lcd in layout["lcds"]), layout["lcds"]
    # No control sticks out of its panel (sideways: panels scroll up and down), none out of the window.
    for container in layout["containers"]:
        for control in container["controls"]:
            assert (
                control["x"] >= container["x"] - 0.5
                and control["x"] + control["w"] <= container["x"] + container["w"] + 0.5
            ), (container["what"], control)
            assert control["x"] + control["w"] <= width + 0.5, (container["what"], control)
    # No part of the page overlaps another; no open robot panel overlaps another.
    parts = layout["parts"]
    names = sorted(parts)
    for i, first in enumerate(names):
        assert 0 <= parts[first]["x"] and parts[first]["x"] + parts[first]["w"] <= width + 0.5, first
        assert parts[first]["y"] + parts[first]["h"] <= height + 0.5, first
        for second in names[i + 1 :]:
            assert overlap(parts[first], parts[second]) < 1, (first, second)
    for i, first in enumerate(layout["panels"]):
        for second in layout["panels"][i + 1 :]:
            assert overlap(first, second) < 1
    # The 3D view keeps a useful size.
    assert parts["world"]["w"] >= 440 and parts["world"]["h"] >= 300, parts["world"]
    return layout


def shot(page, folder: Path, name: str) -> Path:
    path = folder / f"{name}.png"
    page.screenshot(path=str(path))
    print(f"screenshot: {path}")
    return path


@pytest.fixture
def shots(tmp_path) -> Path:
    folder = Path(os.environ.get("EYESIM_SCREENSHOTS") or tmp_path)
    folder.mkdir(parents=True, exist_ok=True)
    return folder


@pytest.fixture
def scene_folder(tmp_path):
    (tmp_path / "camera.py").write_text(CAMERA)
    (tmp_path / "drive.py").write_text(DRIVE)
    (tmp_path / "three robots in the lab.sim").write_text(
        f"world {Path(__file__).resolve().parents[2] / 'src/eyesim/data/scenes/arena.wld'}\n"
        "S4 400 400 0 camera.py\nS4 1200 600 90 drive.py\nLabBot 600 1400 0 drive.py\n"
    )
    return tmp_path


def test_the_layout_fits_from_1024x700_to_1920x1080(browser_context, scene_folder, shots):
    with simulator_with_viewer("three robots in the lab.sim", cwd=scene_folder) as (_, url):
        viewer = open_viewer(browser_context, url)
        page = viewer.page
        page.set_default_timeout(SLOW)
        for width, height in SIZES:
            page.set_viewport_size({"width": width, "height": height})
            page.wait_for_function(
                "() => window.eyesimViewer.cameraImages(1) > 0 && "
                "window.eyesimViewer.lcdUpdates(2) > 0 && window.eyesimViewer.lcdUpdates(3) > 0"
            )
            page.wait_for_function(
                "w => window.innerWidth === w && document.querySelector('#scene-name').textContent", arg=width
            )
            layout = check_layout(page, (width, height))
            columns = viewer.state("panelColumns")
            if width >= 1920:  # a wide screen: robots side by side, each LCD at 1:1
                assert columns >= 2 and len(layout["panels"]) == columns
                tops = {round(p["y"]) for p in layout["panels"]}
                assert len(tops) == 1, layout["panels"]
                assert layout["parts"]["world"]["w"] >= 800
            else:
                assert columns == 1 and len(layout["panels"]) == 1
            shot(page, shots, f"layout-{width}x{height}")
        assert viewer.errors == []


def test_the_scene_editor_and_the_plots_fit_at_1024x700(browser_context, scene_folder, shots):
    with simulator_with_viewer("three robots in the lab.sim", cwd=scene_folder) as (_, url):
        viewer = open_viewer(browser_context, url)
        page = viewer.page
        page.set_default_timeout(SLOW)
        page.set_viewport_size({"width": 1024, "height": 700})
        page.click("#plots-toggle")
        page.locator("input[data-signal='robot/2/x']").check()
        page.wait_for_function("() => window.eyesimViewer.plotted().some((s) => s.points > 0)")
        layout = check_layout(page, (1024, 700))
        plots, world = layout["parts"]["plots"], layout["parts"]["world"]
        assert plots["h"] >= 200 and world["h"] >= 250
        legend = page.locator(".plot-legend").bounding_box()
        assert legend["y"] >= plots["y"] and legend["y"] + legend["height"] <= plots["y"] + plots["h"]
        assert page.locator(".plot-legend .u-series").first.is_visible()
        assert page.locator(".plot-legend .u-label").first.text_content() == "robot 2 x (m)"
        shot(page, shots, "layout-1024x700-plots")
        page.click("#plots-toggle")

        page.click("#edit-scene")
        page.wait_for_selector("#editor:not([hidden])")
        page.wait_for_function("() => document.querySelectorAll('#editor-robot-type option').length > 1")
        layout = check_layout(page, (1024, 700))
        editor = layout["parts"]["editor"]
        assert editor["w"] >= 300 and editor["h"] >= 500, editor  # not a strip
        assert "robots" not in layout["parts"]  # the editor takes the panels' place while editing
        assert layout["parts"]["world"]["w"] >= 600
        for select in ("#editor-robot-type", "#editor-object-type", "#editor-program"):
            box = page.locator(select).bounding_box()
            if box:  # the program list shows once a robot is selected
                assert editor["x"] <= box["x"] and box["x"] + box["width"] <= editor["x"] + editor["w"], select
        page.click("#editor-items li[data-kind=robot][data-index='0']")
        box = page.locator("#editor-program").bounding_box()
        assert box["x"] + box["width"] <= editor["x"] + editor["w"]
        shot(page, shots, "layout-1024x700-editor")
        assert viewer.errors == []
