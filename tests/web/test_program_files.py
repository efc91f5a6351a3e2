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


def test_the_listing_holds_programs_and_sources_and_skips_the_rest(tmp_path):
    executable(tmp_path / "drive")
    (tmp_path / "demo.py").write_text("print(1)\n")
    (tmp_path / "src").mkdir()
    (tmp_path / "src" / "wall.c").write_text("int main(void) { return 0; }\n")
    (tmp_path / "src" / "arm.cpp").write_text("int main() { return 0; }\n")
    (tmp_path / "notes.txt").write_text("not a program\n")
    executable(tmp_path / "libthing.so")
    executable(tmp_path / ".hidden" / "secret")
    executable(tmp_path / ".venv" / "bin" / "python")
    executable(tmp_path / "__pycache__" / "x")
    executable(tmp_path / "a" / "b" / "c" / "d" / "deep")  # four folders down: listed
    executable(tmp_path / "a" / "b" / "c" / "d" / "e" / "deeper")  # five: not
    listed = program_files.list_files([Root("run folder", tmp_path)])
    assert {(f["path"], f["kind"]) for f in listed} == {
        ("drive", "executable"), ("demo.py", "python"), ("src/wall.c", "c"), ("src/arm.cpp", "c++"),
        ("a/b/c/d/deep", "executable")}
    assert all(f["root"] == 0 for f in listed)


def test_resolve_names_a_file_inside_its_root_or_says_why_not(tmp_path):
    root = tmp_path / "root"
    program = executable(root / "sub" / "drive")
    executable(tmp_path / "outside")
    os.symlink(tmp_path / "outside", root / "link")
    os.symlink(program, root / "inner-link")  # a link within the root is fine
    roots = [Root("run folder", root)]
    assert program_files.resolve(roots, 0, "sub/drive") == program.resolve()
    assert program_files.resolve(roots, 0, "inner-link") == program.resolve()
    for root_number, path, reason in [(0, "../outside", "'..' is not allowed"),
                                      (0, "sub/../../outside", "'..' is not allowed"),
                                      (0, str(tmp_path / "outside"), "absolute paths are not allowed"),
                                      (0, "link", "leads out of the scene root"),
                                      (0, "sub", "no such file"),
                                      (0, "", "expected a file path"),
                                      (0, "a\0b", "has a NUL character"),
                                      (0, 5, "expected a file path"),
                                      (1, "sub/drive", "no scene root 1"),
                                      (True, "sub/drive", "no scene root True")]:
        with pytest.raises(FileAccessError, match=reason):
            program_files.resolve(roots, root_number, path)


def test_the_roots_are_the_run_folder_and_the_scenes_folder(tmp_path):
    scene = tmp_path / "scenes" / "lab.sim"
    scene.parent.mkdir()
    scene.write_text("")
    roots = program_files.scene_roots(tmp_path, str(scene))
    assert [(r.name, r.path) for r in roots] == [("run folder", tmp_path.resolve()),
                                                 ("scene folder", scene.parent.resolve())]
    assert len(program_files.scene_roots(scene.parent, str(scene))) == 1  # the same folder once
    assert len(program_files.scene_roots(tmp_path, "test-arena")) == 1  # a scene made in memory
    assert program_files.locate(roots, scene.parent / "lab.sim") == {"root": 0, "path": "scenes/lab.sim"}
    assert program_files.locate(roots[1:], tmp_path / "elsewhere") is None
