"""Browser command `place` (docs/viewer-channel.md): drag a robot or an object to a new pose.

Checked on the I/O thread; the move itself is queued for the simulation thread and done exactly
like SIMSetRobot/SIMSetObject: the true pose changes, encoders and odometry do not notice."""

from __future__ import annotations

import math
import reprlib


def _number(value) -> bool:
    if not isinstance(value, (int, float)) or isinstance(value, bool):
        return False
    try:
        return math.isfinite(value)
    except OverflowError:  # an integer too large for a float
        return False


def _whole(value) -> bool:
    return isinstance(value, int) and not isinstance(value, bool)


def place(sim, message: dict) -> str | None:
    """Queues the move; returns an error text for a bad message, None when queued."""
    if ("robot" in message) == ("object" in message):
        return "place: give either 'robot' or 'object' (an id)"
    kind = "robot" if "robot" in message else "object"
    ident = message[kind]
    target = (sim.robot_by_id if kind == "robot" else sim.object_by_id)(ident) if _whole(ident) else None
    if target is None:
        count = len(sim.robots if kind == "robot" else sim.objects)
        return f"place: no {kind} {ident!r} (the scene has {kind}s 1..{count})" if count else \
            f"place: no {kind} {ident!r} (the scene has none)"
    x, y, phi = message.get("x"), message.get("y"), message.get("phi")
    if not (_number(x) and _number(y) and _number(phi)):
        return f"place: x, y (m) and phi (rad) must be numbers, got {reprlib.repr(x)}, {reprlib.repr(y)}, {reprlib.repr(phi)}"
    width, height = sim.floor.width, sim.floor.height
    if not (0 <= x <= width and 0 <= y <= height):
        return f"place: ({x:g}, {y:g}) is off the floor (0..{width:g} x 0..{height:g} m)"
    if kind == "robot" and target.mounted:
        return f"place: robot {ident} ({target.name}) is mounted on the floor and cannot be moved"
    if kind == "object" and target.fixed:
        return f"place: object {ident} ({target.type.name}) is fixed and cannot be moved"
    sim.call(lambda s: _move(s, kind, ident, float(x), float(y), float(phi)))
    return None


def _move(sim, kind: str, ident: int, x: float, y: float, phi: float) -> None:
    # Looked up again: the scene may have changed since the message was checked.
    target = (sim.robot_by_id if kind == "robot" else sim.object_by_id)(ident)
    if target is None:
        return
    # Set upright at its height above the floor (a submarine keeps its depth, a toppled can stands up).
    z = max(target.pose()[2], 0.0)
    target.set_pose(x, y, z, phi)
    sim.events.edit(edit="place", **{kind: ident}, x=x, y=y, phi=phi)
