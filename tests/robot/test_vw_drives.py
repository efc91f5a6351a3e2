"""VW on the drives other than the differential one, against the true pose (real C programs): the
mecanum robot drives and turns through its four wheels, the Ackermann car drives arcs of its rear
axle and refuses what it cannot do (docs/api/vw.md, "On each drive")."""

import math


from eyesim.scene import load_robot_type
from support.driving import EXAMPLE_ROBOTS


def heading(row) -> float:
    return math.degrees(2 * math.atan2(row["qz"], row["qw"]))


def moved(start, end, offset: float = 0.0) -> tuple[float, float, float]:
    """How far (mm ahead, mm to the left, degrees turned) the point `offset` m ahead of the robot's
    centre moved from one recorded pose to the other, in the frame of the first."""

    def point(row):
        phi = math.radians(heading(row))
        return row["x"] + offset * math.cos(phi), row["y"] + offset * math.sin(phi)

    (x0, y0), (x1, y1) = point(start), point(end)
    phi = math.radians(heading(start))
    ahead = (x1 - x0) * math.cos(phi) + (y1 - y0) * math.sin(phi)
    left = -(x1 - x0) * math.sin(phi) + (y1 - y0) * math.cos(phi)
    return ahead * 1000, left * 1000, (heading(end) - heading(start) + 180) % 360 - 180


def arc(distance: float, degrees: float) -> tuple[float, float]:
    """Where an arc of `distance` mm turning by `degrees` ends: mm ahead, mm to the left."""
    radius = distance / math.radians(degrees)
    return radius * math.sin(math.radians(degrees)), radius * (1 - math.cos(math.radians(degrees)))


def assert_near(actual, expected, mm: float, degrees: float) -> None:
    assert abs(actual[0] - expected[0]) < mm and abs(actual[1] - expected[1]) < mm, (actual, expected)
    assert abs(actual[2] - expected[2]) < degrees, (actual, expected)


def test_vw_drives_the_mecanum_robot_straight_turning_and_on_arcs(drive):
    run = drive(["Mecanum 1000 1000 0"], {1: "vw_mecanum"}, robots=["Mecanum"])
    at = run.marks(1)
    assert_near(moved(at["start"], at["straight"]), (1000, 0, 0), mm=5, degrees=0.5)
    assert_near(moved(at["straight"], at["turn"]), (0, 0, 90), mm=5, degrees=1.5)
    assert_near(moved(at["turn"], at["curve"]), (*arc(500, 90), 90), mm=10, degrees=1.5)
    # Odometry against the truth over the whole run: VWGetPosition starts at (0, 0, 0).
    [[x, y, phi]] = run.values(1, "odometry_curve")
    true = moved(at["start"], at["curve"])
    assert math.hypot(x - true[0], y - true[1]) < 20 and abs(phi - true[2]) < 3, ((x, y, phi), true)


def test_vw_drives_the_car_on_arcs_of_its_rear_axle_and_refuses_to_turn_on_the_spot(drive):
    car = load_robot_type(str(EXAMPLE_ROBOTS / "Car.robi"))
    axle = car.axis_offset / 1000  # m: the rear axle's centre, the car's reference point
    run = drive(["Car 800 1000 0"], {1: "vw_car"}, robots=["Car"])
    at = run.marks(1)
    assert_near(moved(at["start"], at["straight"], axle), (1000, 0, 0), mm=5, degrees=0.5)
    assert_near(moved(at["straight"], at["curve"], axle), (*arc(500, 90), 90), mm=10, degrees=1.0)
    [[x, y, phi]] = run.values(1, "odometry_curve")
    true = moved(at["start"], at["curve"], axle)
    assert math.hypot(x - true[0], y - true[1]) < 10 and abs(phi - true[2]) < 1, ((x, y, phi), true)
    # VWTurn, VWSetSpeed(0, w), an arc of radius 64 mm (the car's smallest: 160 mm) and VWCurve's
    # turn on the spot are all errors, and none of them started anything.
    assert run.values(1, "refused") == [[1, 1, 1, 1]]
    assert run.values(1, "done") == [[1]]
    assert "the Ackermann car cannot turn on the spot; drive an arc with VWCurve or VWDrive" in run.stderr
    assert "an arc of radius 64 mm is tighter than the Ackermann car can drive (at least 160 mm)" in run.stderr
