"""Differential drive under real C programs: VW manoeuvres, odometry, encoders and stalls,
checked against the true poses the simulator records."""

import math

import pytest
from support.driving import drive_scene


def heading(row) -> float:
    """Heading in degrees of a recorded pose (the robot stays level)."""
    return math.degrees(2 * math.atan2(row["qz"], row["qw"]))


def turned(a, b) -> float:
    return (heading(b) - heading(a) + 180) % 360 - 180


def ahead(row, forward: float, left: float) -> tuple[float, float]:
    """The point `forward` m ahead and `left` m to the left of a recorded pose."""
    phi = math.radians(heading(row))
    return (
        row["x"] + forward * math.cos(phi) - left * math.sin(phi),
        row["y"] + forward * math.sin(phi) + left * math.cos(phi),
    )


@pytest.fixture(scope="module")
def manoeuvres(tmp_path_factory, programs):
    """One run of every manoeuvre: the Drive and the true pose at each mark."""
    run = drive_scene(tmp_path_factory.mktemp("vw"), programs, ["S4 500 500 0"], {1: "vw_manoeuvres"})
    return run, run.marks(1)


def test_straight_ends_within_one_percent_and_one_degree(manoeuvres):
    run, at = manoeuvres
    start, end = at["start"], at["straight"]
    distance = math.hypot(end["x"] - start["x"], end["y"] - start["y"])
    assert distance == pytest.approx(1.0, rel=0.01)
    assert abs(turned(start, end)) < 1.0


def test_turn_on_the_spot_within_one_degree(manoeuvres):
    run, at = manoeuvres
    assert turned(at["straight"], at["turn"]) == pytest.approx(90, abs=1.0)
    assert math.hypot(at["turn"]["x"] - at["straight"]["x"], at["turn"]["y"] - at["straight"]["y"]) < 0.005


def test_curve_reaches_its_end_point_within_two_percent(manoeuvres):
    run, at = manoeuvres
    start, end = at["turn"], at["curve"]
    radius = 0.6 / (math.pi / 2)
    x, y = ahead(start, radius, radius)  # a quarter circle to the left
    assert math.hypot(end["x"] - x, end["y"] - y) < 0.02 * 0.6
    assert turned(start, end) == pytest.approx(90, abs=2.0)


def test_drive_reaches_its_point_within_two_percent(manoeuvres):
    run, at = manoeuvres
    start, end = at["curve"], at["drive"]
    x, y = ahead(start, 0.4, 0.15)
    assert math.hypot(end["x"] - x, end["y"] - y) < 0.02 * math.hypot(0.4, 0.15)
    # leaving straight ahead, the arc arrives turned by twice the angle to the point
    assert turned(start, end) == pytest.approx(2 * math.degrees(math.atan2(0.15, 0.4)), abs=2.0)


def test_remain_counts_down_to_zero_and_done_flips(manoeuvres):
    run, _ = manoeuvres
    [[remain_start, done_start, decreasing, samples, remain_end]] = run.values(1, "remain")
    assert remain_start == 1000 and done_start == 0
    assert decreasing == 1 and samples > 30
    assert remain_end == 0


def test_an_unreachable_drive_is_an_error(manoeuvres):
    run, _ = manoeuvres
    assert run.values(1, "unreachable") == [[1]]
    assert "VWDrive" in run.stderr and "dx must be at least |dy|" in run.stderr


def test_odometry_agrees_with_the_true_pose_on_a_two_metre_square(drive):
    run = drive(["S4 1000 1000 0"], {1: "square_odometry"})
    corners = run.values(1, "corner")
    assert len(corners) == 4
    for ox, oy, ophi, x, y, phi in corners:
        assert math.hypot(ox - x, oy - y) <= 0.02 * 2000  # within 2 % of the path driven
        assert abs((ophi - phi + 180) % 360 - 180) <= 3
    x, y = corners[-1][3:5]
    assert math.hypot(x, y) < 40  # the square closes


def test_a_robot_driving_into_a_wall_stalls_there(drive):
    run = drive(["S4 1000 500 0"], {1: "wall_stall"}, size=2000)
    assert run.values(1, "before") == [[0]]
    [[stalled, still, x, y]] = run.values(1, "stalled")
    assert stalled == 3 and still == 3  # both wheels
    front = x + 82  # the S4's front skid reaches 82 mm ahead of its centre
    wall = 1995  # the wall's inner face; contacts may give by a few mm, never by the wall's 10 mm
    assert wall - 10 <= front <= wall + 3
    assert max(row["x"] for row in run.trajectory[1]) * 1000 + 82 <= wall + 3
    assert run.values(1, "after") == [[0]]


def test_encoders_count_wheel_turns_and_speed_control_holds_ticks_per_second(drive):
    run = drive(["S4 500 1000 0"], {1: "encoders"})
    [[left, right, dx, dy]] = run.values(1, "open")
    travelled = math.hypot(dx, dy)
    per_tick = math.pi * 54 / 1100  # mm of S4 wheel circumference per tick
    assert left > 1000 and right > 1000
    assert (left + right) / 2 * per_tick == pytest.approx(travelled, rel=0.02)
    [[left_speed, right_speed]] = run.values(1, "speed")
    assert left_speed == pytest.approx(1000, rel=0.02) and right_speed == pytest.approx(1000, rel=0.02)
    # motor 3 does not exist, 101 % is too much, no encoder 5, too fast, no servo, gain beyond 255
    assert run.values(1, "errors") == [[1, 1, 1, 1, 1, 1]]
    messages = [line for line in run.stderr.splitlines() if line.startswith("[robot 1]")]
    assert len(messages) == 6, messages
