"""Checking and completing a RobotType, whether it came from a .robi file or from JSON."""

from __future__ import annotations

import dataclasses

from eyesim.robot.drives import drive_of
from eyesim.scene.description import Location, RobotType, WheelSpec
from eyesim.scene.diagnostics import Diagnostics
from eyesim.scene.lexer import format_number

DEFAULT_WHEELS = WheelSpec(54.0, 3600.0, 1100, 90.0)  # the S4's
MAX_DENSITY = 8.0  # g/cm3: a robot heavier than solid steel of its size is a typo
ESTIMATED_DENSITY = 0.5  # g/cm3 of a typical small robot (S4: 0.8 kg in 2.4 litres)


def finish_robot_type(robot: RobotType, diagnostics: Diagnostics, where: dict[str, Location],
                      default_location: Location) -> RobotType:
    """Report contradictions (errors) and fill in what a usable robot needs (warnings).
    `where` maps a field name ('wheels', 'mass', 'psd:<i>', ...) to where it was written."""
    at = lambda key: where.get(key, default_location)  # noqa: E731 - short local lookup
    changes = {}
    drive = drive_of(robot)
    if drive.wheeled and robot.wheels is None:
        diagnostics.warning(at("drive"), f"a {robot.drive} robot needs a 'wheel' line; using the S4's wheels "
                            "(54 mm, 3600 deg/s, 1100 ticks, track 90 mm)", "missing-wheels")
        changes["wheels"] = DEFAULT_WHEELS
    immobile = drive.check(robot)
    if immobile is not None:
        diagnostics.warning(at("drive"), *immobile)
    volume = robot.length * robot.width * robot.height / 1000.0  # cm3
    if volume > 0 and robot.mass * 1000.0 / volume > MAX_DENSITY:
        estimate = float(f"{volume * ESTIMATED_DENSITY / 1000.0:.2g}")  # two significant digits
        diagnostics.warning(at("mass"), f"mass {format_number(robot.mass)} kg is impossible for a "
                            f"{format_number(robot.length)} x {format_number(robot.width)} x "
                            f"{format_number(robot.height)} mm robot (denser than steel); using "
                            f"{format_number(estimate)} kg instead", "implausible-mass")
        changes["mass"] = estimate
    _check_psds(robot, diagnostics, at)
    _check_servos(robot, diagnostics, at)
    _check_motors(robot, diagnostics, at)
    if robot.arm is not None:
        for i, joint in enumerate(robot.arm.joints):
            if joint.min > joint.max:
                diagnostics.error(at(f"joint:{i}"), f"joint {joint.name}: expected min <= max, found "
                                  f"{format_number(joint.min)} > {format_number(joint.max)}", "bad-value")
    for i, psd in enumerate(robot.psds):
        if psd.z < 0:
            diagnostics.warning(at(f"psd:{i}"), f"{psd.name} sits {format_number(-psd.z)} mm below the floor "
                                f"(z = {format_number(psd.z)}); kept as written", "below-floor")
    return dataclasses.replace(robot, **changes) if changes else robot


def _check_psds(robot: RobotType, diagnostics: Diagnostics, at) -> None:
    seen: dict[int, str] = {}
    for i, psd in enumerate(robot.psds):
        if psd.id in seen:
            diagnostics.error(at(f"psd:{i}"), f"PSD id {psd.id} of {psd.name} is already used by {seen[psd.id]}: "
                              "expected a different id", "duplicate")
        seen.setdefault(psd.id, psd.name)


def _check_servos(robot: RobotType, diagnostics: Diagnostics, at) -> None:
    users: list[tuple[int, str, str]] = []
    if robot.camera is not None:
        if robot.camera.pan_servo is not None:
            users.append((robot.camera.pan_servo, "camera pan", "camera"))
        if robot.camera.tilt_servo is not None:
            users.append((robot.camera.tilt_servo, "camera tilt", "camera"))
    if robot.arm is not None:
        for i, joint in enumerate(robot.arm.joints):
            users.append((joint.servo, f"joint {joint.name}", f"joint:{i}"))
        if robot.arm.gripper is not None:
            users.append((robot.arm.gripper.servo, "the gripper", "gripper"))
    seen: dict[int, str] = {}
    for servo, user, key in users:
        if servo < 1:
            diagnostics.error(at(key), f"{user}: expected a servo number from 1, found {servo}", "bad-value")
        elif servo in seen:
            diagnostics.error(at(key), f"servo {servo} of {user} is already used by {seen[servo]}", "duplicate")
        seen.setdefault(servo, user)


def _check_motors(robot: RobotType, diagnostics: Diagnostics, at) -> None:
    seen: dict[int, str] = {}
    for i, thruster in enumerate(robot.thrusters):
        if thruster.motor < 1:
            diagnostics.error(at(f"thruster:{i}"), f"thruster {thruster.name}: expected a motor number from 1, "
                              f"found {thruster.motor}", "bad-value")
        elif thruster.motor in seen:
            diagnostics.error(at(f"thruster:{i}"), f"motor {thruster.motor} of thruster {thruster.name} is "
                              f"already used by {seen[thruster.motor]}", "duplicate")
        if (thruster.dx, thruster.dy, thruster.dz) == (0, 0, 0):
            diagnostics.error(at(f"thruster:{i}"), f"thruster {thruster.name}: expected a direction, found 0 0 0",
                              "bad-value")
        seen.setdefault(thruster.motor, thruster.name)
