"""Robots and objects placed overlapping a wall: real scene files do this (a 200 mm LabBot 20 mm
from a wall). Built as placed, the physics would push them out violently, flinging them over the
wall or lifting them. Each one is moved, on the floor plan, to the nearest pose clear of the walls,
with a warning at its placement line (docs/scene.md: "Placements that overlap walls")."""

from __future__ import annotations

import math
from dataclasses import replace

from eyesim.scene.description import Collider, Location, ObjectPlacement, ObjectType, Pose, RobotPlacement, RobotType, Wall
from eyesim.scene.diagnostics import Diagnostics, quoted

CLEARANCE = 1.0  # mm left between a moved footprint and the wall
DEFAULT_OBJECT_SIZE = 100.0  # mm: the box an object without colliders gets (physics/objects.py)
ROUNDS = 8  # of pushing out: a footprint pushed off one wall can touch the next (a corner)


def _robot_extent(robot_type: RobotType) -> tuple[float, float, float, float]:
    """A robot's floor-plan bounding box: its hull as the physics builds it, and its drive wheels."""
    from eyesim.robot.build import hull_colliders  # here: the robot package imports the scene's

    x0, y0, x1, y1 = _box_extent(hull_colliders(robot_type))
    wheels = robot_type.wheels
    if wheels is not None and robot_type.drive in ("differential", "ackermann"):
        radius, reach = wheels.diameter / 2, wheels.track / 2 + wheels.diameter / 2
        x0, x1 = min(x0, robot_type.axis_offset - radius), max(x1, robot_type.axis_offset + radius)
        y0, y1 = min(y0, -reach), max(y1, reach)
    return x0, y0, x1, y1


def _box_extent(colliders: tuple[Collider, ...]) -> tuple[float, float, float, float]:
    """The floor-plan bounding box (x0, y0, x1, y1, mm, object frame) of an object's colliders."""
    if not colliders:
        half = DEFAULT_OBJECT_SIZE / 2
        return -half, -half, half, half
    xs, ys = [], []
    for c in colliders:
        if c.kind == "box":
            hx, hy = c.size[0] / 2, c.size[1] / 2
        elif c.kind == "sphere":
            hx = hy = c.size[0]
        else:  # capsule, cylinder: radius across, half length along a horizontal axis
            r, h = c.size[0], c.size[1] / 2
            hx = max(r, h) if c.axis == "x" else r
            hy = max(r, h) if c.axis == "y" else r
        xs += [c.center[0] - hx, c.center[0] + hx]
        ys += [c.center[1] - hy, c.center[1] + hy]
    return min(xs), min(ys), max(xs), max(ys)


def _corners(pose: Pose, extent: tuple[float, float, float, float]) -> list[tuple[float, float]]:
    x0, y0, x1, y1 = extent
    c, s = math.cos(math.radians(pose.phi)), math.sin(math.radians(pose.phi))
    return [(pose.x + x * c - y * s, pose.y + x * s + y * c) for x, y in ((x0, y0), (x1, y0), (x1, y1), (x0, y1))]


def _push_out(pose: Pose, extent, wall: Wall) -> tuple[float, float]:
    """The shortest shift (mm) along the wall's normal that clears the footprint of this wall, or
    (0, 0) when it does not overlap. The footprint leaves on the side its centre is on."""
    dx, dy = wall.x2 - wall.x1, wall.y2 - wall.y1
    length = math.hypot(dx, dy)
    if length == 0:
        return 0.0, 0.0
    ux, uy = dx / length, dy / length
    nx, ny = -uy, ux
    half = wall.thickness / 2
    corners = _corners(pose, extent)
    along = [(x - wall.x1) * ux + (y - wall.y1) * uy for x, y in corners]
    # Walls are built lengthened by half their thickness at both ends (physics/world.py).
    if max(along) < -half or min(along) > length + half:
        return 0.0, 0.0
    across = [(x - wall.x1) * nx + (y - wall.y1) * ny for x, y in corners]
    if min(across) >= half or max(across) <= -half:
        return 0.0, 0.0  # wholly on one side
    centre = (pose.x - wall.x1) * nx + (pose.y - wall.y1) * ny
    if centre >= 0:
        shift = half + CLEARANCE - min(across)
    else:
        shift = -(half + CLEARANCE + max(across))
    return shift * nx, shift * ny


def _settle(pose: Pose, extent, walls) -> tuple[Pose, Wall | None]:
    """The pose moved clear of all walls (as far as a few rounds manage), and the first wall it
    overlapped (None: it was clear)."""
    first = None
    for _ in range(ROUNDS):
        moved = False
        for wall in walls:
            sx, sy = _push_out(pose, extent, wall)
            if sx or sy:
                first = first or wall
                pose = replace(pose, x=pose.x + sx, y=pose.y + sy)
                moved = True
        if not moved:
            break
    return pose, first


def settle_placements(robots: list[RobotPlacement], objects: list[ObjectPlacement],
                      robot_types: dict[str, RobotType], object_types: dict[str, ObjectType],
                      walls: tuple[Wall, ...], diagnostics: Diagnostics, scene_file: str):
    """Robots and objects with every overlap with a wall moved out, and a warning for each."""
    def settle(placement, kind: str, extent):
        pose, wall = _settle(placement.pose, extent, walls)
        if wall is None:
            return placement
        where = placement.location or Location(scene_file)
        diagnostics.warning(where, f"{kind} {quoted(placement.type_name)} at ({placement.pose.x:g}, "
                            f"{placement.pose.y:g}) overlaps the wall from ({wall.x1:g}, {wall.y1:g}) to "
                            f"({wall.x2:g}, {wall.y2:g}): moved to ({pose.x:.0f}, {pose.y:.0f}), clear of the walls",
                            "overlap")
        return replace(placement, pose=pose)

    settled_robots = []
    for placement in robots:
        settled_robots.append(settle(placement, "robot", _robot_extent(robot_types[placement.type_name])))
    settled_objects = []
    for placement in objects:
        object_type = object_types[placement.type_name]
        settled_objects.append(placement if object_type.fixed
                               else settle(placement, "object", _box_extent(object_type.colliders)))
    return settled_robots, settled_objects
