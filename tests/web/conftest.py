"""Fixtures for the viewer's tests: the helper modules next to this file, a browser, a fake server."""

from __future__ import annotations

import sys
from collections.abc import Iterator
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent))

from browser import ViewerPage, chromium_available, launch_browser, open_viewer  # noqa: E402
from fake_viewer_server import FakeViewerServer  # noqa: E402
from playwright.sync_api import BrowserContext, Playwright, sync_playwright  # noqa: E402


@pytest.fixture(scope="session")
def playwright() -> Iterator[Playwright]:
    if not chromium_available():
        pytest.fail(
            "the browser tests need Chromium at /usr/bin/chromium (Debian package chromium; make test installs it as root)"
        )
    with sync_playwright() as running:
        yield running


@pytest.fixture(scope="session")
def browser_context(playwright: Playwright) -> Iterator[BrowserContext]:
    """One Chromium for the whole run; each test gets its own tab."""
    with launch_browser(playwright=playwright) as context:
        yield context


@pytest.fixture
def fake_server() -> Iterator[FakeViewerServer]:
    with FakeViewerServer() as server:
        yield server


@pytest.fixture
def viewer(browser_context: BrowserContext, fake_server: FakeViewerServer) -> Iterator[ViewerPage]:
    opened = open_viewer(browser_context, fake_server.url)
    yield opened
    opened.page.close()
