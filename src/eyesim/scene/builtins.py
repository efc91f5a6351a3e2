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


def scene_path(name: str) -> Path | None:
    """The bundled scene `name` ('mako_pool' or 'mako_pool.sim', any letter case), or None."""
    stem = name[:-4] if name.lower().endswith(".sim") else name
    return _by_name(SCENES_DIR, ".sim").get(stem.casefold())


def scene_argument(text: str) -> Path:
    """A scene named on the command line: the file if there is one, else the bundled scene of
    that name (so `eyesim run mako_pool` works from anywhere), else the path as given."""
    path = Path(text)
    if path.exists() or path.parent != Path("."):
        return path
    return scene_path(text) or path


def scene_names() -> list[str]:
    return [p.stem for p in _by_name(SCENES_DIR, ".sim").values()]


def robot_names() -> list[str]:
    return [p.stem for p in _by_name(ROBOTS_DIR, ".robi").values()]


def object_names() -> list[str]:
    return [p.stem for p in _by_name(OBJECTS_DIR, ".esObj").values()]
