"""The committed viewer bundle is built from the current sources, with relative asset URLs."""

from __future__ import annotations

import importlib.util
import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
STATIC_DIR = ROOT / "src" / "eyesim" / "web" / "static"


def load_hash_sources():
    spec = importlib.util.spec_from_file_location("hash_sources", ROOT / "viewer-app" / "hash_sources.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_bundle_matches_sources():
    hash_sources = load_hash_sources()
    recorded = hash_sources.HASH_FILE.read_text().strip() if hash_sources.HASH_FILE.exists() else "(none)"
    assert recorded == hash_sources.source_hash(), (
        "src/eyesim/web/static/ is stale: the viewer sources in viewer-app/ changed since the last build; "
        "run `make viewer` and commit eyesim/web/static/"
    )


def test_hash_covers_every_source_and_its_path(tmp_path):
    hash_sources = load_hash_sources()
    for name in hash_sources.TOP_LEVEL_SOURCES:
        (tmp_path / name).write_text(name)
    (tmp_path / "src").mkdir()
    (tmp_path / "src" / "a.ts").write_text("export const a = 1;\n")
    before = hash_sources.source_hash(tmp_path)

    (tmp_path / "src" / "a.ts").write_text("export const a = 1;\r\n")
    assert hash_sources.source_hash(tmp_path) == before, "line endings do not count"

    (tmp_path / "src" / "a.ts").rename(tmp_path / "src" / "b.ts")
    assert hash_sources.source_hash(tmp_path) != before, "a renamed file counts"

    (tmp_path / "src" / "b.ts").rename(tmp_path / "src" / "a.ts")
    (tmp_path / "package-lock.json").write_text("changed")
    assert hash_sources.source_hash(tmp_path) != before, "the lock file counts"


@pytest.mark.parametrize("name", ["index.html", "robot-editor.html"])
def test_bundle_uses_relative_urls_and_has_no_source_maps(name):
    page = (STATIC_DIR / name).read_text()
    urls = re.findall(r'<(?:script|link)[^>]*(?:src|href)="([^"]+)"', page)  # what the page loads, not its links
    assets = [url for url in urls if not url.startswith("data:")]
    assert assets, f"{name} loads the bundle"
    assert all(url.startswith("./assets/") or url == "./favicon.ico" for url in assets), assets
    for url in assets:
        assert (STATIC_DIR / url).is_file(), url
    assert not list(STATIC_DIR.rglob("*.map"))
