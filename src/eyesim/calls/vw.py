"""RoBIOS V-omega group: driving by linear and angular speed, in mm, mm/s, degrees and deg/s, on any
drive with kinematics; what a drive cannot do (a car turning on the spot) is a BAD_ARGUMENT error."""

import math

from eyesim.calls.errors import CallError, checked_arguments, require
from eyesim.net.session import Pending
from eyesim.physics.units import mm, to_mm, wrap_degrees
from eyesim.robot.components.vw import VwController


def _vw(robot) -> VwController:
    return require(robot.component(VwController), robot, "V-omega drive")


def vw_set_speed(sim, robot, request):
    lin, ang = request.args
    with checked_arguments():
        _vw(robot).set_speed(mm(lin), math.radians(ang))
    return (0,)


def vw_get_speed(sim, robot, request):
    v, w = _vw(robot).measured_speed()
    return (0, round(to_mm(v)), round(math.degrees(w)))


def vw_set_position(sim, robot, request):
    x, y, phi = request.args
    _vw(robot).set_odometry(mm(x), mm(y), math.radians(phi))
    return (0,)


def vw_get_position(sim, robot, request):
    x, y, phi = _vw(robot).odometry
    return (0, round(to_mm(x)), round(to_mm(y)), round(wrap_degrees(math.degrees(phi))))


def vw_straight(sim, robot, request):
    dist, speed = request.args
    _vw(robot).straight(mm(dist), mm(speed))
    return (0,)


def vw_turn(sim, robot, request):
    angle, speed = request.args
    with checked_arguments():
        _vw(robot).turn(math.radians(angle), math.radians(speed))
    return (0,)


def vw_curve(sim, robot, request):
    dist, angle, speed = request.args
    with checked_arguments():
        _vw(robot).curve(mm(dist), math.radians(angle), mm(speed))
    return (0,)


def vw_drive(sim, robot, request):
    dx, dy, speed = request.args
    vw = _vw(robot)
    if dx < abs(dy) or dx <= 0:  # dx == |dy| is a quarter circle
        raise CallError(f"the point ({dx}, {dy}) cannot be reached on an arc: dx must be at least |dy| (and above 0)")
    with checked_arguments():
        vw.drive_to(mm(dx), mm(dy), mm(speed))
    return (0,)


def vw_remain(sim, robot, request):
    return (round(to_mm(_vw(robot).remaining())),)


def vw_stalled(sim, robot, request):
    return (_vw(robot).stalled,)


def vw_done(sim, robot, request):
    return (1 if _vw(robot).done else 0,)


def vw_wait(sim, robot, request):
    vw = _vw(robot)
    if vw.done:
        return (0,)
    return Pending(lambda at_us: (0,) if vw.done else None)


HANDLERS = {
    "VW_SET_SPEED": vw_set_speed,
    "VW_GET_SPEED": vw_get_speed,
    "VW_SET_POSITION": vw_set_position,
    "VW_GET_POSITION": vw_get_position,
    "VW_STRAIGHT": vw_straight,
    "VW_TURN": vw_turn,
    "VW_DONE": vw_done,
    "VW_WAIT": vw_wait,
    "VW_CURVE": vw_curve,
    "VW_DRIVE": vw_drive,
    "VW_REMAIN": vw_remain,
    "VW_STALLED": vw_stalled,
}
