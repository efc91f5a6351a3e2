"""Manipulator arm: links built from the robot's Denavit-Hartenberg table, each joint turned (or
slid) by its servo towards the SERVOSet position at a servo's speed.

Link i moves from frame i-1 to frame i by rotating theta about z, moving d along z, a along x
and rotating alpha about x; a revolute joint adds its angle to theta, a prismatic one its
extension to d. The end effector is the origin of the last frame. The links are light tubes whose
weight the servos carry (MuJoCo's gravity compensation), so they stop where they are sent.

The gripper: two fingers at the end effector that close on what is between them and hold it by
friction. Servo position 0 closes them, 255 opens them `opening` mm apart; they squeeze with at
most the gripper's force. The fingers point along the end effector frame's x axis (continuing
the last link) and close along its y axis."""

from __future__ import annotations

import math

import mujoco

from eyesim.parts.arm.declaration import JointSpec
from eyesim.physics.units import mm
from eyesim.robot.actuators import Servo
from eyesim.robot.component import Component

LINK_RADIUS = 0.012  # m
LINK_MASS_PER_METRE = 0.5  # kg/m of link
SERVO_MASS = 0.05  # kg, each joint's servo
REVOLUTE_RATE = math.radians(90)  # rad/s a joint servo turns at
PRISMATIC_RATE = 0.1  # m/s a linear servo slides at
ARMATURE = {"revolute": 0.01, "prismatic": 0.5}  # kg*m^2 / kg: the geared servo's inertia
STIFFNESS = {"revolute": 20.0, "prismatic": 2000.0}  # N*m/rad, N/m
DAMPING = {"revolute": 1.0, "prismatic": 60.0}
MAX_FORCE = {"revolute": 3.0, "prismatic": 50.0}  # N*m, N
LINK_COLOR = [0.75, 0.75, 0.78, 1.0]
# The gripper's two fingers
FINGER_LENGTH = 0.08  # m along x
FINGER_THICKNESS = 0.008  # m along y
FINGER_WIDTH = 0.02  # m along z
FINGER_MASS = 0.02  # kg
FINGER_FRICTION = [1.5, 0.02, 0.0001]  # rubber pads; the torsional part keeps a held can from turning
CLOSED_GAP = 0.004  # m between the closed fingers (they never press on each other)
FINGER_RATE = 0.05  # m/s each finger moves at
FINGER_STIFFNESS = 2000.0  # N/m: far beyond the force limit as soon as a finger touches something
FINGER_DAMPING = 20.0
FINGER_ARMATURE = 0.05  # kg


def dh_quat(theta: float, alpha: float) -> list[float]:
    """Quaternion of a rotation by theta about z followed by alpha about the new x."""
    ct, st, ca, sa = math.cos(theta / 2), math.sin(theta / 2), math.cos(alpha / 2), math.sin(alpha / 2)
    return [ct * ca, ct * sa, st * sa, st * ca]


class JointServo(Servo):
    """Positions 0..255 map linearly onto the joint's [min, max] (radians or metres)."""

    def __init__(self, joint: JointSpec, name: str):
        self.joint = joint
        self.name = name
        self.actuator = self.qpos = -1  # its MuJoCo actuator id and qpos address, once bound
        revolute = joint.kind == "revolute"
        convert = math.radians if revolute else mm
        super().__init__(
            joint.servo, convert(joint.min), convert(joint.max), REVOLUTE_RATE if revolute else PRISMATIC_RATE
        )

    def neutral_raw(self) -> float:
        """A joint starts at its zero position, or the limit nearest to it."""
        low, high = self.low_value, self.high_value
        if low == high:
            return 0.0
        return min(255.0, max(0.0, (0.0 - low) / (high - low) * 255))


