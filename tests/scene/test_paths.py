"""Finding referenced files: search order, separators, Windows and EyeSim 6 paths, letter case."""

from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from eyesim.scene import paths
from scene_testing import CORPUS


@pytest.fixture(autouse=True)
def fresh(monkeypatch, tmp_path):
    monkeypatch.delenv("EYESIM_HOME", raising=False)
    monkeypatch.chdir(tmp_path)
    paths.clear_cache()
    yield
    paths.clear_cache()


def make(root: Path, relative: str) -> Path:
    path = root / relative
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text("x")
    return path


def test_relative_to_the_referencing_file(tmp_path):
    target = make(tmp_path, "lab/worlds/a.wld")
    scene = make(tmp_path, "lab/a.sim")
    assert paths.resolve("worlds/a.wld", scene) == target


def test_backslashes_dot_slash_and_dotdot(tmp_path):
    target = make(tmp_path, "images/track.png")
    world = make(tmp_path, "sims/worlds/t.wld")
    assert paths.resolve("..\\..\\images\\track.png", world) == target
    assert paths.resolve("./../../images/track.png", world) == target


def test_as_given_absolute(tmp_path):
    target = make(tmp_path, "x/a.wld")
    assert paths.resolve(str(target), None) == target


def test_as_given_relative_to_the_working_directory(tmp_path):
    target = make(tmp_path, "cwd.wld")
    assert paths.resolve("cwd.wld", tmp_path / "elsewhere" / "s.sim") == target


def test_letter_case_differs(tmp_path):
    target = make(tmp_path, "Objects/StopSign/STOP.obj")
    es = make(tmp_path, "objects/stopsign/x.esObj")
    assert paths.resolve("Stop.obj", tmp_path / "Objects/StopSign/a.esObj") == target
    assert paths.resolve("../../OBJECTS/stopsign/stop.OBJ", es) == target


def test_windows_absolute_path_falls_back_to_trailing_components(tmp_path):
    target = make(tmp_path, "Sims/Updated_Objects/StopSign/stopsign.esObj")
    scene = make(tmp_path, "Sims/a.sim")
    ref = "C:\\Users\\Noah\\AppData\\eyesimX\\Updated_Objects/StopSign/stopsign.esObj"
    assert paths.resolve(ref, scene) == target


def test_eyesim6_sim_variable_and_rooted_paths_search_above(tmp_path):
    target = make(tmp_path, "Test Assets/worlds/Soccer1998.wld")
    scene = make(tmp_path, "Test Assets/examples/drivemodes/Diff.sim")
    assert paths.resolve("%sim%/worlds/worlds/Soccer1998.wld", scene) == target
    assert paths.resolve("/worlds/Soccer1998.wld", scene) == target
    assert paths.resolve("%SIM%\\worlds\\Soccer1998.wld", scene) == target


def test_a_referencing_file_named_relative_to_the_working_directory_searches_the_same_folders(tmp_path, monkeypatch):
    target = make(tmp_path, "Test Assets/worlds/Soccer1998.wld")
    scene = make(tmp_path, "Test Assets/examples/drivemodes/Diff.sim")
    monkeypatch.chdir(scene.parent)
    assert paths.resolve("%sim%/worlds/worlds/Soccer1998.wld", "Diff.sim") == target
    assert paths.resolve("../../worlds/Soccer1998.wld", Path("Diff.sim")) == target


def test_eyesim_home_directory(tmp_path, monkeypatch):
    home = tmp_path / "home"
    target = make(home, "robots/Eve/Eve.robi")
    monkeypatch.setenv("EYESIM_HOME", str(home))
    scene = make(tmp_path, "somewhere/else/a.sim")
    assert paths.resolve("%sim%/robots/Eve/Eve.robi", scene) == target
    assert paths.resolve("robots/Eve/Eve.robi", scene) == target


def test_package_data_is_a_home(tmp_path):
    scene = make(tmp_path, "a.sim")
    assert paths.resolve("/robots/S4.robi", scene) == paths.DATA_DIR / "robots" / "S4.robi"


def test_missing_gives_none(tmp_path):
    scene = make(tmp_path, "a.sim")
    assert paths.resolve("Path\\To\\World.wld", scene) is None
    assert paths.resolve("", scene) is None
    assert paths.resolve("   ", scene) is None


def test_relative_references_search_the_folders_above_as_eyesim_did(tmp_path, monkeypatch):
    target = make(tmp_path, "maze.maz")
    scene = make(tmp_path, "lab/sub/a.sim")
    monkeypatch.chdir(scene.parent)
    assert paths.resolve("maze.maz", scene) == target
    assert paths.resolve("maze.maz", make(tmp_path, "1/2/3/4/a.sim")) is None  # at most three folders up


def test_a_relative_texture_of_a_world_copied_one_folder_down(tmp_path):
    # EyeSim's Soccer1998.wld in worlds/worlds/ names ../textures/soccer.png, which is in textures/
    # beside worlds/, not in worlds/textures/.
    target = make(tmp_path, "Test Assets/textures/soccer.png")
    world = make(tmp_path, "Test Assets/worlds/worlds/Soccer1998.wld")
    assert paths.resolve("../textures/soccer.png", world) == target
    assert paths.resolve("..\\textures\\Soccer.PNG", world) == target


def test_relative_references_search_the_scene_folder_after_the_referencing_files(tmp_path):
    target = make(tmp_path, "lab/images/floor.png")
    world = make(tmp_path, "worlds/a/b/c/arena.wld")  # the world's own folders do not lead there
    scene = make(tmp_path, "lab/run.sim")
    assert paths.resolve("images/floor.png", world) is None
    assert paths.resolve("images/floor.png", world, scene) == target


def test_the_folders_above_come_before_the_homes(tmp_path, monkeypatch):
    home = tmp_path / "home"
    make(home, "textures/soccer.png")
    near = make(tmp_path, "sims/textures/soccer.png")
    monkeypatch.setenv("EYESIM_HOME", str(home))
    assert paths.resolve("textures/soccer.png", make(tmp_path, "sims/worlds/w.wld")) == near
    assert paths.resolve("textures/soccer.png", make(tmp_path, "other/x/w.wld")) == home / "textures/soccer.png"


def test_a_placeholder_path_stays_missing():
    # the corpus' Example.sim names `world "Path\To\World.wld"`; a world.wld two folders up is
    # not what it means
    scene = CORPUS / "ASAX21__VRRoboticProject/Test Assets/sims/Example.sim"
    assert paths.resolve("Path\\To\\World.wld", scene) is None


def test_directories_are_not_files(tmp_path):
    (tmp_path / "dir.wld").mkdir()
    assert paths.resolve("dir.wld", tmp_path / "a.sim") is None


def test_corpus_windows_world_reference():
    scene = CORPUS / "ASAX21__VRRoboticProject/Test Assets/MySim.sim"
    found = paths.resolve("C:\\University\\EyeSim\\RobotVR\\Test Assets\\MySim_world.wld", scene)
    assert found == CORPUS / "ASAX21__VRRoboticProject/Test Assets/MySim_world.wld"


@settings(max_examples=200, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(st.text(max_size=300) | st.text(alphabet="/\\.:%simCc abx", max_size=40))
def test_any_reference_gives_a_file_or_none(reference):
    found = paths.resolve(reference, CORPUS / "ASAX21__VRRoboticProject/Test Assets/examples/omni/ODW-world.sim")
    assert found is None or found.is_file()
