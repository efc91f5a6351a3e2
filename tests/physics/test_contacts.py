"""Contacts: robots push balls and crates, stop at each other, and their wheels roll without slip."""

import math

import pytest

from eyesim.core.clock import Clock
from eyesim.core.engine import Simulation
from eyesim.robot.components.vw import VwController
from eyesim.robot.wheels.differential_wheels import DifferentialDrive
from support.worlds import arena_scene


def run(sim, seconds: float) -> None:
    for _ in range(round(seconds / (sim.step_us / 1e6))):
        sim.step()


def test_robots_push_a_crate_and_a_ball_ahead_of_them():
    scene = arena_scene(
        robots=[("S4", (500, 500, 0)), ("S4", (500, 1500, 0))],
        objects=[("Crate", (900, 500, 0)), ("Soccer", (900, 1500, 0))],
    )
    sim = Simulation(scene, Clock("deterministic"))
    for robot in sim.robots:
        robot.component(VwController).straight(1.0, 0.2)
    run(sim, 7)
    crate, ball = sim.objects
    pusher = sim.robots[0].pose_mm()
    # The crate (200 mm) ends where the robot's front pushed its back face: 180 mm of robot and crate.
    assert crate.pose_mm()[0] == pytest.approx(pusher[0] + 82 + 100, abs=6)
    assert abs(crate.pose_mm()[1] - 500) < 20
    assert ball.pose_mm()[0] > 1500 + 82  # rolled on ahead of its robot
    assert abs(ball.pose_mm()[2]) < 2  # on the floor, not climbing the robot


def test_two_robots_meeting_head_on_stop_at_each_other():
    scene = arena_scene(robots=[("S4", (500, 1000, 0)), ("S4", (1500, 1000, 180))])
    sim = Simulation(scene, Clock("deterministic"))
    for robot in sim.robots:
        robot.component(VwController).straight(0.8, 0.3)
    closest = math.inf
    for _ in range(4000):
        sim.step()
        a, b = sim.robots[0].pose_mm(), sim.robots[1].pose_mm()
        closest = min(closest, math.hypot(b[0] - a[0], b[1] - a[1]))
    # Each hull reaches 80 mm ahead of its robot's centre, each skid 82: they meet, they do not overlap.
    assert closest >= 2 * 80 - 3
    assert closest <= 2 * 82 + 5
    assert [robot.component(VwController).stalled for robot in sim.robots] == [3, 3]


def test_encoders_count_the_wheels_true_rotation():
    sim = Simulation(arena_scene(robots=[("S4", (500, 500, 0))]), Clock("deterministic"))
    robot = sim.robots[0]
    drive = robot.component(DifferentialDrive)
    robot.component(VwController).set_speed(0.2, 0.4)
    run(sim, 3)
    for wheel in drive.wheels:
        turns = wheel.angle / (2 * math.pi)  # the hinge joint's true angle
        assert wheel.encoder() == math.floor(turns * drive.ticks_per_rev)
        assert abs(wheel.encoder()) > 1000


def test_a_rolling_ball_reports_its_centre_not_a_point_on_its_skin():
    sim = Simulation(arena_scene(objects=[("Soccer", (500, 500, 0))]), Clock("deterministic"))
    ball = sim.objects[0]
    ball.set_pose(0.5, 0.5, 0.0, 0.0)
    sim.world.data.qvel[sim.world.model.jnt_dofadr[sim.world.model.body_jntadr[ball.body]]] = 0.5  # roll along x
    for _ in range(500):
        sim.step()
        x, y, z, phi = ball.pose_mm()
        assert abs(z) < 1 and abs(y - 500) < 1
    assert x > 600
