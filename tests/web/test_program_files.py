"""Which files the page lists and accepts under the scene roots (eyesim/web/program_files.py)."""

import os

import pytest

from eyesim.web import program_files
from eyesim.web.scene_files import FileAccessError, Root


def executable(path, text="#!/bin/sh\n"):
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text)
    path.chmod(0o755)
    return path


ROBOT_PY = "from eye import *\nLCDPrintf('hello')\n"
ROBOT_C = '#include "eyebot.h"\nint main(void) { return 0; }\n'


def test_the_listing_holds_robot_programs_and_sources_and_skips_the_rest(tmp_path):
    """What a student would run: robot programs, their sources and compiled ones; not the libraries,
    tests, scripts, build output, caches and environments of a source tree started in."""
    (tmp_path / "drive").write_bytes(b"\x7fELF\x02\x01\x01" + b"\0" * 64 + b"libeyesim.so\0")
    (tmp_path / "drive").chmod(0o755)
    (tmp_path / "demo.py").write_text(ROBOT_PY)
    executable(tmp_path / "run_me.py", "#!/usr/bin/env python3\nimport eye\n")
    (tmp_path / "src").mkdir()
    (tmp_path / "src" / "wall.c").write_text(ROBOT_C)
    (tmp_path / "src" / "arm.cpp").write_text("int main() { return 0; }\n")
    (tmp_path / "src" / "helpers.c").write_text('#include "eyebot.h"\nint twice(int x) { return 2 * x; }\n')
    (tmp_path / "helper.py").write_text("def twice(x):\n    return 2 * x\n")  # imported, not run
    (tmp_path / "notes.txt").write_text("not a program\n")
    executable(tmp_path / "tool.sh")  # a shell script drives no robot
    executable(tmp_path / "other").write_bytes(b"\x7fELF" + b"\0" * 64)  # not linked with RoBIOS
    executable(tmp_path / "libthing.so")
    for name in ("test_drive.py", "drive_test.py", "conftest.py"):
        (tmp_path / "tests").mkdir(exist_ok=True)
        (tmp_path / "tests" / name).write_text(ROBOT_PY)
    (tmp_path / "tests" / "programs").mkdir()
    (tmp_path / "tests" / "programs" / "square.c").write_text(ROBOT_C)
    for folder in (
        ".hidden",
        "build",
        "dist",
        "__pycache__",
        "node_modules",
        "venv",
        "target",
        "thing.egg-info",
        "CMakeFiles",
    ):
        (tmp_path / folder).mkdir()
        (tmp_path / folder / "robot.py").write_text(ROBOT_PY)
    (tmp_path / "pkg").mkdir()  # a Python package: a library
    (tmp_path / "pkg" / "__init__.py").write_text("")
    (tmp_path / "pkg" / "robot.py").write_text(ROBOT_PY)
    (tmp_path / "env2").mkdir()  # a virtual environment under another name
    (tmp_path / "env2" / "pyvenv.cfg").write_text("home = /usr\n")
    (tmp_path / "env2" / "robot.py").write_text(ROBOT_PY)
    (tmp_path / "a" / "b" / "c" / "d").mkdir(parents=True)
    (tmp_path / "a" / "b" / "c" / "d" / "deep.py").write_text(ROBOT_PY)  # four folders down: listed
    (tmp_path / "a" / "b" / "c" / "d" / "e").mkdir()
    (tmp_path / "a" / "b" / "c" / "d" / "e" / "deeper.py").write_text(ROBOT_PY)  # five: not
    listed = program_files.list_files([Root("run folder", tmp_path)])
    assert [(f["path"], f["kind"]) for f in listed] == [
        ("demo.py", "python"),
        ("drive", "executable"),
        ("run_me.py", "python"),
        ("a/b/c/d/deep.py", "python"),
        ("src/arm.cpp", "c++"),
        ("src/wall.c", "c"),
        ("tests/programs/square.c", "c"),
    ]
    assert all(f["root"] == 0 for f in listed)


def test_the_listing_is_capped(tmp_path, monkeypatch):
    monkeypatch.setattr(program_files, "MAX_FILES", 5)
    for n in range(8):
        (tmp_path / f"robot{n}.py").write_text(ROBOT_PY)
    assert len(program_files.list_files([Root("run folder", tmp_path)])) == 5


def test_resolve_names_a_file_inside_its_root_or_says_why_not(tmp_path):
    root = tmp_path / "root"
    program = executable(root / "sub" / "drive")
    executable(tmp_path / "outside")
    os.symlink(tmp_path / "outside", root / "link")
    os.symlink(program, root / "inner-link")  # a link within the root is fine
    roots = [Root("run folder", root)]
    assert program_files.resolve(roots, 0, "sub/drive") == program.resolve()
    assert program_files.resolve(roots, 0, "inner-link") == program.resolve()
    for root_number, path, reason in [
        (0, "../outside", "'..' is not allowed"),
        (0, "sub/../../outside", "'..' is not allowed"),
        (0, str(tmp_path / "outside"), "absolute paths are not allowed"),
        (0, "link", "leads out of the scene root"),
        (0, "sub", "no such file"),
        (0, "", "expected a file path"),
        (0, "a\0b", "has a NUL character"),
        (0, 5, "expected a file path"),
        (1, "sub/drive", "no scene root 1"),
        (True, "sub/drive", "no scene root True"),
    ]:
        with pytest.raises(FileAccessError, match=reason):
            program_files.resolve(roots, root_number, path)


def test_the_roots_are_the_run_folder_and_the_scenes_folder(tmp_path):
    scene = tmp_path / "scenes" / "lab.sim"
    scene.parent.mkdir()
    scene.write_text("")
    roots = program_files.scene_roots(tmp_path, str(scene))
    assert [(r.name, r.path) for r in roots] == [
        ("run folder", tmp_path.resolve()),
        ("scene folder", scene.parent.resolve()),
    ]
    assert len(program_files.scene_roots(scene.parent, str(scene))) == 1  # the same folder once
    assert len(program_files.scene_roots(tmp_path, "test-arena")) == 1  # a scene made in memory
    assert program_files.locate(roots, scene.parent / "lab.sim") == {"root": 0, "path": "scenes/lab.sim"}
    assert program_files.locate(roots[1:], tmp_path / "elsewhere") is None
