"""`eyesim run` options that script a robot's outside world: keys, touches, IR codes, serial input,
I/O levels.

Each option's text becomes an input command of eyesim.core.inputs (the same table, fields and checks as
the browser's) that takes effect at a simulation time, so headless runs and tests behave the same
every time."""

from __future__ import annotations

import re

from eyesim.core import inputs
from eyesim.robot.components.keys import KEY_NAMES
from eyesim.robot.components.serial_ports import INTERFACES, SerialPorts

AT = r"@([0-9]+(?:\.[0-9]*)?)"


def _serial_text(text: str) -> str:
    """The option's text with its Python escapes (\\n, \\xNN) resolved, one character per byte."""
    try:
        return text.encode("latin-1").decode("unicode_escape")
    except (UnicodeError, ValueError):
        raise ValueError("the text must be Latin-1 with Python escapes (\\n, \\xNN)") from None


# Option -> (pattern of its text, an example, the input command from the pattern's groups but the
# robot and the time: the first and the last group).
OPTIONS = {
    "key": (r"(\w+):(KEY[1-4])" + AT, "1:KEY1@2.5", lambda g: {"type": "key", "key": KEY_NAMES[g[0].upper()]}),
    "touch": (r"(\w+):(\d+),(\d+)" + AT, "1:100,50@2.5", lambda g: {"type": "touch", "x": int(g[0]), "y": int(g[1])}),
    "irtv": (r"(\w+):([^@]+)" + AT, "1:OK@1.5", lambda g: {"type": "irtv", "code": g[0]}),
    "serial": (
        r"(\w+):(\d+):(.*)" + AT,
        "1:0:hello\\n@2",
        lambda g: {"type": "serial", "interface": int(g[0]), "text": _serial_text(g[1])},
    ),
    "digital": (
        r"(\w+):(\d+)=([01-])" + AT,
        "1:3=1@0.5",
        lambda g: {"type": "digital", "line": int(g[0]), "level": None if g[1] == "-" else int(g[1])},
    ),
    "analog": (
        r"(\w+):(\d+)=(\d+)" + AT,
        "1:2=700@0.5",
        lambda g: {"type": "analog", "channel": int(g[0]), "value": int(g[1])},
    ),
}


def schedule_inputs(sim, args, find_robot) -> None:
    """Schedules every scripted input of `args`; ValueError names a bad one.
    `find_robot(selector)` turns an id or a name into the robot."""
    for option, (pattern, example, command_of) in OPTIONS.items():
        for text in getattr(args, option):
            match = re.fullmatch(pattern, text.strip(), flags=re.DOTALL | re.IGNORECASE)
            if not match:
                raise ValueError(f"--{option} {text!r}: expected e.g. {example}")
            try:
                command = {**command_of(match.groups()[1:-1]), "robot": find_robot(match[1]).id}
                action = inputs.prepare(sim, command)
            except ValueError as error:
                raise ValueError(f"--{option} {text!r}: {error}") from None
            sim.schedule(round(float(match.groups()[-1]) * 1e6), action)
    for text in args.serial_loopback:
        match = re.fullmatch(r"(\w+):(\d+)", text.strip())
        if not match:
            raise ValueError(f"--serial-loopback {text!r}: expected e.g. 1:0")
        robot, interface = find_robot(match[1]), int(match[2])
        if interface not in INTERFACES:
            raise ValueError(f"--serial-loopback {text!r}: the interface is not 0..20")
        robot.component(SerialPorts).port(interface).loopback = True
