"""Building a robot: its chassis in the MuJoCo spec, then its components from the registry."""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import mujoco

from eyesim.physics.meshes import model_mesh
from eyesim.physics.units import mm, rad, yaw_quat
from eyesim.physics.visual_mesh import add_model
from eyesim.physics.world import add_collider, rgba
from eyesim.robot.component import Component
from eyesim.robot.robot import Robot
from eyesim.scene.description import RobotPlacement, RobotType, Settings
from eyesim.scene.drives import drive_of
from eyesim.scene.parts.body import glides, hull_colliders

MIN_HULL_MASS_FRACTION = 0.2  # the parts may not weigh more than 80 % of the robot
HULL_FRICTION = [0.4, 0.005, 0.0001]
# A hull collider standing in for a skid or caster glides as the drives' casters do: its priority
# makes its frictionless contact win over the floor's grip.
GLIDER = {"condim": 1, "priority": 2, "friction": [0.0, 0.0, 0.0]}


@dataclass
class BuildContext:
    """What a component factory gets while the model is being built."""

    spec: mujoco.MjSpec
    body: mujoco.MjsBody  # the robot's chassis body (on a free joint unless the robot is mounted)
    prefix: str  # unique name prefix for this robot's bodies, joints, actuators
    robot_type: RobotType
    robot: Robot
    components: list[Component] = field(default_factory=list)  # created so far
    parts_mass: float = 0.0  # kg of the bodies components added; the hull gets the rest
    settings: Settings = Settings()  # the scene's settings (sensor noise, seed)

    def find(self, cls):
        for component in self.components:
            if isinstance(component, cls):
                return component
        return None

    def add_part(
        self, parent: mujoco.MjsBody, name: str, mass: float, shown: bool = False, **attributes
    ) -> mujoco.MjsBody:
        """A body of the robot below `parent` (wheels, links, fingers): its mass counts towards the
        robot's mass, and it never collides with the robot's other parts. A `shown` part is drawn
        by the viewer from its geoms and moves there on its own (docs/viewer-channel.md)."""
        body = parent.add_body(name=name, **attributes)
        self.parts_mass += mass
        self.robot.part_names.append(name)
        if shown:
            self.robot.shown_part_names.append(name)
        return body


def mounted(robot_type: RobotType) -> bool:
    """A manipulator on a fixed base is bolted to the floor (its drive says so); every other robot
    moves freely."""
    return drive_of(robot_type).mounted


def add_chassis(spec: mujoco.MjSpec, name: str, robot_type: RobotType, placement: RobotPlacement) -> mujoco.MjsBody:
    pose = placement.pose
    body = spec.worldbody.add_body(name=name, pos=[mm(pose.x), mm(pose.y), 0.0], quat=yaw_quat(rad(pose.phi)))
    if not mounted(robot_type):
        body.add_freejoint(name=f"{name}/free")
    for index, collider in enumerate(hull_colliders(robot_type)):
        contact = GLIDER if glides(robot_type, collider) and not mounted(robot_type) else {"friction": HULL_FRICTION}
        add_collider(body, f"{name}/hull{index}", collider, rgba=rgba(robot_type.color), **contact)
    mesh = model_mesh(robot_type.model)
    if mesh is not None:
        add_model(spec, body, name, mesh, offset_mm=robot_type.model_offset, rotation_deg=robot_type.model_rotation)
    return body


def _finish_mass(spec: mujoco.MjSpec, body: mujoco.MjsBody, robot_type: RobotType, parts_mass: float) -> None:
    """Give the hull the mass the parts leave over, so the robot weighs what its type says; a
    declared centre of mass is where the hull's mass sits, else the colliders share it by their
    volumes (a thin skid weighs a thin skid's share, and does not pull the centre of mass to it)."""
    hull_mass = max(robot_type.mass - parts_mass, robot_type.mass * MIN_HULL_MASS_FRACTION)
    geoms = [g for g in body.geoms if g.name.startswith(f"{body.name}/hull")]
    if robot_type.center_of_mass is None:
        volumes = [_volume(g) for g in geoms]
        total = sum(volumes)
        for geom, volume in zip(geoms, volumes):
            geom.mass = hull_mass * volume / total if total > 0 else hull_mass / len(geoms)
        return
    for geom in body.geoms:
        geom.mass = 0.0
    length, width, height = mm(robot_type.length), mm(robot_type.width), mm(robot_type.height)
    body.explicitinertial = True
    body.mass = hull_mass
    body.ipos = [mm(v) for v in robot_type.center_of_mass]
    body.inertia = [
        hull_mass * (width**2 + height**2) / 12,
        hull_mass * (length**2 + height**2) / 12,
        hull_mass * (length**2 + width**2) / 12,
    ]


def _volume(geom: mujoco.MjsGeom) -> float:
    """m^3 of a box, sphere, capsule or cylinder geom (MuJoCo's half sizes)."""
    a, b, c = geom.size
    if geom.type == mujoco.mjtGeom.mjGEOM_BOX:
        return 8 * a * b * c
    ball = 4 / 3 * math.pi * a**3
    if geom.type == mujoco.mjtGeom.mjGEOM_SPHERE:
        return ball
    tube = math.pi * a * a * 2 * b
    return tube + ball if geom.type == mujoco.mjtGeom.mjGEOM_CAPSULE else tube


def add_robot(
    spec: mujoco.MjSpec,
    robot_id: int,
    robot_type: RobotType,
    placement: RobotPlacement,
    settings: Settings = Settings(),
) -> Robot:
    from eyesim.robot.components import factories

    name = f"robot{robot_id}"
    robot = Robot(robot_id, robot_type, placement, body_name=name, mounted=mounted(robot_type))
    body = add_chassis(spec, name, robot_type, placement)
    context = BuildContext(spec, body, name, robot_type, robot, settings=settings)
    for factory in factories():
        context.components.extend(factory(context))
    robot.components = context.components
    _finish_mass(spec, body, robot_type, context.parts_mass)
    # A robot's parts never collide with each other (a wheel rubbing its own hull, an arm link its base).
    bodies = [name, *robot.part_names]
    for i, first in enumerate(bodies):
        for second in bodies[i + 1 :]:
            spec.add_exclude(bodyname1=first, bodyname2=second)
    return robot
