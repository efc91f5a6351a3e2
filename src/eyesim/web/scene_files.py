"""The scene roots: the folders the viewer's scene browser and editor may read and write.

Every path the browser names is a root number and a path relative to that root. It is refused
when it is absolute, climbs out with `..`, or leads out of the root through a symbolic link:
the page can reach the files under the roots and nothing else on the machine."""

from __future__ import annotations

import os
import re
from dataclasses import dataclass
from pathlib import Path, PurePosixPath

SCENE_SUFFIXES = (".sim", ".wld", ".maz", ".json")
ROBOT_SUFFIXES = (".robi",)
OBJECT_SUFFIXES = (".esobj",)
PROGRAM_SUFFIXES = ("", ".x", ".out", ".exe")
MAX_DEPTH = 6  # folders below a root the browser looks into
MAX_ENTRIES = 20_000  # directory entries looked at per listing: a root may be a home folder
MAX_LISTED = 500  # files returned per listing
MAX_PATH = 1000
MAX_NAME = 255  # bytes in one folder or file name, on the usual file systems
SKIPPED_DIRS = {"node_modules", "__pycache__", ".venv", "venv", ".git"}
# A JSON file is a scene file when it says so near its start (json_format: "format": "eyesim.scene").
JSON_SCENE = re.compile(rb'"format"\s*:\s*"eyesim\.(scene|world|maze)"')


class FileAccessError(ValueError):
    """A path the browser may not use, with the reason."""


@dataclass(frozen=True)
class Root:
    name: str  # as the browser shows it
    path: Path  # resolved
    writable: bool = True  # the bundled examples are not: they belong to the installed package


def confined(base: Path, relative: object, where: str = "the scene root") -> Path:
    """The real path of `relative` under the folder `base`; FileAccessError when it is not a plain
    path under it (absolute, climbing with `..`, or leading out through a symbolic link). The one
    check every route that takes a path from the browser goes through."""
    if not isinstance(relative, str) or not relative.strip():
        raise FileAccessError(f"expected a file path relative to {where}")
    if len(relative) > MAX_PATH or "\0" in relative:
        raise FileAccessError("the file path is too long or has a NUL character")
    text = relative.replace("\\", "/")
    parts = PurePosixPath(text).parts
    if text.startswith("/") or re.match(r"^[A-Za-z]:", text):
        raise FileAccessError(f"{relative!r}: absolute paths are not allowed, only paths under {where}")
    if ".." in parts:
        raise FileAccessError(f"{relative!r}: '..' is not allowed, only paths under {where}")
    longest = max(parts, key=lambda part: len(part.encode()), default="")
    if len(longest.encode()) > MAX_NAME - 5:  # room for the .sim/.json a save may add
        raise FileAccessError(
            f"{longest[:40]!r}...: a folder or file name of {len(longest.encode())} bytes, "
            f"more than {MAX_NAME - 5} (file systems take {MAX_NAME})"
        )
    base = base.resolve()
    try:
        resolved = base.joinpath(*parts).resolve()
    except (OSError, RuntimeError):  # a link loop
        raise FileAccessError(f"{relative!r}: a symbolic link loop") from None
    if resolved != base and base not in resolved.parents:
        raise FileAccessError(f"{relative!r} leads out of {where} (a symbolic link): not allowed")
    return resolved


class SceneRoots:
    def __init__(self, folders: list[tuple[str, Path, bool]]):
        """`folders`: (name, folder, writable); a folder given twice counts once."""
        roots: list[Root] = []
        for name, folder, writable in folders:
            resolved = Path(folder).resolve()
            if resolved.is_dir() and all(r.path != resolved for r in roots):
                roots.append(Root(name, resolved, writable))
        self.roots = roots

    def describe(self) -> list[dict]:
        return [
            {"index": i, "name": r.name, "path": str(r.path), "writable": r.writable} for i, r in enumerate(self.roots)
        ]

    # -- confinement ---------------------------------------------------------------------------
    def locate(self, root: object, relative: object) -> Path:
        """The file at `relative` under root number `root`; FileAccessError when it is not allowed."""
        if not isinstance(root, int) or isinstance(root, bool) or not 0 <= root < len(self.roots):
            raise FileAccessError(f"no scene root {root!r} (there are {len(self.roots)})")
        return confined(self.roots[root].path, relative, f"the scene root {self.roots[root].name}")

    def place_of(self, path: str | Path) -> tuple[int, str] | None:
        """(root number, relative path) of a file under a root, else None."""
        resolved = Path(path).resolve()
        for index, root in enumerate(self.roots):
            if root.path in resolved.parents:
                return index, resolved.relative_to(root.path).as_posix()
        return None

    def contains(self, path: str | Path) -> bool:
        return self.place_of(path) is not None

    def writable(self, path: str | Path) -> bool:
        place = self.place_of(path)
        return place is not None and self.roots[place[0]].writable

    # -- listings ------------------------------------------------------------------------------
    def scene_files(self, query: str = "") -> list[dict]:
        return self.files(
            lambda path, name: name.endswith(SCENE_SUFFIXES) and (not name.endswith(".json") or _is_json_scene(path)),
            query,
        )

    def robot_files(self) -> list[dict]:
        return self.files(lambda path, name: name.endswith(ROBOT_SUFFIXES))

    def object_files(self) -> list[dict]:
        return self.files(lambda path, name: name.endswith(OBJECT_SUFFIXES))

    def program_files(self) -> list[dict]:
        """Programs a robot can run: .py files and executables (EyeSim's `prog.x`, a bare `drive`)."""
        return self.files(
            lambda path, name: (
                name.endswith(".py") or (Path(name).suffix in PROGRAM_SUFFIXES and os.access(path, os.X_OK))
            )
        )

    def files(self, wanted, query: str = "") -> list[dict]:
        """Files under the roots for which wanted(path, lower-case name) holds and whose relative
        path contains every word of `query` (any letter case), sorted by root and path."""
        words = query.lower().split()
        found: list[dict] = []
        seen = 0
        for index, root in enumerate(self.roots):
            for directory, folders, files in os.walk(root.path):  # does not follow links to folders
                depth = len(Path(directory).relative_to(root.path).parts)
                folders[:] = sorted(
                    f for f in folders if not f.startswith(".") and f not in SKIPPED_DIRS and depth < MAX_DEPTH
                )
                seen += len(files) + len(folders)
                for name in sorted(files):
                    path = Path(directory, name)
                    relative = path.relative_to(root.path).as_posix()
                    if name.startswith(".") or not all(w in relative.lower() for w in words):
                        continue
                    if path.is_symlink() and not self.contains(path):
                        continue
                    if path.is_file() and wanted(path, name.lower()):
                        found.append({"root": index, "path": relative})
                        if len(found) >= MAX_LISTED:
                            return found
                if seen > MAX_ENTRIES:
                    break
        return found


def _is_json_scene(path: Path) -> bool:
    try:
        with open(path, "rb") as file:
            return JSON_SCENE.search(file.read(4096)) is not None
    except OSError:
        return False
