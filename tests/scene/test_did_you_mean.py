"""A misspelt world file, robot file or setting gets a 'did you mean' with the warning."""

from __future__ import annotations

from eyesim.scene import load_scene


def warnings(scene) -> str:
    return "\n".join(str(w) for w in scene.warnings)


def test_a_misspelt_world_or_robot_file_names_the_one_next_to_it(tmp_path):
    (tmp_path / "lab.wld").write_text("floor 2000 2000\n")
    (tmp_path / "Rover.robi").write_text("drive DIFFERENTIAL_DRIVE\nname Rover\naxis 50 0 0 90\n")
    (tmp_path / "lab.sim").write_text("world lab.wdl\nrobi Rovr.robi\nS4 500 500 0\n")
    text = warnings(load_scene(tmp_path / "lab.sim"))
    assert "world file not found: 'lab.wdl'" in text and "did you mean 'lab.wld'?" in text
    assert "did you mean 'Rover.robi'?" in text


def test_a_misspelt_setting_names_the_one_meant(tmp_path):
    (tmp_path / "lab.sim").write_text("world %sim%/scenes/arena.wld\nsettings VIS TRCE PSDNOISE=2\nS4 500 500 0\n")
    text = warnings(load_scene(tmp_path / "lab.sim"))
    assert "unknown setting 'TRCE' ignored (did you mean TRACE?)" in text
