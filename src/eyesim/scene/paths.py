"""Finding the files a scene refers to: search order, Windows and EyeSim 6 paths, letter case."""

from __future__ import annotations

import os
import re
from functools import lru_cache
from pathlib import Path

from eyesim.paths import DATA_DIR

# How far above the referencing file we look for an EyeSim installation layout when a path does
# not lead to a file: rooted somewhere that does not exist here (C:\Users\..\eyesimX\...,
# %sim%/..., /worlds/...), or relative to a folder the file was copied out of (../textures/x.png).
ANCESTOR_LEVELS = 3

_SIM_VARIABLE = re.compile(r"^%sim%[\\/]*", re.IGNORECASE)
_WINDOWS_DRIVE = re.compile(r"^[A-Za-z]:/")


def home_dirs() -> list[Path]:
    """The EyeSim home directories: $EYESIM_HOME (a path list), then the package's own data."""
    dirs = [Path(p) for p in os.environ.get("EYESIM_HOME", "").split(os.pathsep) if p]
    dirs.append(DATA_DIR)
    return dirs


def resolve(
    reference: str, referencing_file: str | Path | None = None, scene_file: str | Path | None = None
) -> Path | None:
    """The file `reference` names, or None. Order: the path as given (absolute, or relative to
    the working directory); relative to the referencing file's directory; relative to each
    EyeSim home directory. `\\` and `/` both separate; `%sim%` and a leading '/' that does not
    exist mean the EyeSim home. Before the home directories, a relative path is also looked for
    as written from the folders above the referencing file's (up to ANCESTOR_LEVELS), then from
    the scene file's folder (when another file names it: a world's texture) and those above it,
    as EyeSim searched (`../textures/soccer.png` of a world in `worlds/worlds/` finds
    `textures/soccer.png` beside `worlds/`). A rooted path that is not found falls back to its
    trailing components, longest first, below the same folders and the home directories. Every
    step also accepts a match that differs only in letter case."""
    text = reference.strip().replace("\\", "/")
    if not text or "\x00" in text:
        return None
    # Absolute, so that a scene given as `x.sim` has the same parent folders to fall back to
    # (and `..` means the same) as one given by its full path.
    base = Path(os.path.abspath(referencing_file)).parent if referencing_file is not None else None
    in_home = bool(_SIM_VARIABLE.match(text))
    if in_home:
        text = _SIM_VARIABLE.sub("", text)
    rooted = in_home or text.startswith("/") or bool(_WINDOWS_DRIVE.match(text))
    parts = [p for p in text.split("/") if p not in ("", ".")]
    if _WINDOWS_DRIVE.match(text):
        parts = parts[1:]  # drop 'C:'

    bases = [base] if base is not None else []
    if scene_file is not None:
        bases.append(Path(os.path.abspath(scene_file)).parent)
    if rooted:
        anchors = []
        if not in_home and (text.startswith("/") or (os.name == "nt" and _WINDOWS_DRIVE.match(text))):
            anchors.append(Path(text[:3] if _WINDOWS_DRIVE.match(text) else "/"))
        anchors += home_dirs()
    else:  # as written: from the working directory, the folders of the files that name it, the homes
        anchors = [Path.cwd(), *_anchors(bases), *home_dirs()]
    for anchor in anchors:
        found = _find(anchor, tuple(parts))
        if found is not None:
            return found
    return _trailing_components(parts, _anchors(bases)) if rooted else None


def _anchors(bases: list[Path]) -> list[Path]:
    """Each base folder and up to ANCESTOR_LEVELS folders above it, in turn."""
    anchors: list[Path] = []
    for base in bases:
        for anchor in (base, *list(base.parents)[:ANCESTOR_LEVELS]):
            if anchor not in anchors:
                anchors.append(anchor)
    return anchors


def _trailing_components(parts: list[str], anchors: list[Path]) -> Path | None:
    anchors = [*anchors, *home_dirs()]
    usable = [p for p in parts if p != ".."]
    for start in range(len(usable)):
        suffix = tuple(usable[start:])
        for anchor in anchors:
            found = _find(anchor, suffix)
            if found is not None:
                return found
    return None


def _find(anchor: Path, parts: tuple[str, ...]) -> Path | None:
    """anchor/parts if it is a file, else the one whose components match ignoring case."""
    if not parts:
        return None
    try:
        return _find_file(anchor, parts)
    except (OSError, ValueError):  # a name too long for the file system, and the like
        return None


def _find_file(anchor: Path, parts: tuple[str, ...]) -> Path | None:
    exact = anchor.joinpath(*parts)
    if exact.is_file():
        return Path(os.path.abspath(exact))
    here = anchor
    for i, part in enumerate(parts):
        if part == "..":
            here = here.parent
            continue
        name = _entry_ignoring_case(str(here), part.casefold())
        if name is None:
            return None
        here = here / name
    return Path(os.path.abspath(here)) if here.is_file() else None


def _entry_ignoring_case(directory: str, folded: str) -> str | None:
    return _listing(directory).get(folded)


@lru_cache(maxsize=4096)
def _listing(directory: str) -> dict[str, str]:
    """A directory's entries by case-folded name (cached: scenes reference the same folders)."""
    try:
        names = os.listdir(directory)
    except OSError:
        return {}
    listing: dict[str, str] = {}
    for name in sorted(names):
        listing.setdefault(name.casefold(), name)
    return listing


def clear_cache() -> None:
    """Forget directory listings (for tests and long-running sessions after files changed)."""
    _listing.cache_clear()
