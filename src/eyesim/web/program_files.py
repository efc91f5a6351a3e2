"""The files the page may name: programs and sources under the scene roots, and nothing outside.

The roots are the folder `eyesim run` was started in and the running scene's folder. The page
names a file by root number and a path relative to that root; a path that is absolute, climbs
with `..`, or leads (through a symbolic link) out of its root is refused with the reason."""

from __future__ import annotations

import os
from pathlib import Path

from eyesim import platform
from eyesim.web.scene_files import FileAccessError, Root, SceneRoots, confined

SKIPPED_FOLDERS = {"__pycache__", "node_modules", ".git", ".venv"}
MAX_DEPTH = 4  # folders below a root that the listing looks into
MAX_FILES = 2000  # a root holding a whole home folder must not stall the page
SOURCE_KINDS = {".c": "c", ".cc": "c++", ".cpp": "c++", ".cxx": "c++"}
NOT_PROGRAMS = {".so", ".o", ".a", ".dylib", ".dll"}  # executable bits, but not something to run


def scene_roots(run_folder: Path, scene_source: str) -> list[Root]:
    """The run folder, then the scene's folder when it is another one."""
    folders = [("run folder", run_folder, True)]
    scene_file = Path(scene_source)
    if scene_file.is_file():
        folders.append(("scene folder", scene_file.parent, True))
    return SceneRoots(folders).roots


def kind_of(path: Path) -> str | None:
    """'python', 'c', 'c++' or 'executable' for a file the page can run or compile, else None."""
    suffix = path.suffix.lower()
    if suffix == ".py":
        return "python"
    if suffix in SOURCE_KINDS:
        return SOURCE_KINDS[suffix]
    if suffix not in NOT_PROGRAMS and platform.is_executable(path):
        return "executable"
    return None


def list_files(roots: list[Root]) -> list[dict]:
    """Every program and source under the roots (no links out of them), as {root, path, kind}."""
    found: list[dict] = []
    for index, root in enumerate(roots):
        for folder, subfolders, files in os.walk(root.path):
            depth = len(Path(folder).relative_to(root.path).parts)
            subfolders[:] = sorted(d for d in subfolders if not d.startswith(".") and d not in SKIPPED_FOLDERS
                                   and depth < MAX_DEPTH)
            for name in sorted(files):
                path = Path(folder) / name
                if name.startswith(".") or not _inside(path, root.path) or not path.is_file():
                    continue
                kind = kind_of(path)
                if kind is not None:
                    found.append({"root": index, "path": path.relative_to(root.path).as_posix(), "kind": kind})
                    if len(found) >= MAX_FILES:
                        return found
    return found


def resolve(roots: list[Root], root: object, relative: object) -> Path:
    """The real path of the file the page names, or FileAccessError with why not."""
    if isinstance(root, bool) or not isinstance(root, int) or not 0 <= root < len(roots):
        raise FileAccessError(f"no scene root {root!r} (there are {len(roots)})")
    path = confined(roots[root].path, relative, "the scene root")
    if not path.is_file():
        raise FileAccessError(f"{relative!r}: no such file in {roots[root].name} {roots[root].path}")
    return path


def locate(roots: list[Root], path: Path) -> dict | None:
    """{root, path} naming a real file under one of the roots, or None when it is in none."""
    real = path.resolve()
    for index, root in enumerate(roots):
        if root.path in real.parents:
            return {"root": index, "path": real.relative_to(root.path).as_posix()}
    return None


def _inside(path: Path, root: Path) -> bool:
    try:
        return root in path.resolve().parents
    except (OSError, RuntimeError):  # a link loop
        return False
