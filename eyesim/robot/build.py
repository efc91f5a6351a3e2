"""Building a robot: its chassis in the MuJoCo spec, then its components from the registry."""

from __future__ import annotations

from dataclasses import dataclass, field

import mujoco

from eyesim.physics.units import mm, rad, yaw_quat
from eyesim.physics.world import rgba
from eyesim.robot.component import Component
from eyesim.robot.robot import Robot
from eyesim.scene.description import RobotPlacement, RobotType

CHASSIS_CLEARANCE = 0.012  # m between the floor and the chassis bottom
CASTER_RADIUS = 0.012  # m
SKID_LIFT = 0.002  # m the front skid sits above the floor: it only touches when the robot tips


@dataclass
class BuildContext:
    """What a component factory gets while the model is being built."""

    spec: mujoco.MjSpec
    body: mujoco.MjsBody  # the robot's chassis body (on a free joint)
    prefix: str  # unique name prefix for this robot's bodies, joints, actuators
    robot_type: RobotType
    robot: Robot
    components: list[Component] = field(default_factory=list)  # created so far

    def find(self, cls):
        for component in self.components:
            if isinstance(component, cls):
                return component
        return None


def add_chassis(spec: mujoco.MjSpec, name: str, robot_type: RobotType, placement: RobotPlacement):
    """The robot's free body with a box hull, a rear caster and a front skid."""
    pose = placement.pose
    body = spec.worldbody.add_body(name=name, pos=[mm(pose.x), mm(pose.y), 0.0],
                                   quat=yaw_quat(rad(pose.phi)))
    body.add_freejoint(name=f"{name}/free")
    length, width, height = mm(robot_type.length), mm(robot_type.width), mm(robot_type.height)
    hull_height = max(height - CHASSIS_CLEARANCE, 0.01)
    # The hull sits slightly behind the axle so the robot leans on its rear caster, not its nose.
    body.add_geom(name=f"{name}/hull", type=mujoco.mjtGeom.mjGEOM_BOX,
                  size=[length / 2, width / 2, hull_height / 2],
                  pos=[-0.01, 0.0, CHASSIS_CLEARANCE + hull_height / 2],
                  mass=robot_type.mass * 0.9, rgba=rgba(robot_type.color), friction=[0.4, 0.005, 0.0001])
    caster_x = length / 2 - CASTER_RADIUS - 0.008
    for part, x, lift in (("caster", -caster_x, 0.0), ("skid", caster_x, SKID_LIFT)):
        body.add_geom(name=f"{name}/{part}", type=mujoco.mjtGeom.mjGEOM_SPHERE, size=[CASTER_RADIUS, 0, 0],
                      pos=[x, 0.0, CASTER_RADIUS + lift], mass=0.005, condim=1, friction=[0.0, 0.0, 0.0],
                      rgba=[0.2, 0.2, 0.2, 1.0])
    return body


def add_robot(spec: mujoco.MjSpec, robot_id: int, robot_type: RobotType, placement: RobotPlacement) -> Robot:
    from eyesim.robot.components import FACTORIES

    name = f"robot{robot_id}"
    robot = Robot(robot_id, robot_type, placement, body_name=name)
    body = add_chassis(spec, name, robot_type, placement)
    context = BuildContext(spec, body, name, robot_type, robot)
    for factory in FACTORIES:
        context.components.extend(factory(context))
    robot.components = context.components
    return robot