class Arm(Component):
    def __init__(self, context):
        arm = context.robot_type.arm
        prefix = context.prefix
        pos = [mm(arm.x), mm(arm.y), mm(arm.z)]
        quat = dh_quat(math.radians(arm.heading), 0.0)
        parent = context.body
        self.servo_list: list[JointServo] = []
        for index, joint in enumerate(arm.joints):
            name = f"{prefix}/link{index + 1}"
            d, a = mm(joint.d), mm(joint.a)
            theta, alpha = math.radians(joint.theta), math.radians(joint.alpha)
            mass = SERVO_MASS + LINK_MASS_PER_METRE * (abs(d) + abs(a))
            link = context.add_part(parent, name, mass, shown=True, pos=pos, quat=quat, gravcomp=1.0)
            kind = joint.kind
            revolute = kind == "revolute"
            link.add_joint(
                name=name,
                type=mujoco.mjtJoint.mjJNT_HINGE if revolute else mujoco.mjtJoint.mjJNT_SLIDE,
                axis=[0, 0, 1],
                armature=ARMATURE[kind],
            )
            link.add_geom(
                name=f"{name}/servo",
                type=mujoco.mjtGeom.mjGEOM_SPHERE,
                size=[1.5 * LINK_RADIUS, 0, 0],
                mass=SERVO_MASS,
                rgba=[0.25, 0.25, 0.28, 1.0],
            )
            # The link as drawn and felt: a tube up z by d, then along the turned x by a.
            elbow = [a * math.cos(theta), a * math.sin(theta), d]
            for part, start, end in (("d", [0.0, 0.0, 0.0], [0.0, 0.0, d]), ("a", [0.0, 0.0, d], elbow)):
                if start != end:
                    link.add_geom(
                        name=f"{name}/{part}",
                        type=mujoco.mjtGeom.mjGEOM_CAPSULE,
                        fromto=start + end,
                        size=[LINK_RADIUS, 0, 0],
                        mass=LINK_MASS_PER_METRE * math.dist(start, end),
                        rgba=LINK_COLOR,
                    )
            actuator = context.spec.add_actuator(name=name, target=name, trntype=mujoco.mjtTrn.mjTRN_JOINT)
            actuator.gainprm[0] = STIFFNESS[kind]
            actuator.biastype = mujoco.mjtBias.mjBIAS_AFFINE
            actuator.biasprm[1] = -STIFFNESS[kind]
            actuator.biasprm[2] = -DAMPING[kind]
            actuator.forcelimited = True
            actuator.forcerange = [-MAX_FORCE[kind], MAX_FORCE[kind]]
            self.servo_list.append(JointServo(joint, name))
            parent, pos, quat = link, elbow, dh_quat(theta, alpha)
        self.end_body = parent  # the last link (while the model is built)
        self.end_pos, self.end_quat = pos, quat  # the end effector frame in the last link
        self.end_site = f"{prefix}/end_effector"
        parent.add_site(name=self.end_site, pos=pos, quat=quat, size=[0.005, 0, 0], group=4)
        self.servos = {servo.number: servo for servo in self.servo_list}

    def bind(self, world) -> None:
        super().bind(world)
        model = world.model
        self.site = world.site_id(self.end_site)
        for servo in self.servo_list:
            servo.actuator = world.actuator_id(servo.name)
            servo.qpos = int(model.jnt_qposadr[world.joint_id(servo.name)])

    def reset(self) -> None:
        data = self.world.data
        for servo in self.servo_list:
            servo.reset_servo()
            data.qpos[servo.qpos] = servo.position
            data.ctrl[servo.actuator] = servo.position

    def before_step(self, dt: float) -> None:
        ctrl = self.world.data.ctrl
        for servo in self.servo_list:
            if servo.moving:
                ctrl[servo.actuator] = servo.advance(dt)

    def joint_values(self) -> list[float]:
        """Where the joints are now: radians or metres from their zero position."""
        qpos = self.world.data.qpos
        return [float(qpos[servo.qpos]) for servo in self.servo_list]

    def end_effector(self) -> tuple[float, float, float]:
        """World position (m) of the end effector."""
        x, y, z = (float(v) for v in self.world.data.site_xpos[self.site])
        return x, y, z


class Gripper(Component):
    """Two fingers on the last link, moved apart and together by one servo."""

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
                armature=FINGER_ARMATURE,
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
            actuator.gainprm[0] = FINGER_STIFFNESS
            actuator.biastype = mujoco.mjtBias.mjBIAS_AFFINE
            actuator.biasprm[1] = -FINGER_STIFFNESS
            actuator.biasprm[2] = -FINGER_DAMPING
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
    """The arm when it has joints, and its gripper when it has one."""
    spec = context.robot_type.arm
    if spec is None or not spec.joints:
        return []
    arm = Arm(context)
    return [arm] if spec.gripper is None else [arm, Gripper(context, arm)]
