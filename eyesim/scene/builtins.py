"""The robot and object types EyeSim provides without a file in the scene: our own data files."""

from __future__ import annotations

from functools import lru_cache
from pathlib import Path

from eyesim.paths import DATA_DIR

ROBOTS_DIR = DATA_DIR / "robots"
OBJECTS_DIR = DATA_DIR / "objects"
SCENES_DIR = DATA_DIR / "scenes"
DEFAULT_SCENE = SCENES_DIR / "default.sim"
FALLBACK_ROBOT = "S4"  # stands in for a robot whose definition file is missing


@lru_cache(maxsize=None)  # the package's data files do not change while we run
def _by_name(directory: Path, suffix: str) -> dict[str, Path]:
    return {p.stem.casefold(): p for p in sorted(directory.glob("*" + suffix))}


def robot_path(name: str) -> Path | None:
    """The built-in robot definition for `name` (any letter case), or None."""
    return _by_name(ROBOTS_DIR, ".robi").get(name.casefold())


def object_path(name: str) -> Path | None:
    """The built-in object definition for `name` (any letter case), or None."""
    return _by_name(OBJECTS_DIR, ".esObj").get(name.casefold())


def robot_names() -> list[str]:
    return [p.stem for p in _by_name(ROBOTS_DIR, ".robi").values()]


def object_names() -> list[str]:
    return [p.stem for p in _by_name(OBJECTS_DIR, ".esObj").values()]
