"""The example Ackermann car under a real C program: its turning circle matches its geometry."""

import math

import numpy as np
import pytest

from eyesim.scene import load_robot_type
from support.driving import EXAMPLE_ROBOTS


def fitted_circle(points: np.ndarray) -> tuple[float, float, float]:
    """Least-squares circle through points: centre x, y and radius."""
    a = np.c_[2 * points, np.ones(len(points))]
    cx, cy, c = np.linalg.lstsq(a, (points**2).sum(axis=1), rcond=None)[0]
    return cx, cy, math.sqrt(c + cx * cx + cy * cy)


def test_the_car_turns_on_the_circle_its_geometry_gives(drive):
    car = load_robot_type(str(EXAMPLE_ROBOTS / "Car.robi"))
    run = drive(["Car 2000 1200 0"], {1: "car_circle"}, robots=["Car"], size=4000)
    wheelbase = car.steering.offset - car.axis_offset  # mm between the axles
    steer = math.radians((127 - 80) / 127 * 45)  # servo 80 of 0 (45 deg left) .. 127 (straight)
    rear_radius = wheelbase / math.tan(steer)  # the rear axle's centre circles the turn's centre
    centre_radius = math.hypot(rear_radius, -car.axis_offset)  # the robot's centre is ahead of the axle
    path = run.trajectory[1]
    # Once up to speed (after 2 s), the robot's centre runs on one circle.
    points = np.array([(row["x"], row["y"]) for row in path if row["time_s"] > 2.5]) * 1000
    cx, cy, radius = fitted_circle(points)
    assert radius == pytest.approx(centre_radius, rel=0.02)
    distances = np.hypot(points[:, 0] - cx, points[:, 1] - cy)
    assert distances.max() - distances.min() < 0.02 * centre_radius
    # Turning left: the centre of the turn lies to the left of where the car started.
    assert cy > 1200
    [[ticks]] = run.values(1, "encoder")
    assert ticks > 500  # the driven axle turned
    # no servo 2, position 256, no motor 2, no turning on the spot for a car
    assert run.values(1, "errors") == [[1, 1, 1, 1]]
    assert "the Ackermann car cannot turn on the spot" in run.stderr
