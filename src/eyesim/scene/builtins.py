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
# EyeSim's stock robots that scenes name by file (`%sim%/robots/ModelCar/ModelCar.robi`) or by
# name, and the built-in robot of the same drive and sensors that stands in for each when its file
# is missing (case-folded name -> built-in name). The EyeSim 6 examples and EyeSim VR test assets
# name these (../shared/corpus); the built-in names stand in for themselves.
STOCK_ROBOTS = {
    "modelcar": "Car",
    "ackermann": "Car",
    "ackermann2": "Car",  # Ackermann cars (motor 1, servo 1)
    "omni1": "Omni",
    "omni2": "Omni",
    "odw": "Omni",  # mecanum robots (motors 1-4 FL FR BL BR, PSDs 1-7)
    "eve": "S4",
    "socbot": "S4",
    "s4bot": "S4",
    "s4y": "S4",
    "s4blue": "S4",  # two-wheeled EyeBots
    "labbot2": "LabBot",
}


@lru_cache(maxsize=None)  # the package's data files do not change while we run
def _by_name(directory: Path, suffix: str) -> dict[str, Path]:
    return {p.stem.casefold(): p for p in sorted(directory.glob("*" + suffix))}


def robot_path(name: str) -> Path | None:
    """The built-in robot definition for `name` (any letter case), or None."""
    return _by_name(ROBOTS_DIR, ".robi").get(name.casefold())


def stock_robot(reference: str) -> tuple[str, str] | None:
    """(EyeSim's stock name, built-in name) for a robot file reference whose file name, else whose
    folder's name (EyeSim keeps each stock robot in a folder of its own: `Omni/Omni2.robi`), is a
    built-in robot or one of EyeSim's stock robots; None for any other name."""
    parts = [p for p in reference.replace("\\", "/").split("/") if p]
    if not parts:
        return None
    names = [parts[-1].rsplit(".", 1)[0] if "." in parts[-1] else parts[-1]]
    if len(parts) > 1:
        names.append(parts[-2])
    for name in names:
        builtin = robot_path(name)
        if builtin is not None:
            return name, builtin.stem
        if name.casefold() in STOCK_ROBOTS:
            return name, STOCK_ROBOTS[name.casefold()]
    return None


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
