"""EyeSim 6's own example scenes name robots of its stock library that we do not have
(`%sim%/robots/ModelCar/ModelCar.robi`, `%sim%/robots/Omni/Omni2.robi`): the built-in robot of the
same drive stands in, so the car drives ahead instead of spinning in place and the omni robot
slides sideways instead of turning, driven by the motors as those examples drive them.

In-process: the motors are driven as the MOTOR handler drives them and the simulation is stepped."""

import math

from support.corpus import CORPUS

from eyesim.core.engine import Simulation
from eyesim.scene import load_scene

DRIVEMODES = CORPUS / "ASAX21__VRRoboticProject/Test Assets/examples/drivemodes"


def run(scene_file: str, speeds: dict[int, int], seconds: float = 2.0):
    """Start and end pose (x, y mm, heading deg) of robot 1 with its motors at `speeds` %."""
    sim = Simulation(load_scene(DRIVEMODES / scene_file))
    robot = sim.robots[0]
    start = robot.pose_mm()
    for motor, speed in speeds.items():
        robot.motors[motor].drive(speed)
    for _ in range(round(seconds / (sim.step_us / 1e6))):
        sim.step()
    return sim, start, robot.pose_mm()


def moved(start, end, heading: float) -> tuple[float, float]:
    """(ahead, to the left) in mm between two poses, in the start heading's frame."""
    dx, dy = end[0] - start[0], end[1] - start[1]
    phi = math.radians(heading)
    return dx * math.cos(phi) + dy * math.sin(phi), -dx * math.sin(phi) + dy * math.cos(phi)


def turned(start, end) -> float:
    return (end[3] - start[3] + 180) % 360 - 180


def test_the_model_car_of_the_ackermann_example_drives_ahead_on_motor_1():
    sim, start, end = run("Ackermann.sim", {1: 50})
    assert sim.scene.robot_types["ModelCar"].drive == "ackermann"
    ahead, left = moved(start, end, start[3])
    assert ahead > 500 and abs(left) < 20  # a differential S4 on motor 1 alone turned on the spot
    assert abs(turned(start, end)) < 2


def test_the_omni_robot_of_the_omni_example_slides_sideways():
    # FL back, FR forward, BL forward, BR back: to the left (docs/robots.md)
    sim, start, end = run("Omni.sim", {1: -60, 2: 60, 3: 60, 4: -60})
    assert sim.scene.robot_types["Omni2"].drive == "omni"
    ahead, left = moved(start, end, start[3])
    assert left > 200 and abs(ahead) < 0.1 * left  # an S4 turned on the spot instead
    assert abs(turned(start, end)) < 3
