"""Wheel physics the wheeled drives share: a wheel on a hinge that rolls on its nominal radius, and
how much torque a drive motor gives."""

from __future__ import annotations

import math

import mujoco

from eyesim.physics.units import mm

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


def wheel_constants(wheels) -> tuple[float, float, int, float, float]:
    """From a `wheel` line: radius (m), track (m), encoder ticks a turn, top wheel speed (rad/s) and
    how far a wheel rolls in one tick (m)."""
    radius = mm(wheels.diameter) / 2
    return (
        radius,
        mm(wheels.track),
        wheels.ticks_per_rev,
        math.radians(wheels.max_speed),
        2 * math.pi * radius / wheels.ticks_per_rev,
    )


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
    wheel.add_joint(
        name=name, type=mujoco.mjtJoint.mjJNT_HINGE, axis=[0, 1, 0], damping=WHEEL_DAMPING, armature=WHEEL_ARMATURE
    )
    wheel.add_geom(
        name=name,
        type=mujoco.mjtGeom.mjGEOM_SPHERE,
        size=[radius, 0, 0],
        mass=WHEEL_MASS,
        friction=WHEEL_FRICTION,
        solref=[0.004, 1.0],
        margin=SINK + SINK_PER_NEWTON * load,
        rgba=[0, 0, 0, 0],
    )
    wheel.add_geom(
        name=f"{name}/tyre",
        type=mujoco.mjtGeom.mjGEOM_CYLINDER,
        size=[radius, WHEEL_WIDTH / 2, 0],
        quat=[math.cos(math.pi / 4), math.sin(math.pi / 4), 0, 0],
        contype=0,
        conaffinity=0,
        mass=0,
        rgba=[0.1, 0.1, 0.1, 1.0],
    )
    return wheel


def ground_positions(data, bodies) -> list[tuple[float, float, float, float]]:
    """Per wheel body: its centre's x, y on the floor (m) and its rolling direction (unit x, y)."""
    out = []
    for body in bodies:
        axle_x, axle_y = data.xmat[body][1], data.xmat[body][4]  # the hinge's y axis in the world
        length = math.hypot(axle_x, axle_y) or 1.0
        out.append((data.xpos[body][0], data.xpos[body][1], axle_y / length, -axle_x / length))
    return out
