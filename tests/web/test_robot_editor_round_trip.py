"""The robot editor's open-edit-save-open path keeps every value: every built-in robot (also
opened as a file) and every .robi in the shared corpus goes through the editor's JSON form, is checked
as the browser's edits are, saved as .robi and as JSON, and opened again unchanged."""

from __future__ import annotations

import dataclasses
import shutil
from pathlib import Path

import pytest
from support.corpus import CORPUS

from eyesim.scene import builtins
from eyesim.web.robot_editor import EditorError, check_document, full_json, open_robot, save_robot

CORPUS_ROBOTS = sorted(CORPUS.rglob("*.robi"))


def same(a, b) -> bool:
    return dataclasses.replace(a, source="") == dataclasses.replace(b, source="")


def round_trip(root: Path, source: str) -> None:
    robot, _, problems = open_robot(root, source)
    edited, check = check_document(full_json(robot))  # what the browser sends back unchanged
    assert edited is not None, check
    assert same(edited, robot)
    for name in ("again.robi", "again.json"):
        saved = save_robot(root, edited, name, overwrite=True)
        reopened, _, _ = open_robot(root, f"file:{saved.name}")
        assert same(reopened, robot), name


@pytest.mark.parametrize("name", builtins.robot_names())
def test_every_builtin_robot_opens_and_saves_unchanged(tmp_path, name):
    round_trip(tmp_path, f"builtin:{name}")


@pytest.mark.parametrize("path", sorted(builtins.ROBOTS_DIR.glob("*.robi")), ids=lambda p: p.name)
def test_every_robot_file_opens_and_saves_unchanged(tmp_path, path):
    shutil.copy(path, tmp_path / path.name)
    round_trip(tmp_path, f"file:{path.name}")


def test_every_corpus_robot_opens_and_saves_unchanged(tmp_path):
    assert len(CORPUS_ROBOTS) > 5
    opened = 0
    for path in CORPUS_ROBOTS:
        shutil.copy(path, tmp_path / "original.robi")
        try:
            open_robot(tmp_path, "file:original.robi")
        except EditorError:
            continue  # a corpus file with errors does not open (the loader says why)
        round_trip(tmp_path, "file:original.robi")
        opened += 1
    assert opened >= len(CORPUS_ROBOTS) * 0.8


@pytest.mark.parametrize("drive", ["differential", "ackermann", "omni", "submarine", "arm"])
def test_an_empty_robot_of_every_drive_type_checks_and_saves(tmp_path, drive):
    round_trip_new = open_robot(tmp_path, f"new:{drive}")[0]
    assert round_trip_new.drive == drive
    saved = save_robot(tmp_path, round_trip_new, "new.robi", overwrite=False)
    assert same(open_robot(tmp_path, "file:new.robi")[0], round_trip_new)
    with pytest.raises(EditorError, match="exists: overwrite it"):
        save_robot(tmp_path, round_trip_new, "new.robi", overwrite=False)
    assert saved.exists()


def test_paths_are_confined_to_the_scene_folder(tmp_path):
    (tmp_path / "inside").mkdir()
    outside = tmp_path.parent / f"{tmp_path.name}-outside"
    outside.mkdir()
    (tmp_path / "inside" / "link").symlink_to(outside)
    robot = open_robot(tmp_path, "builtin:S4")[0]
    for bad, message in (
        ("../x.robi", "'..' is not allowed"),
        ("/tmp/x.robi", "absolute paths are not allowed"),
        ("inside/link/x.robi", "leads out of the scene folder"),
        ("x.txt", "ending in .robi or .json"),
        ("nowhere/x.robi", "does not exist"),
    ):
        with pytest.raises(EditorError, match=message):
            save_robot(tmp_path, robot, bad, overwrite=True)
    assert not list(outside.iterdir())
    with pytest.raises(EditorError, match="leads out"):
        open_robot(tmp_path, "file:inside/link/x.robi")
