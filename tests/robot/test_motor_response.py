"""Open-loop motors follow a MOTORDrive step within 0.1 s on every wheeled drive type, as EyeSim's
motors do (timed MOTORDrive programs depend on it), and MOTORDrive(m, 0) stops the wheel.

In-process: the motors are driven as the MOTOR handler drives them and the simulation is stepped
directly, so the wheels' speeds can be read at exact times."""

import pytest
from support.worlds import arena_scene, example_robot

from eyesim.core.engine import Simulation

MOTORS = {"S4": (1, 2), "LabBot": (1, 2), "Car": (1,), "Mecanum": (1, 2, 3, 4)}
# 0 -> 100 %, 100 % -> -100 %, back to 100 %, 100 % -> 0: each held 0.6 s
STEPS = (100, -100, 100, 0)
HOLD = 0.6  # s
AT = 0.1  # s after the change


def step_responses(robot: str) -> list[float]:
    """For each step, the worst motor's speed error in % of full speed, as its encoder measures it
    over the 20 ms around `AT` after the change."""
    robot_type = example_robot(robot) if robot in ("Car", "Mecanum") else robot
    sim = Simulation(arena_scene([(robot_type, (1500, 1500, 0))], size=3000))
    motors = [sim.robots[0].motors[number] for number in MOTORS[robot]]
    dt = sim.step_us / 1e6
    errors = []
    for percent in STEPS:
        for motor in motors:
            motor.drive(percent)
        for step in range(round(HOLD / dt)):
            sim.step()
            if step + 1 == round((AT - 0.01) / dt):
                start = [motor.angle for motor in motors]
            elif step + 1 == round((AT + 0.01) / dt):
                errors.append(
                    max(
                        abs((motor.angle - angle) / 0.02 / motor.max_speed * 100 - percent)
                        for motor, angle in zip(motors, start)
                    )
                )
    return errors


@pytest.mark.parametrize("robot", MOTORS)
def test_wheels_follow_a_step_within_a_tenth_of_a_second(robot):
    errors = step_responses(robot)
    assert len(errors) == len(STEPS)
    assert max(errors) <= 10, dict(zip(STEPS, errors))


def test_motor_drive_zero_stops_a_turning_robot_at_once():
    # The S4 spins on the spot at 20 % (about 400 deg/s), then both motors get 0. Its wheels lock at
    # once; sliding on them it cannot stop in less than about 15 degrees (floor friction 1).
    # Before, it turned on by 170 degrees.
    sim = Simulation(arena_scene([("S4", (1500, 1500, 0))], size=3000))
    robot = sim.robots[0]
    robot.motors[1].drive(-20)
    robot.motors[2].drive(20)
    turned, heading = 0.0, robot.pose_mm()[3]

    def run(steps):
        nonlocal turned, heading
        for _ in range(steps):
            sim.step()
            now = robot.pose_mm()[3]
            turned += (now - heading + 180) % 360 - 180
            heading = now

    run(500)
    assert turned > 300  # it was spinning left
    spun = turned
    robot.motors[1].drive(0)
    robot.motors[2].drive(0)
    run(500)
    assert 0 <= turned - spun < 25
