"""RoBIOS simulation group: true poses. Robot id 0 = the calling robot, 1..n = scene order."""

import math

from eyesim.physics.units import mm, wrap_degrees


def _robot(sim, caller, robot_id):
    if robot_id == 0:
        return caller
    if 1 <= robot_id <= len(sim.robots):
        return sim.robots[robot_id - 1]
    return None


def sim_get_robot(sim, robot, request):
    (robot_id,) = request.args
    target = _robot(sim, robot, robot_id)
    if target is None:
        return (1, 0, 0, 0, 0)
    x, y, z, phi = target.pose_mm()
    return (0, round(x), round(y), round(z), round(wrap_degrees(phi)))


def sim_set_robot(sim, robot, request):
    robot_id, x, y, z, phi = request.args
    target = _robot(sim, robot, robot_id)
    if target is None:
        return (1,)
    target.set_pose(mm(x), mm(y), mm(z), math.radians(phi))
    return (0,)


HANDLERS = {"SIM_GET_ROBOT": sim_get_robot, "SIM_SET_ROBOT": sim_set_robot}
