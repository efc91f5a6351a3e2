"""Input a robot or the scene gets from outside, in one table for every source: the browser, the
`eyesim run` options (--key, --touch, --irtv, --serial, --digital, --analog) and the testing API.

Each input is a command of the viewer channel, so its fields and ranges are declared once, in
interface/viewer.schema.json, and every source checks them with the same validator; what depends
on the world (the robot exists, an IR button's name, a fixed object) is checked here.
`prepare` turns a command into the action the simulation thread carries out (eyesim.core.robot_input)."""

from __future__ import annotations

import math
from typing import Callable

from eyesim.core import robot_input
from eyesim.protocol import channel_schema
from eyesim.robot.components.irtv import code_of

Action = Callable[[object], None]


class InputError(ValueError):
    """An input that cannot be carried out; the text says why in one sentence."""


def _key(sim, command: dict) -> Action:
    robot, key = command["robot"], command["key"]
    return lambda s: robot_input.key(s, robot, key)


def _touch(sim, command: dict) -> Action:
    robot, x, y = command["robot"], command["x"], command["y"]
    return lambda s: robot_input.touch(s, robot, x, y)


def _irtv(sim, command: dict) -> Action:
    try:
        code = code_of(command["code"])
    except ValueError as error:
        raise InputError(f"irtv: {error}") from None
    robot = command["robot"]
    return lambda s: robot_input.irtv(s, robot, code)


def _serial(sim, command: dict) -> Action:
    robot, interface = command["robot"], command["interface"]
    data = command["text"].encode("latin-1")  # one character per byte (the schema allows no others)
    return lambda s: robot_input.serial(s, robot, interface, data)


def _digital(sim, command: dict) -> Action:
    robot, line, level = command["robot"], command["line"], command["level"]
    return lambda s: robot_input.digital(s, robot, line, level)


def _analog(sim, command: dict) -> Action:
    robot, channel, value = command["robot"], command["channel"], command["value"]
    return lambda s: robot_input.analog(s, robot, channel, value)


def _place(sim, command: dict) -> Action:
    """Drag a robot or an object to a new pose, exactly like SIMSetRobot/SIMSetObject: the true
    pose changes, encoders and odometry do not notice."""
    if ("robot" in command) == ("object" in command):
        raise InputError("place: give either 'robot' or 'object' (an id)")
    kind = "robot" if "robot" in command else "object"
    ident = command[kind]
    target = (sim.robot_by_id if kind == "robot" else sim.object_by_id)(ident)
    if target is None:
        count = len(sim.robots if kind == "robot" else sim.objects)
        raise InputError(
            f"place: no {kind} {ident!r} (the scene has {kind}s 1..{count})"
            if count
            else f"place: no {kind} {ident!r} (the scene has none)"
        )
    x, y, phi = (_finite(command[name]) for name in ("x", "y", "phi"))
    width, height = sim.floor.width, sim.floor.height
    if not (0 <= x <= width and 0 <= y <= height):
        raise InputError(f"place: ({x:g}, {y:g}) is off the floor (0..{width:g} x 0..{height:g} m)")
    if kind == "robot" and target.mounted:
        raise InputError(f"place: robot {ident} ({target.name}) is mounted on the floor and cannot be moved")
    if kind == "object" and target.fixed:
        raise InputError(f"place: object {ident} ({target.type.name}) is fixed and cannot be moved")
    return lambda s: _move(s, kind, ident, x, y, phi)


def _finite(value) -> float:
    """A JSON number as a float; a whole number too large for one is off every floor."""
    try:
        return float(value)
    except OverflowError:
        return math.inf


def _move(sim, kind: str, ident: int, x: float, y: float, phi: float) -> None:
    # Looked up again: the scene may have changed since the command was checked.
    target = (sim.robot_by_id if kind == "robot" else sim.object_by_id)(ident)
    if target is None:
        return
    # Set upright at its height above the floor (a submarine keeps its depth, a toppled can stands up).
    z = max(target.pose()[2], 0.0)
    target.set_pose(x, y, z, phi)
    sim.events.edit(edit="place", **{kind: ident}, x=x, y=y, phi=phi)


# The inputs: viewer-channel command type -> what checks it against the world and makes its action.
INPUTS: dict[str, Callable[[object, dict], Action]] = {
    "key": _key,
    "touch": _touch,
    "irtv": _irtv,
    "serial": _serial,
    "digital": _digital,
    "analog": _analog,
    "place": _place,
}


def prepare(sim, command: dict, checked: bool = False) -> Action:
    """The action for an input command; InputError says why it cannot be carried out.
    `checked`: the command already passed the schema (the browser's commands have)."""
    problem = None if checked else channel_schema.command_problem(command)
    if problem:
        raise InputError(problem)
    kind = command["type"]
    if kind not in INPUTS:
        raise InputError(f"{kind!r} is not an input ({', '.join(INPUTS)})")
    if kind != "place" and sim.robot_by_id(command["robot"]) is None:
        raise InputError(f"{kind}: no robot {command['robot']!r}")
    return INPUTS[kind](sim, command)
