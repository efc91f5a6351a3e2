"""Small scenes built in code for the engine and network tests."""

import dataclasses

from eyesim.scene import load_robot_type
from eyesim.scene.description import Pose, RobotPlacement, Scene, Wall, World


def arena(robots=((500, 500, 0),), size=2000, inner_walls=()) -> Scene:
    """A square walled arena with S4 robots at the given (x, y, phi) poses (mm, degrees)."""
    walls = (Wall(0, 0, size, 0), Wall(size, 0, size, size), Wall(size, size, 0, size), Wall(0, size, 0, 0))
    s4 = load_robot_type("S4")
    placements = tuple(RobotPlacement(s4.name, Pose(*pose)) for pose in robots)
    return Scene(
        "test-arena",
        World("test-arena", size, size, walls + tuple(inner_walls)),
        robot_types={s4.name: s4},
        robots=placements,
    )


def with_call_time(scene: Scene, ms: float) -> Scene:
    """The scene with `settings CALLTIME=<ms>`: every ordinary call takes `ms` of simulation time."""
    return dataclasses.replace(scene, settings=dataclasses.replace(scene.settings, call_time=ms))
