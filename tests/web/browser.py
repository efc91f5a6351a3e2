"""Headless Chromium driving the viewer: launching it, opening the page, reading robot panels.

Shared by the viewer's tests and the simulator's end-to-end browser tests (import this file by
path; tests have no packages). Uses Debian's Chromium; never downloads a browser.
"""

from __future__ import annotations

import base64
import io
import os
import tempfile
from collections.abc import Iterator
from contextlib import ExitStack, contextmanager
from dataclasses import dataclass, field
from pathlib import Path

from PIL import Image
from playwright.sync_api import BrowserContext, Locator, Page, Playwright, sync_playwright

CHROMIUM = Path("/usr/bin/chromium")
CHROMIUM_ARGS = [
    "--no-sandbox",
    "--disable-gpu",
    "--disable-quic",
    "--no-first-run",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    # WebGL on the CPU: slow but enough for the tests.
    "--use-angle=swiftshader",
    "--enable-unsafe-swiftshader",
]
NO_WEBGL_ARGS = ["--disable-webgl", "--disable-3d-apis"]
VIEWPORT = {"width": 1400, "height": 900}
TIMEOUT_MS = 10_000


def chromium_available() -> bool:
    return CHROMIUM.exists()


@contextmanager
def launch_browser(webgl: bool = True, playwright: Playwright | None = None) -> Iterator[BrowserContext]:
    """A headless Chromium with a fresh, throw-away profile. `webgl=False` turns WebGL off, as
    on machines where it cannot start. Pass `playwright` when one is already running (Playwright
    allows one per thread)."""
    args = CHROMIUM_ARGS + ([] if webgl else NO_WEBGL_ARGS)
    with ExitStack() as stack:
        if playwright is None:
            playwright = stack.enter_context(sync_playwright())
        profile = stack.enter_context(tempfile.TemporaryDirectory(prefix="eyesim-chromium-"))
        context = playwright.chromium.launch_persistent_context(
            profile,
            executable_path=str(CHROMIUM),
            headless=True,
            args=args,
            viewport=VIEWPORT,
        )
        stack.callback(context.close)
        context.set_default_timeout(TIMEOUT_MS)
        yield context


@dataclass
class ViewerPage:
    """An open viewer tab and the uncaught errors its scripts raised."""

    page: Page
    errors: list[str] = field(default_factory=list)

    def state(self, expression: str, *args: object) -> object:
        """Evaluates `eyesimViewer.<expression>` with `args`, e.g. state("robotPose", 1)."""
        return self.page.evaluate("([name, args]) => window.eyesimViewer[name](...args)", [expression, list(args)])


def open_viewer(context: BrowserContext, url: str) -> ViewerPage:
    """Opens the viewer and waits until it is connected and has a scene."""
    page = context.new_page()
    viewer = ViewerPage(page)
    page.on("pageerror", lambda error: viewer.errors.append(str(error)))
    page.goto(url)
    page.wait_for_function(
        "() => window.eyesimViewer?.connectionState() === 'open' && window.eyesimViewer.scene().floor !== null"
    )
    return viewer


def robot_panel(page: Page, robot_id: int) -> Locator:
    return page.locator(f'.robot-panel[data-robot="{robot_id}"]')


def lcd_image(page: Page, robot_id: int) -> Locator:
    return robot_panel(page, robot_id).locator("img.lcd-image")


def soft_key(page: Page, robot_id: int, number: int) -> Locator:
    """The button of KEY1..KEY4 (`number` 1..4) under the robot's LCD."""
    return robot_panel(page, robot_id).locator(".soft-key").nth(number - 1)


def wait_for_lcd(page: Page, robot_id: int, updates: int = 1) -> None:
    """Waits until the robot's LCD has shown at least `updates` images."""
    page.wait_for_function(
        "([robot, updates]) => (window.eyesimViewer?.lcdUpdates(robot) ?? 0) >= updates",
        arg=[robot_id, updates],
    )


WORLD_VIEW_SIZED = """() => {
    const canvas = document.querySelector("#world .world-canvas");
    const box = document.querySelector("#world");
    return canvas && canvas.style.width === `${box.clientWidth}px` && canvas.style.height === `${box.clientHeight}px`;
}"""  # the 3D view has taken the size of its box (after a layout change)


def read_lcd_pixels(page: Page, robot_id: int) -> Image.Image:
    """The image the robot's LCD shows, as decoded by the browser, at its natural 480x320."""
    data_url = lcd_image(page, robot_id).evaluate(
        """async image => {
            await image.decode().catch(() => {});  // a new image may still be decoding
            const canvas = document.createElement("canvas");
            canvas.width = image.naturalWidth;
            canvas.height = image.naturalHeight;
            canvas.getContext("2d").drawImage(image, 0, 0);
            return canvas.toDataURL("image/png");
        }"""
    )
    return Image.open(io.BytesIO(base64.b64decode(data_url.split(",", 1)[1]))).convert("RGB")


def robot_screen_position(page: Page, robot_id: int) -> tuple[float, float] | None:
    """Where the robot is drawn on the page (CSS pixels), or None without WebGL."""
    position = page.evaluate("robot => window.eyesimViewer.robotScreenPosition(robot)", robot_id)
    return None if position is None else (position["x"], position["y"])


def save_screenshot(page: Page, name: str) -> None:
    """Saves the page as $EYESIM_SCREENSHOTS/<name>.png when that is set (for looking at it)."""
    folder = os.environ.get("EYESIM_SCREENSHOTS")
    if folder:
        page.screenshot(path=str(Path(folder) / f"{name}.png"))
