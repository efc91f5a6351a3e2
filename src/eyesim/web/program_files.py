"""The files the page may name: programs and sources under the scene roots, and nothing outside.

The roots are the folder `eyesim run` was started in and the running scene's folder. The page
names a file by root number and a path relative to that root; a path that is absolute, climbs
with `..`, or leads (through a symbolic link) out of its root is refused with the reason.

The program list holds what a student would run for a robot, not everything with an execute bit
or a .py name: a source tree started in (EyeSim's own listed 505 files) shows its robot programs
only. A Python file counts when it imports the `eye` module (pytest's test files do not), a C/C++
source when it has a `main` (a library's sources have none), an executable when it is linked
with the RoBIOS library (a script: when it is such a Python program). Folders of build output, caches,
version control, virtual environments, installed packages and Python packages (libraries, not
programs) are not looked into."""

from __future__ import annotations

import os
import re
from pathlib import Path

from eyesim import platform
from eyesim.web.scene_files import FileAccessError, Root, SceneRoots, confined

# Folders that hold no student's programs: build output, caches, VCS, environments, dependencies.
SKIPPED_FOLDERS = {
    "__pycache__",
    "node_modules",
    ".git",
    ".venv",
    "venv",
    "env",
    ".env",
    "build",
    "dist",
    "_build",
    "cmake-build-debug",
    "cmake-build-release",
    "CMakeFiles",
    "site-packages",
    "dist-packages",
    ".tox",
    ".nox",
    ".mypy_cache",
    ".pytest_cache",
    ".ruff_cache",
    ".cache",
    ".eggs",
    "htmlcov",
    ".idea",
    ".vscode",
    "target",
    "bower_components",
}
SKIPPED_SUFFIXES = (".egg-info", ".dist-info", ".app", ".dSYM")
MAX_DEPTH = 4  # folders below a root that the listing looks into
MAX_FILES = 500  # listed at most: a root holding a whole home folder must not stall the page
MAX_ENTRIES = 20_000  # directory entries looked at per root
HEAD_BYTES = 64 * 1024  # of a source read to tell a robot program from other code
BINARY_BYTES = 1024 * 1024  # of an executable read to find the RoBIOS library it is linked with
SOURCE_KINDS = {".c": "c", ".cc": "c++", ".cpp": "c++", ".cxx": "c++"}
NOT_PROGRAMS = {".so", ".o", ".a", ".dylib", ".dll"}  # executable bits, but not something to run
PYTHON_ROBOT = re.compile(rb"^[ \t]*(from[ \t]+eye[ \t]+import|import[ \t]+eye\b)", re.MULTILINE)
C_MAIN = re.compile(rb"\bmain[ \t]*\(")
BINARY_MAGIC = (b"\x7fELF", b"MZ", b"\xcf\xfa\xed\xfe", b"\xce\xfa\xed\xfe", b"\xca\xfe\xba\xbe")
ROBIOS_LIBRARY = re.compile(rb"eyesim", re.IGNORECASE)  # libeyesim.so, eyesim.dll, ...


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


def is_robot_program(path: Path, kind: str) -> bool:
    """Whether a file of that kind is a robot program (or its source), by what it holds."""
    try:
        with open(path, "rb") as file:
            head = file.read(HEAD_BYTES)
            if kind == "python":  # pytest's files import `eye` to test programs, they are not ones
                return PYTHON_ROBOT.search(head) is not None and not _pytest_file(path.name)
            if kind in ("c", "c++"):  # a library's sources have no main
                return C_MAIN.search(head) is not None
            if head.startswith(b"#!"):  # a script: a Python robot program, or not one
                return PYTHON_ROBOT.search(head) is not None
            if not head.startswith(BINARY_MAGIC):
                return False
            return ROBIOS_LIBRARY.search(head + file.read(BINARY_BYTES - len(head))) is not None
    except OSError:
        return False


def _pytest_file(name: str) -> bool:
    return name == "conftest.py" or name.startswith("test_") or name.endswith("_test.py")


def _skipped(folder: Path, name: str) -> bool:
    """A folder the listing does not look into (see the module's doc)."""
    if name.startswith(".") or name in SKIPPED_FOLDERS or name.endswith(SKIPPED_SUFFIXES):
        return True
    path = folder / name
    return (path / "__init__.py").is_file() or (path / "pyvenv.cfg").is_file() or (path / "CMakeCache.txt").is_file()


def list_files(roots: list[Root]) -> list[dict]:
    """The robot programs and their sources under the roots (no links out of them), as {root, path, kind}."""
    found: list[dict] = []
    for index, root in enumerate(roots):
        seen = 0
        for folder, subfolders, files in os.walk(root.path):
            depth = len(Path(folder).relative_to(root.path).parts)
            subfolders[:] = sorted(d for d in subfolders if depth < MAX_DEPTH and not _skipped(Path(folder), d))
            seen += len(files) + len(subfolders)
            for name in sorted(files):
                path = Path(folder) / name
                if name.startswith(".") or not _inside(path, root.path) or not path.is_file():
                    continue
                kind = kind_of(path)
                if kind is not None and is_robot_program(path, kind):
                    found.append({"root": index, "path": path.relative_to(root.path).as_posix(), "kind": kind})
                    if len(found) >= MAX_FILES:
                        return found
            if seen > MAX_ENTRIES:
                break
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
