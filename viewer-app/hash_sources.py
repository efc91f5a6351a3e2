"""Fingerprints the viewer's sources, so a test can tell when the committed bundle is stale."""

from __future__ import annotations

import argparse
import hashlib
from pathlib import Path

WEB_DIR = Path(__file__).resolve().parent
HASH_FILE = WEB_DIR.parent / "src" / "eyesim" / "web" / "static" / "source-hash.txt"
TOP_LEVEL_SOURCES = (
    "index.html",
    "robot-editor.html",
    "package.json",
    "package-lock.json",
    "tsconfig.json",
    "vite.config.ts",
)


def source_files(web_dir: Path = WEB_DIR) -> list[Path]:
    """Every file the bundle is built from, sorted by its path inside `web_dir`."""
    files = [web_dir / name for name in TOP_LEVEL_SOURCES]
    files += [path for folder in ("src", "public") for path in (web_dir / folder).rglob("*") if path.is_file()]
    return sorted(files, key=lambda path: path.relative_to(web_dir).as_posix())


def source_hash(web_dir: Path = WEB_DIR) -> str:
    """SHA-256 over each source's path and content (line endings normalised, so a Windows
    checkout hashes the same)."""
    digest = hashlib.sha256()
    for path in source_files(web_dir):
        content = path.read_bytes().replace(b"\r\n", b"\n")
        name = path.relative_to(web_dir).as_posix().encode()
        digest.update(b"%s\0%d\0" % (name, len(content)))
        digest.update(content)
    return digest.hexdigest()


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument(
        "--write", action="store_true", help=f"record the hash in {HASH_FILE.relative_to(WEB_DIR.parent)}"
    )
    args = parser.parse_args()
    fingerprint = source_hash()
    if args.write:
        HASH_FILE.write_text(fingerprint + "\n")
    print(fingerprint)


if __name__ == "__main__":
    main()
