"""Short human-readable summaries of loaded scenes, worlds, robots and objects (`eyesim check`)."""

from __future__ import annotations

from collections import Counter
from pathlib import Path

from eyesim.scene.description import ObjectType, RobotType, Scene, World
from eyesim.scene.lexer import format_number as f


def world_lines(world: World) -> list[str]:
    if world.floor_width is not None and world.floor_height is not None:
        floor = f"floor {f(world.floor_width)} x {f(world.floor_height)} mm"
    else:
        floor = "no floor size"
    lines = [f"world {Path(world.source).name}: {floor}, {len(world.walls)} wall{'s' if len(world.walls) != 1 else ''}"]
    if world.walls:
        xs = [v for w in world.walls for v in (w.x1, w.x2)]
        ys = [v for w in world.walls for v in (w.y1, w.y2)]
        lines[-1] += f" within x {f(min(xs))}..{f(max(xs))}, y {f(min(ys))}..{f(max(ys))}"
    if world.floor_texture:
        lines.append(f"floor texture {Path(world.floor_texture).name}")
    if world.start_pose:
        lines.append(f"start position {_pose(world.start_pose)}")
    if world.start_positions:
        lines.append("maze starts " + ", ".join(f"{s.letter} {_pose(s.pose)}" for s in world.start_positions))
    return lines


def scene_lines(scene: Scene) -> list[str]:
    lines = world_lines(scene.world)
    for robot in scene.robots:
        program = f" running {Path(robot.program).name}" if robot.program else ""
        lines.append(f"robot {robot.type_name} at {_pose(robot.pose)}{program}")
    if scene.objects:
        counts = Counter(o.type_name for o in scene.objects)
        lines.append(f"objects: {len(scene.objects)} (" + ", ".join(f"{n} x{c}" for n, c in counts.items()) + ")")
    if scene.markers:
        lines.append(f"markers: {len(scene.markers)}")
    flags = [
        n
        for n, on in (
            ("VIS", scene.settings.vis),
            ("TRACE", scene.settings.trace),
            ("EYESIM6PSD", scene.settings.eyesim6_psd),
        )
        if on
    ]
    if flags:
        lines.append("settings " + " ".join(flags))
    return lines


def robot_lines(robot: RobotType) -> list[str]:
    line = (
        f"robot type {robot.name}: {robot.drive} drive, {f(robot.length)} x {f(robot.width)} x "
        f"{f(robot.height)} mm, {f(robot.mass)} kg"
    )
    if robot.wheels:
        line += f", wheels {f(robot.wheels.diameter)} mm on a {f(robot.wheels.track)} mm track"
    lines = [line]
    parts = []
    if robot.psds:
        parts.append(
            f"{len(robot.psds)} PSD{'s' if len(robot.psds) != 1 else ''} ("
            + ", ".join(f"{p.id} {p.name}" for p in robot.psds)
            + ")"
        )
    if robot.camera:
        parts.append("fisheye camera" if robot.camera.fisheye else "camera")
    if robot.lidar:
        parts.append(f"lidar {robot.lidar.points} points")
    if robot.thrusters:
        parts.append(f"{len(robot.thrusters)} thrusters")
    if robot.arm:
        parts.append(f"arm with {len(robot.arm.joints)} joints" + (" and a gripper" if robot.arm.gripper else ""))
    if parts:
        lines.append(", ".join(parts))
    return lines


def object_lines(obj: ObjectType) -> list[str]:
    model = Path(obj.model).name if obj.model else "no model"
    fixed = ", fixed" if obj.fixed else ""
    return [
        f"object type {obj.name}: {f(obj.mass)} kg, {len(obj.colliders)} collider"
        f"{'s' if len(obj.colliders) != 1 else ''}, {model}{fixed}"
    ]


def _pose(pose) -> str:
    return f"({f(pose.x)}, {f(pose.y)}, {f(pose.phi)} deg)"
