"""Plots people can read, against the real simulator in headless Chromium: the legend shows (not
clipped), hovering reads out the time and the values there, readings a program took now and then
are drawn as steps, a click on the plot moves the timeline to that time, and the plot exports as
PNG and CSV.

Screenshots go to $EYESIM_SCREENSHOTS when it is set (for looking at them)."""

import csv
import io
import re
import sys
from pathlib import Path

import pytest
from browser import open_viewer, save_screenshot
from PIL import Image

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from support.programs import simulator_with_viewer  # noqa: E402

pytestmark = pytest.mark.browser
SLOW = 60_000  # ms: programs starting, worlds built, on a loaded 2-core machine

# Drives on, and reads its front PSD twice a second: a sparse signal beside the dense pose.
PROGRAM = """from eye import *
VWSetSpeed(100, 0)
while True:
    PSDGet(PSD_FRONT)
    OSWait(500)
"""
SIGNALS = ["robot/1/x", "robot/1/psd.1"]


def value_at(rows: list[tuple[float, float]], t: float) -> float:
    """A signal's value at t: its last sample at or before it."""
    return [v for time, v in rows if time <= t][-1]


def test_legend_readout_steps_click_to_seek_and_exports(browser_context, tmp_path):
    (tmp_path / "psd.py").write_text(PROGRAM)
    with simulator_with_viewer("default", "--program", "1=psd.py", cwd=tmp_path) as (_, url):
        viewer = open_viewer(browser_context, url)
        page = viewer.page
        page.set_default_timeout(SLOW)
        page.set_viewport_size({"width": 1366, "height": 768})
        page.wait_for_function("() => window.eyesimViewer.status()?.time > 3.2")
        page.click("#pause")  # the data holds still from here on
        page.wait_for_function("() => window.eyesimViewer.status().paused")
        page.click("#plots-toggle")
        for signal in SIGNALS:
            page.locator(f"input[data-signal='{signal}']").check()
        page.wait_for_function(
            "ids => { const p = window.eyesimViewer.plotted(); return p.length === 2 && "
            "p.every((s) => s.points > 0) && ids.every((id) => p.some((s) => s.id === id)); }",
            arg=SIGNALS,
        )
        points = {s["id"]: s["points"] for s in viewer.state("plotted")}
        assert points["robot/1/psd.1"] >= 6 and points["robot/1/x"] > 100

        # The legend names both signals, inside the panel.
        shown = viewer.state("plotShown")
        assert shown["legend"] == ["robot 1 x (m)", "robot 1 psd.1 (mm)"]
        plots = page.locator("#plots").bounding_box()
        for i in range(2):
            entry = page.locator(".plot-legend .u-series").nth(i).bounding_box()
            assert plots["y"] <= entry["y"] and entry["y"] + entry["height"] <= plots["y"] + plots["height"]
            assert plots["x"] <= entry["x"] and entry["x"] + entry["width"] <= plots["x"] + plots["width"]
        # The PSD, read twice a second, is drawn as steps; the pose, sampled all the time, as a line.
        assert shown["stepped"] == ["robot/1/psd.1"]

        # The exported CSV: a time column, one column per signal, every sample.
        with page.expect_download() as download:
            page.click(".plot-csv")
        assert re.fullmatch(r"eyesim-plot-t[\d.]+\.csv", download.value.suggested_filename)
        table = list(csv.reader(io.StringIO(Path(download.value.path()).read_text())))
        assert table[0] == ["t (s)", "robot 1 x (m)", "robot 1 psd.1 (mm)"]
        x = [(float(r[0]), float(r[1])) for r in table[1:] if r[1]]
        psd = [(float(r[0]), float(r[2])) for r in table[1:] if r[2]]
        assert (len(x), len(psd)) == (points["robot/1/x"], points["robot/1/psd.1"])
        assert [t for t, _ in x] == sorted(t for t, _ in x)

        # Hovering reads out the time and both values there.
        spot = page.evaluate("t => window.eyesimViewer.plotPosition(t)", 2.0)
        page.mouse.move(spot["x"], spot["y"])
        page.wait_for_function("() => window.eyesimViewer.plotShown().readout !== ''")
        readout = viewer.state("plotShown")["readout"]
        match = re.fullmatch(r"t ([\d.]+) s +robot 1 x ([-\d.]+) m +robot 1 psd\.1 (\d+) mm", readout)
        assert match, readout
        t = float(match.group(1))
        assert t == pytest.approx(2.0, abs=0.05)
        assert float(match.group(2)) == pytest.approx(value_at(x, t), abs=0.005)
        assert float(match.group(3)) == value_at(psd, t + 0.005) or float(match.group(3)) == value_at(psd, t - 0.005)
        save_screenshot(page, "plots-hover")

        # The PNG: the chart with its legend.
        with page.expect_download() as download:
            page.click(".plot-png")
        image = Image.open(download.value.path())
        chart = page.locator(".plot-chart canvas").bounding_box()
        assert image.format == "PNG" and image.width >= chart["width"] and image.height > chart["height"]
        assert len(set(image.convert("RGB").getcolors(1 << 16) or [])) > 10  # more than a blank picture

        # A click moves the timeline to that time: the page looks back at it.
        spot = page.evaluate("t => window.eyesimViewer.plotPosition(t)", 1.5)
        page.mouse.click(spot["x"], spot["y"])
        page.wait_for_function("() => window.eyesimViewer.timeline().mode === 'review'")
        assert viewer.state("timeline")["time"] == pytest.approx(1.5, abs=0.05)
        page.wait_for_function(
            "() => Math.abs(window.eyesimViewer.robotPose(1).time - window.eyesimViewer.timeline().time) < 0.05"
        )
        assert viewer.errors == []
