"""RoBIOS LIDAR group: the scanner's field, tilt and beam count (LIDARGet and SIMLaserScan only take
a scan, an int32 array encoded as it is: protocol.json's "calls")."""

from eyesim.calls.errors import CallError, component_of
from eyesim.parts.lidar.component import MAX_POINTS, LidarScanner

GROUP = "lidar"  # protocol.json's group of the operations below


def _scanner(robot) -> LidarScanner:
    return component_of(robot, LidarScanner)


def lidar_set(sim, robot, request):
    field, tilt, points = request.args
    if not 1 <= field <= 360:
        raise CallError(f"range {field} is not a field of view of 1..360 degrees")
    if not -90 < tilt < 90:
        raise CallError(f"tilt {tilt} is not between -90 and 90 degrees")
    if not 1 <= points <= MAX_POINTS:
        raise CallError(f"{points} points; expected 1..{MAX_POINTS}")
    _scanner(robot).configure(field, tilt, points)
    return (0,)


HANDLERS = {"LIDAR_SET": lidar_set}
