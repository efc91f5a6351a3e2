"""The ackermann drive's wheels, motors and kinematics (its declaration: drives/ackermann.py).

Ackermann drive (ACKERMANN_DRIVE, a car): motor 1 drives the rear axle through a differential,
servo 1 steers the front wheels with Ackermann geometry; encoder 1 counts the axle's turns. It
cannot turn on the spot: the V-omega controller drives it along arcs of its rear axle's centre."""

from __future__ import annotations

import math

import mujoco

from eyesim.physics.units import mm
from eyesim.robot.actuators import Servo, WheelMotor
from eyesim.robot.component import Component
from eyesim.robot.wheels.kinematics import Kinematics
from eyesim.robot.wheels.wheel import GRAVITY, WHEEL_ARMATURE, add_wheel, ground_positions, wheel_torque

MAX_STEER = math.radians(45)  # servo 0 steers 45 degrees left, 255 as far right (the EyeSim car)
STRAIGHT = 127  # the servo position that steers straight ahead
STEER_RATE = math.radians(300)  # rad/s: a hobby servo's speed
STEER_GAIN = 2.0  # N*m per rad holding the steered wheels on their angle
STEER_DAMPING = 0.02  # N*m per rad/s
# The driven axle needs more than a differential drive's motors (measured, docs/api/motor.md): when
# one rear wheel slips, the differential lets it take the other's torque.
AXLE_GRIP_FACTOR = 5.0
KNUCKLE_MASS = 0.005  # kg: the king pin a steered wheel turns on


class SteeringServo(Servo):
    """Servo 1: its position is the steering angle of a virtual wheel at the front axle's centre
    (radians, left positive); 0 = 45 degrees left, 127 = straight, 255 = 45 degrees right."""

    def value_of(self, raw: float) -> float:
        if raw <= STRAIGHT:
            return (STRAIGHT - raw) / STRAIGHT * MAX_STEER
        return -(raw - STRAIGHT) / (255 - STRAIGHT) * MAX_STEER

    def neutral_raw(self) -> float:
        return STRAIGHT


