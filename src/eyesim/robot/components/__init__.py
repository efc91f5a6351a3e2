"""Registry of component kinds: each factory looks at a robot type and returns the components it needs.

Adding a component kind = one new module with a `create(context)` function + one line here. A
robot's drive (wheels, motors, steering) comes from its declared drive archetype (scene/drives),
built by robot/drives."""

from eyesim.robot import drives
from eyesim.robot.components import camera  # one import and one FACTORIES line per kind
from eyesim.robot.components import thrusters
from eyesim.robot.components import buoyancy
from eyesim.robot.components import arm
from eyesim.robot.components import gripper
from eyesim.robot.components import analog_io
from eyesim.robot.components import battery
from eyesim.robot.components import digital_io
from eyesim.robot.components import irtv
from eyesim.robot.components import keys
from eyesim.robot.components import lcd
from eyesim.robot.components import lidar
from eyesim.robot.components import psd
from eyesim.robot.components import radio
from eyesim.robot.components import serial_ports
from eyesim.robot.components import speaker
from eyesim.robot.components import timers
from eyesim.robot.components import vw

FACTORIES = (
    drives.create,
    vw.create,  # after the drive: it drives any drive with kinematics
    thrusters.create,
    buoyancy.create,
    arm.create,
    gripper.create,  # after arm: the fingers sit on its last link
    psd.create,
    lidar.create,
    camera.create,
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
