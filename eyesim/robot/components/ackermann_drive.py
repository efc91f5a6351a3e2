"""Ackermann drive (a car): motor 1 drives the rear axle through a differential, servo 1 steers the
front wheels with Ackermann geometry; encoder 1 counts the axle's turns."""

from __future__ import annotations

import math

import mujoco

from eyesim.physics.units import mm
from eyesim.robot.actuators import Servo, WheelMotor
from eyesim.robot.component import Component
from eyesim.robot.components.differential_drive import GRAVITY, WHEEL_ARMATURE, add_wheel, wheel_torque

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


class AckermannDrive(Component):
    kind = "ackermann_drive"

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
        self.radius = mm(drive_wheels.diameter) / 2
        prefix = context.prefix
        spec = context.spec
        load = robot_type.mass * GRAVITY / 4  # N on each wheel
        # Rear axle: two driven wheels; the tendon is their mean angle (an open differential).
        axle = f"{prefix}/axle"
        tendon = spec.add_tendon(name=axle)
        for side, sign in (("left", 1.0), ("right", -1.0)):
            name = f"{prefix}/wheel_rear_{side}"
            add_wheel(context, name, [self.rear_x, sign * mm(drive_wheels.track) / 2, self.radius], self.radius,
                      load, shown=True)
            tendon.wrap_joint(name, 0.5)
        self.motor = WheelMotor(spec, axle, axle, mujoco.mjtTrn.mjTRN_TENDON, drive_wheels.ticks_per_rev,
                                math.radians(drive_wheels.max_speed),
                                # the axle's torque, which the differential splits between the two wheels
                                2 * wheel_torque(robot_type, self.radius, 4, AXLE_GRIP_FACTOR))
        self.motors = {1: self.motor}
        self.encoders = {1: self.motor}
        # Front axle: each wheel turns freely on a knuckle that the steering turns about z.
        self.knuckles = []
        for side, sign in (("left", 1.0), ("right", -1.0)):
            name = f"{prefix}/knuckle_{side}"
            knuckle = context.add_part(context.body, name, KNUCKLE_MASS,
                                       pos=[self.front_x, sign * self.front_track / 2, front_radius])
            knuckle.add_joint(name=name, type=mujoco.mjtJoint.mjJNT_HINGE, axis=[0, 0, 1], armature=WHEEL_ARMATURE)
            knuckle.add_geom(name=name, type=mujoco.mjtGeom.mjGEOM_CYLINDER, size=[0.004, front_radius / 2, 0],
                             mass=KNUCKLE_MASS, contype=0, conaffinity=0, rgba=[0.3, 0.3, 0.3, 1.0])
            add_wheel(context, f"{prefix}/wheel_front_{side}", [0.0, 0.0, 0.0], front_radius, load, parent=knuckle,
                      shown=True)
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

    def reset(self) -> None:
        self.motor.reset()
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
        if self.servo.moving:
            self._steer(self.servo.advance(dt))
        if self.motor.needs_update:
            self.motor.update(dt)


def create(context) -> list[Component]:
    robot_type = context.robot_type
    if robot_type.drive != "ackermann" or robot_type.wheels is None:
        return []
    return [AckermannDrive(context)]
