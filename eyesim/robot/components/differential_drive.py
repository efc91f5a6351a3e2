"""Differential drive: two driven wheels with encoders (motors/encoders 1 = left, 2 = right) and casters."""

from __future__ import annotations

import math

import mujoco

from eyesim.physics.units import mm
from eyesim.robot.actuators import WheelMotor
from eyesim.robot.component import Component

WHEEL_WIDTH = 0.014  # m
WHEEL_MASS = 0.03  # kg
WHEEL_FRICTION = [1.0, 0.005, 0.0001]
# The geared motor's rotor inertia as the wheel feels it. It also keeps the stiff speed controller
# (integrated implicitly) in step with the contact solver, which would otherwise let the wheels creep.
WHEEL_ARMATURE = 1e-4  # kg*m^2
WHEEL_DAMPING = 5e-5  # N*m per rad/s: the bearings' friction
GRAVITY = 9.81  # m/s^2
# A drive motor gives this many times the torque its wheel can pass to the floor: enough to bring
# the wheel to a new speed within 0.1 s, as EyeSim's motors do (it slips until the robot catches up),
# yet too little to tip a small robot back onto its caster (measured: docs/api/motor.md).
MOTOR_GRIP_FACTOR = 2.5
CASTER_RADIUS = 0.012  # m
CASTER_LIFT = 0.001  # m casters sit above the floor: the wheels carry the robot, casters catch its tilt


def wheel_torque(robot_type, radius: float, wheels: int, factor: float = MOTOR_GRIP_FACTOR) -> float:
    """N*m a drive motor gives at most at its wheel: `factor` times what the wheel can transmit,
    with the robot's weight shared by its `wheels` on the floor."""
    return factor * WHEEL_FRICTION[0] * robot_type.mass * GRAVITY / wheels * radius


# MuJoCo's soft contact lets a wheel sink into the floor under its load (measured: 0.11 mm for the
# S4's 3.9 N, 0.14 mm for the LabBot's 7.4 N). It would then roll on a radius that much smaller than
# the one its encoder odometry assumes, and every VWTurn would fall short by 0.2-0.3 %. A contact
# margin of the expected sink lets the wheel settle with its surface on the floor instead.
SINK = 0.080e-3  # m at no load
SINK_PER_NEWTON = 0.0079e-3  # m per N of load


def add_wheel(context, name: str, pos, radius: float, load: float, parent=None, shown: bool = False):
    """A wheel body at `pos` (in `parent`, default the chassis) on a hinge about its y axis, carrying
    `load` newtons. It touches the floor through a sphere: one contact point straight below the
    axle, so the effective track is exactly the track (a cylinder would touch at its rims). The tyre
    cylinder is only for looks."""
    wheel = context.add_part(parent or context.body, name, WHEEL_MASS, shown=shown, pos=pos)
    wheel.add_joint(name=name, type=mujoco.mjtJoint.mjJNT_HINGE, axis=[0, 1, 0], damping=WHEEL_DAMPING,
                    armature=WHEEL_ARMATURE)
    wheel.add_geom(name=name, type=mujoco.mjtGeom.mjGEOM_SPHERE, size=[radius, 0, 0], mass=WHEEL_MASS,
                   friction=WHEEL_FRICTION, solref=[0.004, 1.0], margin=SINK + SINK_PER_NEWTON * load,
                   rgba=[0, 0, 0, 0])
    wheel.add_geom(name=f"{name}/tyre", type=mujoco.mjtGeom.mjGEOM_CYLINDER, size=[radius, WHEEL_WIDTH / 2, 0],
                   quat=[math.cos(math.pi / 4), math.sin(math.pi / 4), 0, 0], contype=0, conaffinity=0, mass=0,
                   rgba=[0.1, 0.1, 0.1, 1.0])
    return wheel


class DifferentialDrive(Component):
    """Left wheel = motor/encoder 1, right wheel = motor/encoder 2 (RoBIOS numbering)."""

    kind = "differential_drive"

    def __init__(self, context):
        robot_type = context.robot_type
        wheels = robot_type.wheels
        self.radius = mm(wheels.diameter) / 2
        self.track = mm(wheels.track)
        self.ticks_per_rev = wheels.ticks_per_rev
        self.max_wheel_speed = math.radians(wheels.max_speed)  # rad/s
        axle_x = mm(robot_type.axis_offset)
        self.wheels = []
        self.wheel_names = []
        for side, sign in (("left", 1.0), ("right", -1.0)):
            name = f"{context.prefix}/wheel_{side}"
            self.wheel_names.append(name)
            add_wheel(context, name, [axle_x, sign * self.track / 2, self.radius], self.radius,
                      robot_type.mass * GRAVITY / 2)  # the casters sit above the floor
            self.wheels.append(WheelMotor(context.spec, name, name, mujoco.mjtTrn.mjTRN_JOINT, self.ticks_per_rev,
                                          self.max_wheel_speed, wheel_torque(robot_type, self.radius, 2)))
        self.motors = {1: self.wheels[0], 2: self.wheels[1]}
        self.encoders = self.motors
        # A caster behind and a skid in front keep the robot level. They glide without friction:
        # their priority makes their frictionless contact win over the floor's grip.
        caster_x = mm(robot_type.length) / 2 - CASTER_RADIUS - 0.008
        for part, x in (("caster", -caster_x), ("skid", caster_x)):
            context.body.add_geom(name=f"{context.prefix}/{part}", type=mujoco.mjtGeom.mjGEOM_SPHERE,
                                  size=[CASTER_RADIUS, 0, 0], pos=[x, 0.0, CASTER_RADIUS + CASTER_LIFT], mass=0.0,
                                  condim=1, priority=2, friction=[0.0, 0.0, 0.0], rgba=[0.2, 0.2, 0.2, 1.0])

    def bind(self, world) -> None:
        super().bind(world)
        for wheel in self.wheels:
            wheel.bind(world)
        self.wheel_bodies = [world.body_id(name) for name in self.wheel_names]

    def wheel_ground_positions(self) -> list[tuple[float, float, float, float]]:
        """Per wheel: its centre's x, y on the floor (m) and its rolling direction (unit x, y)."""
        data = self.world.data
        out = []
        for body in self.wheel_bodies:
            axle_x, axle_y = data.xmat[body][1], data.xmat[body][4]  # the hinge's y axis in the world
            length = math.hypot(axle_x, axle_y) or 1.0
            out.append((data.xpos[body][0], data.xpos[body][1], axle_y / length, -axle_x / length))
        return out

    def reset(self) -> None:
        for wheel in self.wheels:
            wheel.reset()

    def before_step(self, dt: float) -> None:
        for wheel in self.wheels:
            if wheel.needs_update:
                wheel.update(dt)

    def wheel_speed(self, index: int) -> float:
        return self.wheels[index].speed


def create(context) -> list[Component]:
    robot_type = context.robot_type
    if robot_type.drive != "differential" or robot_type.wheels is None:
        return []
    return [DifferentialDrive(context)]
