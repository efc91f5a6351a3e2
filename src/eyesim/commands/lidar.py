"""RoBIOS LIDAR group: the scanner's field, tilt and beam count, and one scan per LIDARGet."""

from eyesim.commands.errors import CommandError, require
from eyesim.robot.components.lidar import MAX_POINTS, LidarScanner


def _scanner(robot) -> LidarScanner:
    return require(robot.component(LidarScanner), robot, "lidar")


def lidar_set(sim, robot, request):
    field, tilt, points = request.args
    if not 1 <= field <= 360:
        raise CommandError(f"range {field} is not a field of view of 1..360 degrees")
    if not -90 < tilt < 90:
        raise CommandError(f"tilt {tilt} is not between -90 and 90 degrees")
    if not 1 <= points <= MAX_POINTS:
        raise CommandError(f"{points} points; expected 1..{MAX_POINTS}")
    _scanner(robot).configure(field, tilt, points)
    return (0,)


def lidar_get(sim, robot, request):
    return (0, _scanner(robot).scan())  # int32 array: encoded without a list


def sim_laser_scan(sim, robot, request):
    return (0, _scanner(robot).laser_scan())


HANDLERS = {"LIDAR_SET": lidar_set, "LIDAR_GET": lidar_get, "SIM_LASER_SCAN": sim_laser_scan}
