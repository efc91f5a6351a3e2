"""The loader moves placements that overlap a wall, with a warning at their line (a real scene)."""

from eyesim.scene import load_scene
from scene_testing import CORPUS


def test_a_corpus_scene_with_a_labbot_twenty_mm_from_a_wall_gets_the_warning():
    scene = load_scene(CORPUS / "ASAX21__VRRoboticProject/Test Assets/examples/random/Random3.sim")
    [warning] = [w for w in scene.warnings if w.code == "overlap"]
    assert warning.location.line == 4 and "robot 'LabBot' at (200, 200)" in warning.message
