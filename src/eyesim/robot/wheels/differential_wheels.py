"""The differential drive's wheels, motors and kinematics (its declaration: drives/differential.py).

Differential drive (DIFFERENTIAL_DRIVE): two driven wheels with encoders (motors/encoders 1 = left,
2 = right) and casters; turns on the spot."""

from __future__ import annotations

import mujoco

from eyesim.physics.units import mm
from eyesim.robot.actuators import WheelMotor
from eyesim.robot.component import Component
from eyesim.robot.wheels.kinematics import Kinematics
from eyesim.robot.wheels.wheel import GRAVITY, add_wheel, ground_positions, wheel_constants, wheel_torque

CASTER_RADIUS = 0.012  # m
CASTER_LIFT = 0.001  # m casters sit above the floor: the wheels carry the robot, casters catch its tilt


class DifferentialDrive(Component, Kinematics):
    """Left wheel = motor/encoder 1, right wheel = motor/encoder 2 (RoBIOS numbering)."""

    kind = "differential_drive"

    def __init__(self, context):
        robot_type = context.robot_type
        wheels = robot_type.wheels
        self.radius, self.track, self.ticks_per_rev, self.max_wheel_speed, self.metres_per_tick = wheel_constants(
            wheels
        )
        self.tick_travel = self.metres_per_tick / 2  # one wheel's tick moves the axle's centre half as far
        self.spot_radius = self.track / 2
        axle_x = mm(robot_type.axis_offset)
        self.wheels = []
        self.wheel_names = []
        for side, sign in (("left", 1.0), ("right", -1.0)):
            name = f"{context.prefix}/wheel_{side}"
            self.wheel_names.append(name)
            add_wheel(
                context, name, [axle_x, sign * self.track / 2, self.radius], self.radius, robot_type.mass * GRAVITY / 2
            )  # the casters sit above the floor
            self.wheels.append(
                WheelMotor(
                    context.spec,
                    name,
                    name,
                    mujoco.mjtTrn.mjTRN_JOINT,
                    self.ticks_per_rev,
                    self.max_wheel_speed,
                    wheel_torque(robot_type, self.radius, 2),
                )
            )
        self.motors = {1: self.wheels[0], 2: self.wheels[1]}
        self.encoders = self.motors
        # A caster behind and a skid in front keep the robot level. They glide without friction:
        # their priority makes their frictionless contact win over the floor's grip.
        caster_x = mm(robot_type.length) / 2 - CASTER_RADIUS - 0.008
        for part, x in (("caster", -caster_x), ("skid", caster_x)):
            context.body.add_geom(
                name=f"{context.prefix}/{part}",
                type=mujoco.mjtGeom.mjGEOM_SPHERE,
                size=[CASTER_RADIUS, 0, 0],
                pos=[x, 0.0, CASTER_RADIUS + CASTER_LIFT],
                mass=0.0,
                condim=1,
                priority=2,
                friction=[0.0, 0.0, 0.0],
                rgba=[0.2, 0.2, 0.2, 1.0],
            )

    def bind(self, world) -> None:
        super().bind(world)
        for wheel in self.wheels:
            wheel.bind(world)
        self.wheel_bodies = [world.body_id(name) for name in self.wheel_names]

    def wheel_ground_positions(self) -> list[tuple[float, float, float, float]]:
        return ground_positions(self.world.data, self.wheel_bodies)

    def reset(self) -> None:
        for wheel in self.wheels:
            wheel.reset()

    def before_step(self, dt: float) -> None:
        for wheel in self.wheels:
            if wheel.needs_update:
                wheel.update(dt)

    # -- kinematics (the V-omega controller's interface) ----------------------------------------
    def odometer(self) -> tuple[int, int]:
        return self.wheels[0].raw_ticks(), self.wheels[1].raw_ticks()

    def motion(self, before: tuple[int, int], after: tuple[int, int]) -> tuple[float, float, float]:
        left = (after[0] - before[0]) * self.metres_per_tick
        right = (after[1] - before[1]) * self.metres_per_tick
        return (left + right) / 2, 0.0, (right - left) / self.track

    def set_motion(self, v: float, w: float) -> None:
        half_track, r = self.spot_radius, self.radius
        left, right = self.wheels
        left.set_speed((v - w * half_track) / r)
        right.set_speed((v + w * half_track) / r)

    def measured_speed(self) -> tuple[float, float]:
        r = self.radius
        left, right = self.wheels[0].speed * r, self.wheels[1].speed * r
        return (left + right) / 2, (right - left) / self.track

    def top_speed(self, curvature: float) -> float:
        return self.max_wheel_speed * self.radius / (1 + abs(curvature) * self.spot_radius)

    def stall_watch(self):
        return ((1, self.wheels[0], 0, self.radius), (2, self.wheels[1], 1, self.radius))
