"""RoBIOS motor group: motors (open loop, PID speed control) and their encoders.

Motor and encoder numbers depend on the drive (docs/api/motor.md): differential 1 left, 2 right;
Ackermann 1 = the driven axle; omni 1..4 front left, front right, back left, back right;
submarine = its thrusters' numbers (no encoders)."""

from eyesim.commands.errors import CommandError
from eyesim.protocol import generated
from eyesim.robot.actuators import ActuatorError
from eyesim.robot.components.vw import VwController

MAX_PERCENT = 100
MAX_GAIN = 255


def _numbers(table: dict) -> str:
    return ", ".join(str(n) for n in sorted(table)) or "none"


def _motor(robot, number: int, function: str):
    motor = robot.motors.get(number)
    if motor is None:
        raise CommandError(f"{function}: robot {robot.id} ({robot.name}) has no motor {number} "
                           f"(its motors: {_numbers(robot.motors)})", generated.ERR_NOT_SUPPORTED
                           if not robot.motors else generated.ERR_BAD_ARGUMENT)
    # Driving a motor directly takes it over from the V-omega controller.
    for vw in robot.components_of(VwController):
        if motor in vw.drive.wheels:
            vw.release()
    return motor


def _encoder(robot, number: int, function: str):
    encoder = robot.encoders.get(number)
    if encoder is None:
        raise CommandError(f"{function}: robot {robot.id} ({robot.name}) has no encoder {number} "
                           f"(its encoders: {_numbers(robot.encoders)})", generated.ERR_NOT_SUPPORTED
                           if not robot.encoders else generated.ERR_BAD_ARGUMENT)
    return encoder


def _check(value: int, low: int, high: int, what: str, function: str) -> None:
    if not low <= value <= high:
        raise CommandError(f"{function}: {what} {value} is out of range {low}..{high}")


def _drive(function: str):
    def handler(sim, robot, request):
        number, speed = request.args
        _check(speed, -MAX_PERCENT, MAX_PERCENT, "speed", function)
        _motor(robot, number, function).drive(speed)
        return (0,)
    return handler


def _carry_out(function: str, action) -> tuple:
    try:
        action()
    except ActuatorError as error:
        raise CommandError(f"{function}: motor {error}", generated.ERR_NOT_SUPPORTED) from None
    except ValueError as error:
        raise CommandError(f"{function}: {error}") from None
    return (0,)


def motor_pid(sim, robot, request):
    number, p, i, d = request.args
    for value, name in ((p, "p"), (i, "i"), (d, "d")):
        _check(value, 0, MAX_GAIN, name, "MOTORPID")
    motor = _motor(robot, number, "MOTORPID")
    return _carry_out("MOTORPID", lambda: motor.set_pid(p, i, d))


def motor_pid_off(sim, robot, request):
    (number,) = request.args
    motor = _motor(robot, number, "MOTORPIDOff")
    return _carry_out("MOTORPIDOff", motor.pid_off)


def motor_speed(sim, robot, request):
    number, ticks = request.args
    motor = _motor(robot, number, "MOTORSpeed")
    return _carry_out("MOTORSpeed", lambda: motor.set_ticks_per_second(ticks))


def encoder_read(sim, robot, request):
    (number,) = request.args
    return (_encoder(robot, number, "ENCODERRead").encoder(),)


def encoder_reset(sim, robot, request):
    (number,) = request.args
    _encoder(robot, number, "ENCODERReset").reset_encoder()
    return (0,)


HANDLERS = {
    "MOTOR_DRIVE": _drive("MOTORDrive"),
    "MOTOR_DRIVE_RAW": _drive("MOTORDriveRaw"),
    "MOTOR_PID": motor_pid,
    "MOTOR_PID_OFF": motor_pid_off,
    "MOTOR_SPEED": motor_speed,
    "ENCODER_READ": encoder_read,
    "ENCODER_RESET": encoder_reset,
}
