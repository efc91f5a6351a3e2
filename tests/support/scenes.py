"""Small scenes built in code for the engine, network and camera tests."""

import dataclasses

import numpy as np
from PIL import Image

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


RED, GREEN, BLUE, YELLOW, ORANGE = (255, 0, 0), (0, 200, 0), (0, 0, 255), (230, 230, 0), (255, 120, 0)


def coloured_scene(
    tmp_path, robot_type=None, robots=((600, 600, 30), (1200, 900, 100), (700, 1300, 200)), texture=False
) -> Scene:
    """A 2 m room with a wall of each colour, a low orange wall, three robots and, if asked, a
    checkered floor texture (written to `tmp_path`) and another robot type for them (the cameras'
    tests)."""
    walls = (
        Wall(0, 0, 2000, 0, color=RED),
        Wall(2000, 0, 2000, 2000, color=GREEN),
        Wall(2000, 2000, 0, 2000, color=BLUE),
        Wall(0, 2000, 0, 0, color=YELLOW),
        Wall(1000, 300, 1400, 300, thickness=40, height=120, color=ORANGE),
    )
    scene = arena(robots=robots)
    world = dataclasses.replace(scene.world, walls=walls)
    if texture:
        checks = np.kron(np.indices((8, 8)).sum(axis=0) % 2, np.ones((16, 16), dtype=np.int64))
        image = np.where(checks[:, :, None] == 1, (240, 240, 240), (60, 60, 140)).astype(np.uint8)
        Image.fromarray(image).save(tmp_path / "checker.png")
        world = dataclasses.replace(world, floor_texture=str(tmp_path / "checker.png"))
    scene = dataclasses.replace(scene, world=world)
    if robot_type is not None:
        scene = dataclasses.replace(scene, robot_types={robot_type.name: robot_type})
    return scene
