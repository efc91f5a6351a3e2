"""Gripper: two fingers at the arm's end effector that close on what is between them and hold it by
friction. Servo position 0 closes them, 255 opens them `opening` mm apart; they squeeze with at
most the gripper's force.

The fingers point along the end effector frame's x axis (continuing the last link) and close
along its y axis."""

from __future__ import annotations

import mujoco

from eyesim.physics.units import mm
from eyesim.robot.actuators import Servo
from eyesim.robot.component import Component
from eyesim.robot.components.arm import Arm

FINGER_LENGTH = 0.08  # m along x
FINGER_THICKNESS = 0.008  # m along y
FINGER_WIDTH = 0.02  # m along z
FINGER_MASS = 0.02  # kg
FINGER_FRICTION = [1.5, 0.02, 0.0001]  # rubber pads; the torsional part keeps a held can from turning
CLOSED_GAP = 0.004  # m between the closed fingers (they never press on each other)
FINGER_RATE = 0.05  # m/s each finger moves at
STIFFNESS = 2000.0  # N/m: far beyond the force limit as soon as a finger touches something
DAMPING = 20.0
ARMATURE = 0.05  # kg


class Gripper(Component):
    def __init__(self, context, arm: Arm):
        spec = context.robot_type.arm.gripper
        prefix = context.prefix
        end = arm.end_body
        self.force = spec.force
        self.names = []
        for side, sign in (("left", 1.0), ("right", -1.0)):
            name = f"{prefix}/finger_{side}"
            # A holder at the end effector frame carries the finger sliding along its y axis.
            holder = context.add_part(end, f"{name}/holder", 0.0, pos=arm.end_pos, quat=arm.end_quat)
            finger = context.add_part(
                holder,
                name,
                FINGER_MASS,
                shown=True,
                gravcomp=1.0,
                pos=[0.0, sign * (CLOSED_GAP + FINGER_THICKNESS) / 2, 0.0],
            )
            finger.add_joint(
                name=name,
                type=mujoco.mjtJoint.mjJNT_SLIDE,
                axis=[0, sign, 0],
                armature=ARMATURE,
                range=[0.0, mm(spec.opening) / 2],
                limited=True,
            )
            finger.add_geom(
                name=name,
                type=mujoco.mjtGeom.mjGEOM_BOX,
                size=[FINGER_LENGTH / 2, FINGER_THICKNESS / 2, FINGER_WIDTH / 2],
                pos=[FINGER_LENGTH / 2, 0.0, 0.0],
                mass=FINGER_MASS,
                friction=FINGER_FRICTION,
                condim=4,
                priority=2,
                rgba=[0.3, 0.3, 0.32, 1.0],
            )
            actuator = context.spec.add_actuator(name=name, target=name, trntype=mujoco.mjtTrn.mjTRN_JOINT)
            actuator.gainprm[0] = STIFFNESS
            actuator.biastype = mujoco.mjtBias.mjBIAS_AFFINE
            actuator.biasprm[1] = -STIFFNESS
            actuator.biasprm[2] = -DAMPING
            actuator.forcelimited = True
            actuator.forcerange = [-self.force, self.force]
            self.names.append(name)
        # Positions 0..255 map onto each finger's travel: 0 (closed) to half the opening.
        self.servo = Servo(spec.servo, 0.0, mm(spec.opening) / 2, FINGER_RATE)
        self.servos = {spec.servo: self.servo}

    def bind(self, world) -> None:
        super().bind(world)
        self.actuators = [world.actuator_id(name) for name in self.names]
        self.qpos = [int(world.model.jnt_qposadr[world.joint_id(name)]) for name in self.names]

    def reset(self) -> None:
        self.servo.reset_servo()
        for actuator in self.actuators:
            self.world.data.ctrl[actuator] = self.servo.position

    def before_step(self, dt: float) -> None:
        if self.servo.moving:
            position = self.servo.advance(dt)
            ctrl = self.world.data.ctrl
            for actuator in self.actuators:
                ctrl[actuator] = position

    def opening(self) -> float:
        """Gap (m) between the fingers now."""
        qpos = self.world.data.qpos
        return CLOSED_GAP + float(qpos[self.qpos[0]] + qpos[self.qpos[1]])


def create(context) -> list[Component]:
    arm = context.find(Arm)
    if arm is None or context.robot_type.arm.gripper is None:
        return []
    return [Gripper(context, arm)]
