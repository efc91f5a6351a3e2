"""The loader moves placements that overlap a wall or each other, with a warning at their line
(real scenes), and refuses a crowd on one spot."""

from eyesim.scene import load_scene
from scene_testing import CORPUS


def test_a_corpus_scene_with_a_labbot_twenty_mm_from_a_wall_gets_the_warning():
    scene = load_scene(CORPUS / "ASAX21__VRRoboticProject/Test Assets/examples/random/Random3.sim")
    wall, robot = [w for w in scene.warnings if w.code == "overlap"]
    assert wall.location.line == 4 and "robot 'LabBot' at (200, 200) overlaps the wall" in wall.message
    # moved off the wall, the first LabBot's corner reaches into the second (placed at 45 degrees):
    # the second moves the shortest way out, a few mm
    assert robot.location.line == 5 and robot.message == (
        "robot 'LabBot' at (400, 400) overlaps robot 'LabBot' (line 4): moved to (420, 420), clear of it"
    )
    assert [(r.pose.x, r.pose.y) for r in scene.robots] == [(300, 200), (420, 420), (600, 600)]
