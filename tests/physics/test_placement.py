"""Robots and objects placed overlapping a wall (real scene files do this): the loader moves them
clear with a warning at their line, so the physics neither flings nor lifts them."""

import math
from pathlib import Path

from support.rooms import square_room, write_scene

from eyesim.core.engine import Simulation
from eyesim.parts.psd.component import PsdSensor
from eyesim.scene import load_scene


def test_a_robot_half_in_a_wall_is_moved_out_stays_upright_and_its_psds_read_the_room(tmp_path):
    # A 200 mm LabBot facing east with its centre 20 mm from the west wall; a Can half in the south wall.
    scene_file = write_scene(tmp_path, square_room(2000), ["LabBot 20 1000 0", "Can 800 10 0"])
    scene = load_scene(scene_file)
    overlaps = [w for w in scene.warnings if w.code == "overlap"]
    assert [(Path(w.location.file).name, w.location.line) for w in overlaps] == [
        (scene_file.name, 1 + scene_file.read_text().splitlines().index("LabBot 20 1000 0")),
        (scene_file.name, 1 + scene_file.read_text().splitlines().index("Can 800 10 0")),
    ]
    assert "overlaps the wall" in overlaps[0].message and "moved to (116, 1000)" in overlaps[0].message
    robot = scene.robots[0].pose
    assert robot.x == 116 and robot.y == 1000  # the wall's face at 5 mm, 1 mm clear, the hull 110 mm behind its centre
    can = scene.objects[0].pose
    assert can.y > 10 and can.x == 800

    sim = Simulation(scene)
    for _ in range(500):  # 1 s
        sim.step()
    x, y, z, phi = sim.robots[0].pose_mm()
    assert abs(x - 116) < 2 and abs(y - 1000) < 2 and abs(z) < 2 and abs(phi) < 0.5  # where put, upright
    quat = sim.world.data.xquat[sim.robots[0].body]
    tilt = math.degrees(2 * math.asin(min(1.0, math.hypot(quat[1], quat[2]))))
    assert tilt < 1
    psds = {psd.id: psd.distance_mm() for psd in sim.robots[0].components_of(PsdSensor)}
    # LabBot PSDs sit 100 mm ahead/behind and 90 mm left/right of its centre, facing out.
    assert abs(psds[1] - (2000 - 5 - 116 - 100)) < 10  # front: the east wall
    assert abs(psds[4] - (116 - 100 - 5)) <= 3  # back: the wall it was moved off
    assert abs(psds[2] - (2000 - 5 - 1000 - 90)) < 10  # left: the north wall
    can_x, can_y, can_z, _ = sim.objects[0].pose_mm()
    assert abs(can_x - 800) < 2 and abs(can_y - can.y) < 2 and abs(can_z) < 2  # stands by the wall, not flung
