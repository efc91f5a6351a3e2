"""A simulator serving on every address: Chromium gets in with the printed URL's token, not without."""

import re
import sys
from pathlib import Path

import pytest
from browser import open_viewer

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from support.programs import simulator_with_viewer  # noqa: E402

pytestmark = pytest.mark.browser


def test_the_printed_url_opens_the_viewer_and_a_bare_one_is_refused(browser_context, tmp_path):
    with simulator_with_viewer("--host", "0.0.0.0", cwd=tmp_path, token=True) as (process, url):
        match = re.match(r"http://[^/]+:(\d+)/\?token=([\w-]+)$", url)
        assert match, url
        port, token = match.groups()
        bare = browser_context.new_page()
        response = bare.goto(f"http://127.0.0.1:{port}/")
        bare.screenshot(path="/tmp/refused.png")
        assert response.status == 403
        assert "access token" in bare.inner_text("body")
        bare.close()
        viewer = open_viewer(browser_context, f"http://127.0.0.1:{port}/?token={token}")
        assert viewer.state("robotIds") == [1]
        viewer.page.screenshot(path="/tmp/token.png")
        assert viewer.errors == []
        viewer.page.close()


def test_on_loopback_too_the_printed_url_carries_the_token(browser_context, tmp_path):
    with simulator_with_viewer(cwd=tmp_path, token=True) as (process, url):
        match = re.match(r"http://127\.0\.0\.1:(\d+)/\?token=([\w-]+)$", url)
        assert match, url
        port, _ = match.groups()
        bare = browser_context.new_page()
        assert bare.goto(f"http://127.0.0.1:{port}/").status == 403
        bare.close()
        viewer = open_viewer(browser_context, url)
        assert viewer.state("robotIds") == [1] and viewer.errors == []
        viewer.page.close()
