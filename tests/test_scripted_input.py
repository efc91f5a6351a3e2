"""`eyesim run`'s scripted input options: what they schedule, and clear errors for bad ones."""

from argparse import Namespace

import pytest
from support.scenes import arena

from eyesim.app.scripted_input import schedule_inputs
from eyesim.core.clock import DETERMINISTIC, Clock
from eyesim.core.engine import Simulation
from eyesim.robot.components.analog_io import AnalogInputs
from eyesim.robot.components.digital_io import DigitalLines
from eyesim.robot.components.irtv import IrReceiver
from eyesim.robot.components.keys import KEY2, Keys
from eyesim.robot.components.serial_ports import SerialPorts


def options(**given) -> Namespace:
    values = {name: [] for name in ("key", "touch", "irtv", "serial", "serial_loopback", "digital", "analog")}
    return Namespace(**(values | given))


def find_robot(sim):
    def find(selector):
        robot = sim.robot_by_id(int(selector)) if selector.isdigit() else None
        if robot is None:
            raise ValueError(f"no robot {selector!r}")
        return robot

    return find


def test_each_option_takes_effect_at_its_simulation_time():
    sim = Simulation(arena(), Clock(DETERMINISTIC))
    schedule_inputs(
        sim,
        options(
            key=["1:key2@0.01"],
            touch=["1:100,50@0.01"],
            irtv=["1:ok@0.01", "1:>@0.01"],
            serial=["1:3:a\\x41\\n@0.01"],
            serial_loopback=["1:4"],
            digital=["1:2=1@0.01"],
            analog=["1:8=1023@0.01"],
        ),
        find_robot(sim),
    )
    robot = sim.robots[0]
    assert robot.component(SerialPorts).port(4).loopback
    sim.run(until=0.008)
    assert not robot.component(Keys).touches  # not yet
    sim.run(until=0.012)
    assert list(robot.component(Keys).touches) == [(100, 50)]
    assert robot.component(Keys).take() == KEY2
    assert list(robot.component(IrReceiver).codes) == [ord("O"), ord(">")]
    assert robot.component(SerialPorts).port(3).received == b"aA\n"
    assert robot.component(DigitalLines).read(2) == 1
    assert robot.component(AnalogInputs).read(8) == 1023


@pytest.mark.parametrize(
    "option, value, message",
    [
        ("touch", "1:480,0@1", "x must be a whole number from 0 to 479, not 480"),
        ("touch", "1:10,10", "expected e.g. 1:100,50@2.5"),
        ("irtv", "1:PLAY@1", "'PLAY' is not an IR remote button"),
        ("serial", "1:21:x@1", "interface must be a whole number from 0 to 20, not 21"),
        ("serial", "1:0:\u20ac@1", "must be Latin-1"),
        ("serial_loopback", "1:x", "expected e.g. 1:0"),
        ("digital", "1:17=1@1", "line must be a whole number from 1 to 16, not 17"),
        ("digital", "1:1=2@1", "expected e.g. 1:3=1@0.5"),
        ("analog", "1:9=1@1", "channel must be a whole number from 1 to 8, not 9"),
        ("analog", "1:2=1024@1", "value must be a whole number from 0 to 1023, not 1024"),
        ("key", "1:KEY5@1", "expected e.g. 1:KEY1@2.5"),
        ("analog", "2:2=1@1", "no robot '2'"),
    ],
)
def test_bad_options_are_refused_with_what_is_wrong(option, value, message):
    sim = Simulation(arena())
    with pytest.raises(ValueError, match=message):
        schedule_inputs(sim, options(**{option: [value]}), find_robot(sim))


def test_an_option_is_checked_as_the_browser_command_it_becomes():
    """One table of inputs: the same fields, ranges and sentence for `eyesim run` and the viewer."""
    from eyesim.protocol.channel_schema import command_problem

    sim = Simulation(arena())
    browser = command_problem({"type": "touch", "robot": 1, "x": 480, "y": 0})
    with pytest.raises(ValueError) as refused:
        schedule_inputs(sim, options(touch=["1:480,0@1"]), find_robot(sim))
    assert str(refused.value) == f"--touch '1:480,0@1': {browser}"
