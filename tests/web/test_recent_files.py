"""The scene browser's recent files outlive the run: kept in the state folder, newest first, at
most ten, and a damaged or unwritable store never stops the viewer."""

import json
import logging

from eyesim.paths import state_dir
from eyesim.web.recent_files import FILE_NAME, MAX_RECENT, RecentFiles


def test_the_list_is_kept_for_the_next_run_newest_first_without_repeats(tmp_path):
    store = tmp_path / "state" / FILE_NAME  # the folder is made when first written
    first = RecentFiles(store)
    assert first.paths == []
    for name in ("a.sim", "b.sim", "a.sim"):
        first.note(tmp_path / name)
    expected = [str((tmp_path / "a.sim").resolve()), str((tmp_path / "b.sim").resolve())]
    assert first.paths == expected
    assert RecentFiles(store).paths == expected  # the next run
    assert json.loads(store.read_text()) == expected


def test_at_most_ten_are_kept(tmp_path):
    recent = RecentFiles(tmp_path / FILE_NAME)
    for i in range(MAX_RECENT + 5):
        recent.note(tmp_path / f"{i}.sim")
    kept = RecentFiles(tmp_path / FILE_NAME).paths
    assert len(kept) == MAX_RECENT and kept[0].endswith(f"{MAX_RECENT + 4}.sim")


def test_a_damaged_store_starts_a_new_list_with_a_warning(tmp_path, caplog):
    store = tmp_path / FILE_NAME
    for content in ("{not json", json.dumps({"a": 1}), json.dumps([1, 2])):
        store.write_text(content)
        with caplog.at_level(logging.WARNING, logger="eyesim.web"):
            caplog.clear()
            recent = RecentFiles(store)
        assert recent.paths == [] and str(store) in caplog.text
        recent.note(tmp_path / "x.sim")  # and it is mended by the next note
        assert RecentFiles(store).paths == [str((tmp_path / "x.sim").resolve())]


def test_a_store_that_cannot_be_written_keeps_the_list_for_this_run(tmp_path, caplog):
    blocker = tmp_path / "not-a-folder"
    blocker.write_text("a file where the state folder should be")
    recent = RecentFiles(blocker / FILE_NAME)
    with caplog.at_level(logging.WARNING, logger="eyesim.web"):
        recent.note(tmp_path / "a.sim")
        recent.note(tmp_path / "b.sim")
    assert recent.paths[0].endswith("b.sim") and len(recent.paths) == 2
    assert caplog.text.count("cannot keep the recent scenes") == 1  # warned once


def test_the_state_folder_follows_the_environment(monkeypatch, tmp_path):
    monkeypatch.setenv("EYESIM_STATE_DIR", str(tmp_path / "mine"))
    assert state_dir() == tmp_path / "mine"
    monkeypatch.delenv("EYESIM_STATE_DIR")
    monkeypatch.setenv("XDG_STATE_HOME", str(tmp_path / "xdg"))
    assert state_dir() == tmp_path / "xdg" / "eyesim"
