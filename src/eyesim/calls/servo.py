"""RoBIOS servo group: steering (Ackermann), arm joints and grippers, positions 0..255.

Servo numbers come from the robot file (docs/api/servo.md): the Ackermann steering is servo 1,
arm joints and grippers use the numbers of their `joint` and `gripper` lines."""

from eyesim.calls.errors import CallError, numbered
from eyesim.robot.actuators import SERVO_MAX


def _servo(robot, number: int):
    return numbered(robot, robot.servos, number, "servo")


def _position(value: int, what: str) -> None:
    if not 0 <= value <= SERVO_MAX:
        raise CallError(f"{what} {value} is out of range 0..{SERVO_MAX}")


def servo_set(sim, robot, request):
    number, angle = request.args
    _position(angle, "angle")
    _servo(robot, number).set(angle)
    return (0,)


def servo_set_raw(sim, robot, request):
    number, angle = request.args
    _position(angle, "angle")
    _servo(robot, number).set_raw(angle)
    return (0,)


def servo_range(sim, robot, request):
    number, low, high = request.args
    _position(low, "low")
    _position(high, "high")
    if low >= high:
        raise CallError(f"low {low} must be below high {high}")
    _servo(robot, number).set_range(low, high)
    return (0,)


HANDLERS = {"SERVO_SET": servo_set, "SERVO_SET_RAW": servo_set_raw, "SERVO_RANGE": servo_range}
