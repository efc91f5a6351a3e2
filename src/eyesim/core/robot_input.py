"""What input from outside does to a robot: keys, touches, IR codes, serial bytes, digital and
analog levels. Run on the simulation thread, after eyesim.core.inputs checked the input (from the
viewer, `eyesim run` options or the testing API); a robot that lost the part meanwhile raises
ValueError."""

from __future__ import annotations

from eyesim.robot.components.analog_io import AnalogInputs
from eyesim.robot.components.digital_io import DigitalLines
from eyesim.robot.components.irtv import IrReceiver
from eyesim.robot.components.keys import Keys
from eyesim.robot.components.lcd import Lcd
from eyesim.robot.components.serial_ports import SerialPorts


def _part(sim, robot_id: int, cls, what: str):
    robot = sim.robot_by_id(robot_id)
    if robot is None:
        raise ValueError(f"no robot {robot_id}")
    part = robot.component(cls)
    if part is None:
        raise ValueError(f"robot {robot_id} has no {what}")
    return robot, part


def key(sim, robot_id: int, key: int) -> None:
    """A soft-key press (KEY1..KEY4), as KEYGet/KEYRead see it."""
    _part(sim, robot_id, Keys, "keys")[1].press(key)
    sim.events.input(robot_id, "key", key=key)


def touch(sim, robot_id: int, x: int, y: int) -> None:
    """A touch on the LCD at pixel (x, y): on the shown menu bar it presses that soft key,
    anywhere else it is a touch for KEYGetXY/KEYReadXY."""
    robot, keys = _part(sim, robot_id, Keys, "touch screen")
    lcd = robot.component(Lcd)
    key = lcd.menu_key_at(x, y) if lcd is not None else None
    if key is not None:
        keys.press(key)
    else:
        keys.touch(x, y)
    sim.events.input(robot_id, "touch", x=x, y=y)


def irtv(sim, robot_id: int, code: int) -> None:
    _part(sim, robot_id, IrReceiver, "IR receiver")[1].receive(code)
    sim.events.input(robot_id, "irtv", code=code)


def serial(sim, robot_id: int, interface: int, data: bytes) -> None:
    _part(sim, robot_id, SerialPorts, "serial interfaces")[1].deliver(interface, data)
    sim.events.input(robot_id, "serial", interface=interface, text=data.decode("latin-1"))


def digital(sim, robot_id: int, line: int, level: int | None) -> None:
    robot, lines = _part(sim, robot_id, DigitalLines, "digital I/O")
    lines.drive(line, level)
    sim.events.input(robot_id, "digital", line=line, level=level)
    sim.events.io(robot)


def analog(sim, robot_id: int, channel: int, value: int) -> None:
    robot, inputs = _part(sim, robot_id, AnalogInputs, "analog inputs")
    inputs.set_value(channel, value, sim.time_us)
    sim.events.input(robot_id, "analog", channel=channel, value=value)
    sim.events.io(robot)
