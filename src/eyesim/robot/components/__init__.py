"""Registry of component kinds: each factory looks at a robot type and returns the components it needs.

A robot is built from, in this order: its drive (the wheels its declared drive archetype names,
scene/drives, built by robot/wheels) and the VW controller that drives it; the components of its
parts, which each part declaration names (parts/<kind>/declaration.py: a new part kind needs no
line here); and the parts of the robot's computer that every robot has, listed below (a new one of
those = one new module with a `create(context)` function + one line here)."""

from __future__ import annotations

from eyesim.robot import wheels
from eyesim.robot.component import named
from eyesim.robot.components import analog_io
from eyesim.robot.components import battery
from eyesim.robot.components import digital_io
from eyesim.robot.components import irtv
from eyesim.robot.components import keys
from eyesim.robot.components import lcd
from eyesim.robot.components import radio
from eyesim.robot.components import serial_ports
from eyesim.robot.components import speaker
from eyesim.robot.components import timers
from eyesim.robot.components import vw
from eyesim.scene.parts import PARTS


COMPUTER = (
    radio.create,
    lcd.create,
    keys.create,
    timers.create,
    speaker.create,
    serial_ports.create,
    digital_io.create,
    analog_io.create,
    battery.create,
    irtv.create,
)


def factories() -> tuple:
    """The factories, in the order they build a robot. The parts' are looked up here, not when this
    package is imported: a part's component may import a module of it (a bumper, digital_io)."""
    return (
        wheels.create,
        vw.create,  # after the drive: it drives any drive with kinematics
        *(named(name) for part in PARTS for name in part.components),
        *COMPUTER,
    )
