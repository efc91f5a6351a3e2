"""Browser commands for a robot's outside world (docs/viewer-channel.md): touch, irtv, serial, digital, analog.

Each checks its message on the I/O thread and queues the input for the simulation thread
(eyesim.robot_input); it returns an error text for a bad message, None when queued."""

from __future__ import annotations

from eyesim import robot_input
from eyesim.robot.components.analog_io import CHANNELS, MAX_VALUE
from eyesim.robot.components.digital_io import LINES
from eyesim.robot.components.irtv import code_of
from eyesim.robot.components.lcd import HEIGHT, WIDTH
from eyesim.robot.components.serial_ports import INTERFACES


def _integer(value, low: int, high: int) -> bool:
    return isinstance(value, int) and not isinstance(value, bool) and low <= value <= high


def _robot_error(sim, message: dict) -> str | None:
    robot = message.get("robot")
    if not _integer(robot, 1, len(sim.robots)):
        return f"{message['type']}: no robot {robot!r}"
    return None


def touch(sim, message: dict) -> str | None:
    x, y = message.get("x"), message.get("y")
    if not (_integer(x, 0, WIDTH - 1) and _integer(y, 0, HEIGHT - 1)):
        return f"touch: ({x!r}, {y!r}) is not a pixel of the {WIDTH}x{HEIGHT} LCD"
    robot = message["robot"]
    sim.call(lambda s: robot_input.touch(s, robot, x, y))
    return None


def irtv(sim, message: dict) -> str | None:
    button = message.get("code")
    if not isinstance(button, str):
        return f"irtv: code {button!r} is not a button name or an IRTV code character"
    try:
        code = code_of(button)
    except ValueError as error:
        return f"irtv: {error}"
    robot = message["robot"]
    sim.call(lambda s: robot_input.irtv(s, robot, code))
    return None


def serial(sim, message: dict) -> str | None:
    interface, text = message.get("interface"), message.get("text")
    if not _integer(interface, INTERFACES.start, INTERFACES.stop - 1):
        return f"serial: interface {interface!r} is not 0..20"
    try:
        data = text.encode("latin-1")  # one character per byte (docs/viewer-channel.md)
    except (AttributeError, UnicodeError):
        return "serial: text must be a string of characters U+0000..U+00FF (one per byte)"
    robot = message["robot"]
    sim.call(lambda s: robot_input.serial(s, robot, interface, data))
    return None


def digital(sim, message: dict) -> str | None:
    line, level = message.get("line"), message.get("level")
    if not _integer(line, 1, LINES):
        return f"digital: line {line!r} is not 1..{LINES}"
    if level is not None and not _integer(level, 0, 1):
        return f"digital: level {level!r} is not 0, 1 or null"
    robot = message["robot"]
    sim.call(lambda s: robot_input.digital(s, robot, line, level))
    return None


def analog(sim, message: dict) -> str | None:
    channel, value = message.get("channel"), message.get("value")
    if not _integer(channel, 1, CHANNELS):
        return f"analog: channel {channel!r} is not 1..{CHANNELS}"
    if not _integer(value, 0, MAX_VALUE):
        return f"analog: value {value!r} is not 0..{MAX_VALUE}"
    robot = message["robot"]
    sim.call(lambda s: robot_input.analog(s, robot, channel, value))
    return None


COMMANDS = {"touch": touch, "irtv": irtv, "serial": serial, "digital": digital, "analog": analog}


def command(sim, message: dict) -> str | None:
    """Handles one of COMMANDS; returns an error text for a bad message."""
    return _robot_error(sim, message) or COMMANDS[message["type"]](sim, message)
