"""RoBIOS simulation group: true poses of robots and objects, and how many there are.

Robot id 0 = the calling robot, 1..n = the scene's robots in scene order; object ids 1..m = the
scene's objects in scene order (maze balls and crates first, then the .sim file's objects)."""

import math

from eyesim.calls.errors import CallError
from eyesim.physics.objects import FixedObjectError
from eyesim.physics.units import mm, wrap_degrees
from eyesim.robot.robot import MountedRobotError


def _robot(sim, caller, robot_id: int):
    if robot_id == 0:
        return caller
    target = sim.robot_by_id(robot_id)
    if target is None:
        raise CallError(f"no robot {robot_id} (0 = this robot, 1..{len(sim.robots)} = the scene's)")
    return target


def _object(sim, object_id: int):
    target = sim.object_by_id(object_id)
    if target is None:
        known = f"1..{len(sim.objects)}" if sim.objects else "the scene has none"
        raise CallError(f"no object {object_id} ({known})")
    return target


def _pose(target) -> tuple:
    x, y, z, phi = target.pose_mm()
    return (0, round(x), round(y), round(z), round(wrap_degrees(phi)))


def _place(target, x: int, y: int, z: int, phi: int) -> tuple:
    """z is the height above the floor: a place below it is on it (the floor would otherwise push
    a body buried 10 km deep out at an absurd speed)."""
    try:
        target.set_pose(mm(x), mm(y), mm(max(z, 0)), math.radians(phi))
    except (FixedObjectError, MountedRobotError) as error:
        raise CallError(str(error)) from None
    return (0,)


def sim_get_robot(sim, robot, request):
    (robot_id,) = request.args
    return _pose(_robot(sim, robot, robot_id))


def sim_set_robot(sim, robot, request):
    robot_id, x, y, z, phi = request.args
    return _place(_robot(sim, robot, robot_id), x, y, z, phi)


def sim_get_object(sim, robot, request):
    (object_id,) = request.args
    return _pose(_object(sim, object_id))


def sim_set_object(sim, robot, request):
    object_id, x, y, z, phi = request.args
    return _place(_object(sim, object_id), x, y, z, phi)


def sim_get_robot_count(sim, robot, request):
    return (len(sim.robots),)


def sim_get_object_count(sim, robot, request):
    return (len(sim.objects),)


HANDLERS = {
    "SIM_GET_ROBOT": sim_get_robot,
    "SIM_SET_ROBOT": sim_set_robot,
    "SIM_GET_OBJECT": sim_get_object,
    "SIM_SET_OBJECT": sim_set_object,
    "SIM_GET_ROBOT_COUNT": sim_get_robot_count,
    "SIM_GET_OBJECT_COUNT": sim_get_object_count,
}
