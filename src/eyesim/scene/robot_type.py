"""Checking and completing a RobotType, whether it came from a .robi file or from JSON: each part
kind checks its own fields (scene/parts/), and servos shared between parts are caught here."""

from __future__ import annotations

import dataclasses

from eyesim.scene.description import Location, RobotType
from eyesim.scene.diagnostics import Diagnostics
from eyesim.scene.parts import PARTS


def finish_robot_type(
    robot: RobotType, diagnostics: Diagnostics, where: dict[str, Location], default_location: Location
) -> RobotType:
    """Report contradictions (errors) and fill in what a usable robot needs (warnings).
    `where` maps a field name ('wheels', 'mass', 'psd:<i>', ...) to where it was written."""
    at = lambda key: where.get(key, default_location)  # noqa: E731 - short local lookup
    changes = {}
    for part in PARTS:
        changes.update(part.check(robot, diagnostics, at))
    _check_servos(robot, diagnostics, at)
    return dataclasses.replace(robot, **changes) if changes else robot


def _check_servos(robot: RobotType, diagnostics: Diagnostics, at) -> None:
    seen: dict[int, str] = {}
    for servo, user, key in (user for part in PARTS for user in part.servos(robot)):
        if servo < 1:
            diagnostics.error(at(key), f"{user}: expected a servo number from 1, found {servo}", "bad-value")
        elif servo in seen:
            diagnostics.error(at(key), f"servo {servo} of {user} is already used by {seen[servo]}", "duplicate")
        seen.setdefault(servo, user)