class AckermannDrive(Component, Kinematics):
    kind = "ackermann_drive"
    noun = "the Ackermann car"
    spot_radius = 0.0

    def __init__(self, context):
        robot_type = context.robot_type
        drive_wheels = robot_type.wheels
        steering = robot_type.steering
        steered_wheels = (steering.wheels if steering else None) or drive_wheels
        front_radius = mm(steered_wheels.diameter) / 2
        self.rear_x = mm(robot_type.axis_offset)
        # Without an `axel turn` line the front axle sits a wheel radius inside the chassis' front.
        self.front_x = mm(steering.offset) if steering else mm(robot_type.length) / 2 - front_radius
        self.wheelbase = self.front_x - self.rear_x
        self.front_track = mm(steered_wheels.track)
        self.rear_track = mm(drive_wheels.track)
        self.radius = mm(drive_wheels.diameter) / 2
        # The driven axle's encoder counts the mean of its wheels: the rear axle centre's travel.
        self.tick_travel = 2 * math.pi * self.radius / drive_wheels.ticks_per_rev
        self.min_radius = self.wheelbase / math.tan(MAX_STEER)
        self.rear_wheels = []
        prefix = context.prefix
        spec = context.spec
        load = robot_type.mass * GRAVITY / 4  # N on each wheel
        # Rear axle: two driven wheels; the tendon is their mean angle (an open differential).
        axle = f"{prefix}/axle"
        tendon = spec.add_tendon(name=axle)
        for side, sign in (("left", 1.0), ("right", -1.0)):
            name = f"{prefix}/wheel_rear_{side}"
            self.rear_wheels.append(name)
            add_wheel(
                context,
                name,
                [self.rear_x, sign * mm(drive_wheels.track) / 2, self.radius],
                self.radius,
                load,
                shown=True,
            )
            tendon.wrap_joint(name, 0.5)
        self.motor = WheelMotor(
            spec,
            axle,
            axle,
            mujoco.mjtTrn.mjTRN_TENDON,
            drive_wheels.ticks_per_rev,
            math.radians(drive_wheels.max_speed),
            # the axle's torque, which the differential splits between the two wheels
            2 * wheel_torque(robot_type, self.radius, 4, AXLE_GRIP_FACTOR),
        )
        self.motors = {1: self.motor}
        self.encoders = {1: self.motor}
        # Front axle: each wheel turns freely on a knuckle that the steering turns about z.
        self.knuckles = []
        for side, sign in (("left", 1.0), ("right", -1.0)):
            name = f"{prefix}/knuckle_{side}"
            knuckle = context.add_part(
                context.body, name, KNUCKLE_MASS, pos=[self.front_x, sign * self.front_track / 2, front_radius]
            )
            knuckle.add_joint(name=name, type=mujoco.mjtJoint.mjJNT_HINGE, axis=[0, 0, 1], armature=WHEEL_ARMATURE)
            knuckle.add_geom(
                name=name,
                type=mujoco.mjtGeom.mjGEOM_CYLINDER,
                size=[0.004, front_radius / 2, 0],
                mass=KNUCKLE_MASS,
                contype=0,
                conaffinity=0,
                rgba=[0.3, 0.3, 0.3, 1.0],
            )
            add_wheel(
                context, f"{prefix}/wheel_front_{side}", [0.0, 0.0, 0.0], front_radius, load, parent=knuckle, shown=True
            )
            actuator = spec.add_actuator(name=name, target=name, trntype=mujoco.mjtTrn.mjTRN_JOINT)
            actuator.gainprm[0] = STEER_GAIN
            actuator.biastype = mujoco.mjtBias.mjBIAS_AFFINE
            actuator.biasprm[1] = -STEER_GAIN
            actuator.biasprm[2] = -STEER_DAMPING
            self.knuckles.append(name)
        self.servo = SteeringServo(1, -MAX_STEER, MAX_STEER, STEER_RATE)
        self.servos = {1: self.servo}

    def bind(self, world) -> None:
        super().bind(world)
        self.motor.bind(world)
        self.steer_actuators = [world.actuator_id(name) for name in self.knuckles]
        self.wheel_bodies = [world.body_id(name) for name in self.rear_wheels]

    def reset(self) -> None:
        self.motor.reset()
        self._odometer_ticks: int | None = None
        self._turned = 0.0  # rad the odometry has turned, from the axle's travel and the steering
        self.servo.reset_servo()
        self._steer(self.servo.position)

    def wheel_angles(self, angle: float) -> tuple[float, float]:
        """Left and right steering angles for a steering angle `angle` of the axle's centre: both
        wheels' axles point at the same centre of the turn, on the rear axle's line."""
        if angle == 0:
            return 0.0, 0.0
        radius = self.wheelbase / math.tan(angle)  # signed: positive turns left
        half = self.front_track / 2
        return math.atan(self.wheelbase / (radius - half)), math.atan(self.wheelbase / (radius + half))

    def turning_radius(self) -> float:
        """Radius (m) of the rear axle centre's circle at the current steering goal; inf straight."""
        angle = self.servo.goal
        return math.inf if angle == 0 else abs(self.wheelbase / math.tan(angle))

    def _steer(self, angle: float) -> None:
        left, right = self.wheel_angles(angle)
        ctrl = self.world.data.ctrl
        ctrl[self.steer_actuators[0]] = left
        ctrl[self.steer_actuators[1]] = right

    def before_step(self, dt: float) -> None:
        # The odometer adds up its turn tick by tick with the steering of the moment, so it reads
        # the last step's ticks before the steering moves on (the VW controller asks less often).
        self.odometer()
        if self.servo.moving:
            self._steer(self.servo.advance(dt))
        if self.motor.needs_update:
            self.motor.update(dt)

    # -- kinematics (the V-omega controller's interface) ----------------------------------------
    def odometer(self) -> tuple[int, float]:
        """The axle's ticks and the rotation they add up to: each increment turns the car by its
        length times the curvature the steering is commanded to (a bicycle model of the rear axle)."""
        ticks = self.motor.raw_ticks()
        if self._odometer_ticks is None:
            self._odometer_ticks = ticks
        elif ticks != self._odometer_ticks:
            self._turned += (
                (ticks - self._odometer_ticks) * self.tick_travel * math.tan(self.servo.position) / self.wheelbase
            )
            self._odometer_ticks = ticks
        return ticks, self._turned

    def motion(self, before: tuple[int, float], after: tuple[int, float]) -> tuple[float, float, float]:
        return (after[0] - before[0]) * self.tick_travel, 0.0, after[1] - before[1]

    def set_motion(self, v: float, w: float) -> None:
        """The rear axle at v; the steering to the curvature w / v, within its 45 degrees. At v = 0
        the steering stays where it is (w is then 0: the controller never asks a car to turn still)."""
        self.motor.set_speed(v / self.radius)
        if v != 0:
            self.servo.goal = max(-MAX_STEER, min(MAX_STEER, math.atan(self.wheelbase * w / v)))

    def measured_speed(self) -> tuple[float, float]:
        v = self.motor.speed * self.radius
        return v, v * math.tan(self.servo.position) / self.wheelbase

    def top_speed(self, curvature: float) -> float:
        # The outer rear wheel turns fastest; the differential lets it outrun the axle's motor.
        return self.motor.max_speed * self.radius / (1 + abs(curvature) * self.rear_track / 2)

    def arc_lever(self) -> float:
        return self.rear_track / 2  # the outer rear wheel, through the differential

    def stall_watch(self):
        return ((1, self.motor, 0, self.radius), (2, self.motor, 1, self.radius))

    def wheel_ground_positions(self) -> list[tuple[float, float, float, float]]:
        return ground_positions(self.world.data, self.wheel_bodies)
