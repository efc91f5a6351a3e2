"""Submarine (SUBMARINE): no wheels; its `thruster` lines move it and its `buoyancy` line floats it
(the thrusters and buoyancy components), and a scene with one is under water."""

from eyesim.scene.drives.archetype import DriveArchetype


def check(robot) -> tuple[str, str] | None:
    return None if robot.thrusters else ("a submarine without 'thruster' lines cannot move", "no-thrusters")


DRIVE = DriveArchetype(
    "submarine",
    "SUBMARINE",
    noun="a submarine",
    aliases=("submarine_drive",),
    swims=True,
    parts=("thrusters", "buoyancy", "drag", "start_depth"),
    check=check,
)
