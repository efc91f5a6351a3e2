"""`eyesim run` options that script a robot's outside world: touches, IR codes, serial input, I/O levels.

Each takes effect at a simulation time, so headless runs and tests behave the same every time."""

from __future__ import annotations

import re

from eyesim import robot_input
from eyesim.robot.components.analog_io import CHANNELS, MAX_VALUE
from eyesim.robot.components.digital_io import LINES
from eyesim.robot.components.irtv import code_of
from eyesim.robot.components.lcd import HEIGHT, WIDTH
from eyesim.robot.components.serial_ports import INTERFACES, SerialPorts

AT = r"@([0-9]+(?:\.[0-9]*)?)"


def add_arguments(parser) -> None:
    parser.add_argument("--touch", action="append", default=[], metavar="ROBOT:X,Y@SECONDS",
                        help="touch the LCD at pixel X,Y at a simulation time, e.g. 1:100,50@2; repeatable")
    parser.add_argument("--irtv", action="append", default=[], metavar="ROBOT:BUTTON@SECONDS",
                        help="press an IR remote button (0-9, RED, GREEN, YELLOW, BLUE, LEFT, RIGHT, UP, DOWN, "
                             "OK, POWER) at a simulation time, e.g. 1:OK@1.5; repeatable")
    parser.add_argument("--serial", action="append", default=[], metavar="ROBOT:INTERFACE:TEXT@SECONDS",
                        help="bytes arriving on a serial interface at a simulation time; TEXT may use \\n, \\r, "
                             "\\xNN; e.g. '1:0:hello\\n@2'; repeatable")
    parser.add_argument("--serial-loopback", action="append", default=[], metavar="ROBOT:INTERFACE",
                        help="plug a loopback into a serial interface: what the robot sends comes back")
    parser.add_argument("--digital", action="append", default=[], metavar="ROBOT:LINE=LEVEL@SECONDS",
                        help="drive digital input line 1..16 to 0 or 1 (- lets go) at a simulation time; repeatable")
    parser.add_argument("--analog", action="append", default=[], metavar="ROBOT:CHANNEL=VALUE@SECONDS",
                        help="set analog channel 1..8 to 0..1023 at a simulation time; repeatable")


def _match(pattern: str, text: str, option: str, example: str) -> re.Match:
    match = re.fullmatch(pattern, text.strip(), flags=re.DOTALL)
    if not match:
        raise ValueError(f"{option} {text!r}: expected e.g. {example}")
    return match


def _at(sim, seconds: str, action) -> None:
    sim.schedule(round(float(seconds) * 1e6), action)


def _check(ok: bool, option: str, text: str, problem: str) -> None:
    if not ok:
        raise ValueError(f"{option} {text!r}: {problem}")


def schedule_inputs(sim, args, find_robot) -> None:
    """Schedules every scripted input of `args`; ValueError names a bad one.
    `find_robot(selector)` turns an id or a name into the robot."""
    for text in args.touch:
        m = _match(r"(\w+):(\d+),(\d+)" + AT, text, "--touch", "1:100,50@2.5")
        robot, x, y = find_robot(m[1]).id, int(m[2]), int(m[3])
        _check(x < WIDTH and y < HEIGHT, "--touch", text, f"outside the {WIDTH}x{HEIGHT} LCD")
        _at(sim, m[4], lambda s, r=robot, x=x, y=y: robot_input.touch(s, r, x, y))
    for text in args.irtv:
        m = _match(r"(\w+):([^@]+)" + AT, text, "--irtv", "1:OK@1.5")
        robot = find_robot(m[1]).id
        try:
            code = code_of(m[2])
        except ValueError as error:
            raise ValueError(f"--irtv {text!r}: {error}") from None
        _at(sim, m[3], lambda s, r=robot, c=code: robot_input.irtv(s, r, c))
    for text in args.serial:
        m = _match(r"(\w+):(\d+):(.*)" + AT, text, "--serial", "1:0:hello\\n@2")
        robot, interface = find_robot(m[1]).id, int(m[2])
        _check(interface in INTERFACES, "--serial", text, "the interface is not 0..20")
        try:
            data = m[3].encode("latin-1").decode("unicode_escape").encode("latin-1")
        except (UnicodeError, ValueError):
            raise ValueError(f"--serial {text!r}: the text must be Latin-1 with Python escapes (\\n, \\xNN)") from None
        _at(sim, m[4], lambda s, r=robot, i=interface, d=data: robot_input.serial(s, r, i, d))
    for text in args.serial_loopback:
        m = _match(r"(\w+):(\d+)", text, "--serial-loopback", "1:0")
        robot, interface = find_robot(m[1]), int(m[2])
        _check(interface in INTERFACES, "--serial-loopback", text, "the interface is not 0..20")
        robot.component(SerialPorts).port(interface).loopback = True
    for text in args.digital:
        m = _match(r"(\w+):(\d+)=([01-])" + AT, text, "--digital", "1:3=1@0.5")
        robot, line, level = find_robot(m[1]).id, int(m[2]), None if m[3] == "-" else int(m[3])
        _check(1 <= line <= LINES, "--digital", text, f"the line is not 1..{LINES}")
        _at(sim, m[4], lambda s, r=robot, n=line, v=level: robot_input.digital(s, r, n, v))
    for text in args.analog:
        m = _match(r"(\w+):(\d+)=(\d+)" + AT, text, "--analog", "1:2=700@0.5")
        robot, channel, value = find_robot(m[1]).id, int(m[2]), int(m[3])
        _check(1 <= channel <= CHANNELS, "--analog", text, f"the channel is not 1..{CHANNELS}")
        _check(value <= MAX_VALUE, "--analog", text, f"the value is not 0..{MAX_VALUE}")
        _at(sim, m[4], lambda s, r=robot, c=channel, v=value: robot_input.analog(s, r, c, v))
