"""Browser commands for a robot's outside world (docs/viewer-channel.md): touch, irtv, serial, digital, analog.

Their fields were checked against the viewer schema (ranges included, see
tests/web/test_viewer_command_checks.py); here each is checked against the world on the I/O
thread and queued for the simulation thread (eyesim.robot_input). Each returns an error text for
a command the world refuses, None when queued."""

from __future__ import annotations

from eyesim import robot_input
from eyesim.robot.components.irtv import code_of


def touch(sim, message: dict) -> str | None:
    robot, x, y = message["robot"], message["x"], message["y"]
    sim.call(lambda s: robot_input.touch(s, robot, x, y))
    return None


def irtv(sim, message: dict) -> str | None:
    try:
        code = code_of(message["code"])
    except ValueError as error:
        return f"irtv: {error}"
    robot = message["robot"]
    sim.call(lambda s: robot_input.irtv(s, robot, code))
    return None


def serial(sim, message: dict) -> str | None:
    robot, interface = message["robot"], message["interface"]
    data = message["text"].encode("latin-1")  # one character per byte (the schema allows no others)
    sim.call(lambda s: robot_input.serial(s, robot, interface, data))
    return None


def digital(sim, message: dict) -> str | None:
    robot, line, level = message["robot"], message["line"], message["level"]
    sim.call(lambda s: robot_input.digital(s, robot, line, level))
    return None


def analog(sim, message: dict) -> str | None:
    robot, channel, value = message["robot"], message["channel"], message["value"]
    sim.call(lambda s: robot_input.analog(s, robot, channel, value))
    return None


COMMANDS = {"touch": touch, "irtv": irtv, "serial": serial, "digital": digital, "analog": analog}


def command(sim, message: dict) -> str | None:
    """Handles one of COMMANDS; returns an error text for a command the world refuses."""
    if sim.robot_by_id(message["robot"]) is None:
        return f"{message['type']}: no robot {message['robot']!r}"
    return COMMANDS[message["type"]](sim, message)
