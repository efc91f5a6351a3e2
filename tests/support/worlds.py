"""Scenes for the physics tests: any robot files and objects in a walled square arena."""

from __future__ import annotations


from eyesim.scene import builtins, load_object_type, load_robot_type
from eyesim.scene.description import ObjectPlacement, Pose, RobotPlacement, RobotType, Scene, Wall, World

EXAMPLE_ROBOTS = builtins.ROBOTS_DIR


def example_robot(name: str) -> RobotType:
    """A built-in robot type from its file (eyesim/data/robots/<name>.robi)."""
    return load_robot_type(str(EXAMPLE_ROBOTS / f"{name}.robi"))


def arena_scene(robots=(), objects=(), size: float = 3000, wall_height: float = 300, walls=()) -> Scene:
    """`robots`: (RobotType or built-in name, (x, y, phi)) pairs; `objects`: (built-in object name,
    (x, y, phi)) pairs; a square walled floor of `size` mm plus any extra `walls`."""
    border = tuple(
        Wall(*ends, height=wall_height)
        for ends in ((0, 0, size, 0), (size, 0, size, size), (size, size, 0, size), (0, size, 0, 0))
    )
    robot_types, placements = {}, []
    for robot, pose in robots:
        robot_type = robot if isinstance(robot, RobotType) else load_robot_type(robot)
        robot_types[robot_type.name] = robot_type
        placements.append(RobotPlacement(robot_type.name, Pose(*pose)))
    object_types, object_placements = {}, []
    for name, pose in objects:
        object_type = load_object_type(name)
        object_types[object_type.name] = object_type
        object_placements.append(ObjectPlacement(object_type.name, Pose(*pose)))
    world = World("test-arena", size, size, border + tuple(walls))
    return Scene(
        "test-arena",
        world,
        robot_types=robot_types,
        object_types=object_types,
        robots=tuple(placements),
        objects=tuple(object_placements),
    )
