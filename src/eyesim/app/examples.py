"""`eyesim examples [DIR]`: a copy of the examples that come with EyeSim (scenes, C and Python
programs, a grading lab) to run, read and change."""

from __future__ import annotations

import shutil
import sys
from pathlib import Path

from eyesim.paths import EXAMPLES_DIR

DEFAULT_FOLDER = "eyesim-examples"


def register(subparsers) -> None:
    parser = subparsers.add_parser(
        "examples",
        help="copy the examples (scenes, C and Python programs) into a folder",
        description="Copy EyeSim's examples into DIR (default eyesim-examples), then e.g. "
        "`cd DIR && eyesim run scenes/wall_follow.sim`: each scene's first lines say how to run it.",
    )
    parser.add_argument(
        "folder",
        nargs="?",
        default=DEFAULT_FOLDER,
        metavar="DIR",
        help=f"where to put them (default {DEFAULT_FOLDER}); it must not exist or be empty",
    )
    parser.set_defaults(func=main)


def main(args) -> int:
    target = Path(args.folder)
    if target.exists() and (not target.is_dir() or any(target.iterdir())):
        print(f"eyesim examples: {target} already exists and is not an empty folder; name another", file=sys.stderr)
        return 2
    try:
        shutil.copytree(EXAMPLES_DIR, target, dirs_exist_ok=True, ignore=shutil.ignore_patterns("__pycache__", "*.pyc"))
    except OSError as error:
        print(f"eyesim examples: cannot copy to {target}: {error.strerror or error}", file=sys.stderr)
        return 2
    scenes = sorted(p.name for p in (target / "scenes").glob("*.sim"))
    print(
        f"EyeSim examples in {target}: {len(scenes)} scenes ({', '.join(scenes)}), their programs in C and "
        f"Python, and a grading lab.\nTry: cd {target} && eyesim run scenes/{scenes[0] if scenes else ''}"
    )
    return 0
