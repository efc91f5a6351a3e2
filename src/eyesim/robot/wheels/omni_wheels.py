"""The omni drive's wheels, motors and kinematics (its declaration: eyesim/scene/drives/omni.py).

A mecanum wheel's rollers sit at 45 degrees: the wheel only pushes along its bottom roller's axis
and rolls freely across it. That is modelled exactly by a plain wheel turned by 45 degrees that
rolls along the roller's axis and slides freely along its own axle (a capsule touching the floor,
whose contact friction is high along the rolling direction and nearly zero along the axle). As it
rolls cos 45 as far per turn, it is geared to its motor by 1/cos 45 (a tendon), so the motor and
its encoder turn exactly like the real wheel."""

from __future__ import annotations

import math

import mujoco

from eyesim.physics.units import mm
from eyesim.robot.actuators import WheelMotor
from eyesim.robot.component import Component
from eyesim.robot.wheels.kinematics import Kinematics
from eyesim.robot.wheels.wheel import (
    WHEEL_ARMATURE,
    WHEEL_DAMPING,
    WHEEL_MASS,
    ground_positions,
    wheel_constants,
    wheel_torque,
)

ROLLER_FRICTION = 0.02  # along the axle: what the rollers' bearings resist
GRIP = 1.0  # along the rolling direction
WHEEL_WIDTH = 0.02  # m
# Of the grip along a wheel's rolling direction; measured to meet the 0.1 s step response
# (docs/api/motor.md): more makes four slipping wheels fight each other.
MECANUM_GRIP_FACTOR = 4.0
# (name, motor, x sign, y sign, direction its bottom roller pushes when the wheel turns forward)
WHEELS = (
    ("front_left", 1, 1, 1, -45.0),
    ("front_right", 2, 1, -1, 45.0),
    ("back_left", 3, -1, 1, 45.0),
    ("back_right", 4, -1, -1, -45.0),
)


class OmniDrive(Component, Kinematics):
    """Also moves by robot speeds (the V-omega controller): ahead and turning, wheel speeds
    FL = BL = (v - l w) / r and FR = BR = (v + l w) / r, with l = half wheelbase + half track
    (docs/robots.md)."""

    kind = "omni_drive"
    noun = "the mecanum robot"

    def __init__(self, context):
        robot_type = context.robot_type
        wheels = robot_type.wheels
        self.radius, self.track, self.ticks_per_rev, self.max_wheel_speed, self.metres_per_tick = wheel_constants(
            wheels
        )
        # The axles sit a wheel radius inside the chassis' front and back.
        self.wheelbase = max(mm(robot_type.length) - 2 * self.radius, self.radius)
        self.tick_travel = self.metres_per_tick / 4  # the robot moves by the mean of its four wheels
        self.spot_radius = self.wheelbase / 2 + self.track / 2
        spec, prefix = context.spec, context.prefix
        self.motors = {}
        self.wheel_names = []
        for name, motor, x_sign, y_sign, heading in WHEELS:
            body_name = f"{prefix}/wheel_{name}"
            self.wheel_names.append(body_name)
            half = math.radians(heading) / 2
            wheel = context.add_part(
                context.body,
                body_name,
                WHEEL_MASS,
                shown=True,
                pos=[x_sign * self.wheelbase / 2, y_sign * self.track / 2, self.radius],
                quat=[math.cos(half), 0.0, 0.0, math.sin(half)],
            )
            wheel.add_joint(
                name=body_name,
                type=mujoco.mjtJoint.mjJNT_HINGE,
                axis=[0, 1, 0],
                damping=WHEEL_DAMPING,
                armature=WHEEL_ARMATURE,
            )
            # A capsule along the axle (MuJoCo's capsule stands along z: turn it onto y).
            wheel.add_geom(
                name=body_name,
                type=mujoco.mjtGeom.mjGEOM_CAPSULE,
                size=[self.radius, WHEEL_WIDTH / 2, 0],
                quat=[math.cos(math.pi / 4), -math.sin(math.pi / 4), 0, 0],
                mass=WHEEL_MASS,
                contype=0,
                conaffinity=0,
                rgba=[0.15, 0.15, 0.15, 1.0],
            )
            # The capsule-floor contact frame's first direction is the capsule's axis.
            spec.add_pair(
                geomname1=body_name,
                geomname2="floor",
                condim=3,
                friction=[ROLLER_FRICTION, GRIP, 0.005, 0.0001, 0.0001],
            )
            shaft = f"{body_name}/shaft"
            tendon = spec.add_tendon(name=shaft)
            tendon.wrap_joint(body_name, math.sqrt(2))
            self.motors[motor] = WheelMotor(
                spec,
                shaft,
                shaft,
                mujoco.mjtTrn.mjTRN_TENDON,
                wheels.ticks_per_rev,
                math.radians(wheels.max_speed),
                # the shaft's gearing multiplies its torque by sqrt 2 at the wheel
                wheel_torque(robot_type, self.radius, 4, MECANUM_GRIP_FACTOR) / math.sqrt(2),
            )
        self.encoders = self.motors
        self.wheels = tuple(self.motors[motor] for motor in (1, 2, 3, 4))

    def bind(self, world) -> None:
        super().bind(world)
        for motor in self.motors.values():
            motor.bind(world)
        self.wheel_bodies = [world.body_id(name) for name in self.wheel_names]

    def reset(self) -> None:
        for motor in self.motors.values():
            motor.reset()

    def before_step(self, dt: float) -> None:
        for motor in self.motors.values():
            if motor.needs_update:
                motor.update(dt)

    # -- kinematics (the V-omega controller's interface) ----------------------------------------
    def odometer(self) -> tuple[int, int, int, int]:
        a, b, c, d = (wheel.raw_ticks() for wheel in self.wheels)
        return a, b, c, d

    def motion(self, before, after) -> tuple[float, float, float]:
        """The inverse of the wheel speeds (docs/robots.md): sideways motion too, so VWGetPosition
        follows a robot that MOTOR commands drive sideways."""
        fl, fr, bl, br = ((a - b) * self.metres_per_tick for a, b in zip(after, before))
        return (fl + fr + bl + br) / 4, (-fl + fr + bl - br) / 4, (-fl + fr - bl + br) / (4 * self.spot_radius)

    def set_motion(self, v: float, w: float) -> None:
        left, right = (v - w * self.spot_radius) / self.radius, (v + w * self.spot_radius) / self.radius
        fl, fr, bl, br = self.wheels
        fl.set_speed(left)
        fr.set_speed(right)
        bl.set_speed(left)
        br.set_speed(right)

    def measured_speed(self) -> tuple[float, float]:
        fl, fr, bl, br = (wheel.speed * self.radius for wheel in self.wheels)
        return (fl + fr + bl + br) / 4, (-fl + fr - bl + br) / (4 * self.spot_radius)

    def top_speed(self, curvature: float) -> float:
        return self.max_wheel_speed * self.radius / (1 + abs(curvature) * self.spot_radius)

    def stall_watch(self):
        # A left wheel stalling sets bit 0, a right one bit 1; each rolls cos 45 as far as its
        # motor turns (module docstring).
        roll = self.radius / math.sqrt(2)
        fl, fr, bl, br = self.wheels
        return ((1, fl, 0, roll), (2, fr, 1, roll), (1, bl, 2, roll), (2, br, 3, roll))

    def wheel_ground_positions(self) -> list[tuple[float, float, float, float]]:
        return ground_positions(self.world.data, self.wheel_bodies)
