"""Differential drive: two driven wheels on hinge joints with velocity-controlled motors and encoders."""

from __future__ import annotations

import math

import mujoco

from eyesim.physics.units import mm
from eyesim.robot.component import Component

WHEEL_WIDTH = 0.014  # m
WHEEL_MASS = 0.03  # kg
MOTOR_GAIN = 0.05  # N*m per rad/s of speed error (velocity servo)
MOTOR_TORQUE = 0.12  # N*m a motor can deliver at most: robots stall against walls


class DifferentialDrive(Component):
    """Left wheel = motor/encoder 1, right wheel = motor/encoder 2 (RoBIOS numbering)."""

    kind = "differential_drive"

    def __init__(self, context):
        wheels = context.robot_type.wheels
        self.radius = mm(wheels.diameter) / 2
        self.track = mm(wheels.track)
        self.ticks_per_rev = wheels.ticks_per_rev
        self.max_wheel_speed = math.radians(wheels.max_speed)  # rad/s
        axle_x = mm(context.robot_type.axis_offset)
        self.names = []
        for side, sign in (("left", 1.0), ("right", -1.0)):
            name = f"{context.prefix}/wheel_{side}"
            wheel = context.body.add_body(name=name, pos=[axle_x, sign * self.track / 2, self.radius])
            wheel.add_joint(name=name, type=mujoco.mjtJoint.mjJNT_HINGE, axis=[0, 1, 0], damping=0.0005)
            # The wheel touches the floor through a sphere: one contact point straight below the
            # axle, so the effective track is exactly the track (a cylinder touches at its rims).
            # The cylinder is only for looks (and for other robots' sensors).
            wheel.add_geom(name=name, type=mujoco.mjtGeom.mjGEOM_SPHERE, size=[self.radius, 0, 0], mass=WHEEL_MASS,
                           friction=[1.0, 0.005, 0.0001], solref=[0.004, 1.0], rgba=[0, 0, 0, 0])
            wheel.add_geom(name=f"{name}/tyre", type=mujoco.mjtGeom.mjGEOM_CYLINDER,
                           size=[self.radius, WHEEL_WIDTH / 2, 0], quat=[math.cos(math.pi / 4), math.sin(math.pi / 4), 0, 0],
                           contype=0, conaffinity=0, mass=0, rgba=[0.1, 0.1, 0.1, 1.0])
            actuator = context.spec.add_actuator(name=name, target=name, trntype=mujoco.mjtTrn.mjTRN_JOINT)
            actuator.gainprm[0] = MOTOR_GAIN
            actuator.biastype = mujoco.mjtBias.mjBIAS_AFFINE
            actuator.biasprm[2] = -MOTOR_GAIN
            actuator.forcelimited = True
            actuator.forcerange = [-MOTOR_TORQUE, MOTOR_TORQUE]
            self.names.append(name)
        self.target = [0.0, 0.0]  # wheel speed set points, rad/s
        self.encoder_offset = [0, 0]

    def bind(self, world) -> None:
        super().bind(world)
        self.joints = [world.joint_id(n) for n in self.names]
        self.qpos_adr = [world.model.jnt_qposadr[j] for j in self.joints]
        self.dof_adr = [world.model.jnt_dofadr[j] for j in self.joints]
        self.actuators = [world.actuator_id(n) for n in self.names]

    def reset(self) -> None:
        self.target = [0.0, 0.0]
        self.encoder_offset = [0, 0]

    def set_wheel_speeds(self, left: float, right: float) -> None:
        """Wheel angular speeds in rad/s (positive drives forward), clipped to the motors' maximum."""
        limit = self.max_wheel_speed
        self.target = [max(-limit, min(limit, left)), max(-limit, min(limit, right))]

    def before_step(self, dt: float) -> None:
        ctrl = self.world.data.ctrl
        ctrl[self.actuators[0]] = self.target[0]
        ctrl[self.actuators[1]] = self.target[1]

    def wheel_angle(self, index: int) -> float:
        return float(self.world.data.qpos[self.qpos_adr[index]])

    def wheel_speed(self, index: int) -> float:
        return float(self.world.data.qvel[self.dof_adr[index]])

    def raw_ticks(self, index: int) -> int:
        return math.floor(self.wheel_angle(index) / (2 * math.pi) * self.ticks_per_rev)

    def encoder(self, index: int) -> int:
        """Encoder count of wheel `index` (0 left, 1 right) since its last reset."""
        return self.raw_ticks(index) - self.encoder_offset[index]

    def reset_encoder(self, index: int) -> None:
        self.encoder_offset[index] = self.raw_ticks(index)


def create(context) -> list[Component]:
    robot_type = context.robot_type
    if robot_type.drive != "differential" or robot_type.wheels is None:
        return []
    return [DifferentialDrive(context)]
