"""VW manoeuvres against the true pose: series of turns do not drift, and a robot stuck in a
corner ends its manoeuvres stalled instead of waiting for ever (real C programs)."""

import math


def heading(row) -> float:
    """Heading in degrees of a recorded pose (the robot stays level)."""
    return math.degrees(2 * math.atan2(row["qz"], row["qw"]))


def heading_error(start, end, turns: int) -> float:
    """Degrees the true heading is off after `turns` quarter turns to the left."""
    return (heading(end) - heading(start) - 90 * turns + 180) % 360 - 180


def test_twelve_quarter_turns_and_a_square_end_on_the_true_heading(drive):
    run = drive(["S4 1500 1500 0"], {1: "vw_accuracy"})
    at = run.marks(1)
    errors = {
        speed: heading_error(previous, at[f"turns{speed}"], 12)
        for speed, previous in ((20, at["start"]), (45, at["turns20"]), (90, at["turns45"]))
    }
    assert all(abs(error) <= 0.5 for error in errors.values()), errors
    assert abs(heading_error(at["turns90"], at["square"], 4)) <= 0.5
    start, end = at["turns90"], at["square"]
    assert math.hypot(end["x"] - start["x"], end["y"] - start["y"]) < 0.01  # the square closes


def test_a_robot_jammed_in_a_corner_ends_its_manoeuvres_stalled(drive):
    run = drive(["S4 400 400 225"], {1: "corner_jam"}, size=2000)
    [[done, stalled, x, y]] = run.values(1, "straight")
    assert done == 1 and stalled != 0
    assert x < 150 and y < 150  # it reached the south-west corner
    [[done, stalled]] = run.values(1, "turn")
    assert done == 1 and stalled != 0
    [[done, stalled]] = run.values(1, "back")
    assert done == 1 and stalled == 0


def ahead(row, forward: float, left: float) -> tuple[float, float]:
    """The point `forward` m ahead and `left` m to the left of a recorded pose."""
    phi = math.radians(heading(row))
    return (
        row["x"] + forward * math.cos(phi) - left * math.sin(phi),
        row["y"] + forward * math.sin(phi) + left * math.cos(phi),
    )


def test_vw_drive_as_far_ahead_as_aside_is_a_quarter_circle(drive):
    run = drive(["S4 1000 1000 0"], {1: "quarter_circles"})
    assert run.values(1, "left") == [[0]] and run.values(1, "right") == [[0]]
    at = run.marks(1)
    for start, end, side, turn in ((at["start"], at["left"], 0.2, 90), (at["left"], at["right"], -0.2, -90)):
        x, y = ahead(start, 0.2, side)
        assert math.hypot(end["x"] - x, end["y"] - y) < 0.005  # at (200, +-200) within 5 mm
        assert abs((heading(end) - heading(start) - turn + 180) % 360 - 180) < 1.0


def angle_error(measured: float, target: float) -> float:
    """Degrees between two headings, whatever whole turns lie between them."""
    return (measured - target + 180) % 360 - 180


def test_small_turns_take_what_the_ramps_allow_and_tight_arcs_end_on_their_heading(drive):
    run = drive(["S4 1500 1500 0"], {1: "small_manoeuvres"})
    at = run.marks(1)
    spot_radius = 0.045  # m: the S4's half track
    # Turns: each as fast as accelerating at 1 m/s^2 and braking at 0.5 m/s^2 (the VW ramps, wheel
    # speed) allows, plus 40 ms for the last crawl, the calls' time and a step or two. Before, the
    # crawl alone took 125 ms, a one-degree turn 146 ms.
    turns = run.values(1, "turn")
    assert len(turns) == 13
    heading_now = heading(at["start"])
    for i, (angle, took_ms) in enumerate(turns):
        travel = math.radians(abs(angle)) * spot_radius
        allowed_ms = 1000 * math.sqrt(2 * travel * (1 / 1.0 + 1 / 0.5)) + 40
        assert took_ms <= allowed_ms, (angle, took_ms, allowed_ms)
        heading_now += angle
        # within the S4's 0.2-degree encoder steps of where the turns so far should have left it
        assert abs(angle_error(heading(at[f"turn{i}"]), heading_now)) <= 0.3, (i, angle)
    # Arcs: the odometry ends at the arc's end and heading, and so does the robot.
    curves = run.values(1, "curve")
    assert len(curves) == 5
    before = at[f"turn{len(turns) - 1}"]
    for i, (dist, angle, x, y, phi) in enumerate(curves):
        end = at[f"curve{i}"]
        radius = dist / math.radians(angle)  # mm, signed: the arc's end in the frame it started in
        ahead_mm, left_mm = radius * math.sin(math.radians(angle)), radius * (1 - math.cos(math.radians(angle)))
        assert abs(angle_error(phi, angle)) <= 1, (dist, angle, phi)  # VWGetPosition's whole degrees
        assert math.hypot(x - ahead_mm, y - left_mm) <= 3, (dist, angle, x, y)
        assert abs(angle_error(heading(end) - heading(before), angle)) <= 1, (dist, angle)
        true_x, true_y = ahead(before, ahead_mm / 1000, left_mm / 1000)
        assert math.hypot(end["x"] - true_x, end["y"] - true_y) <= 0.005, (dist, angle)
        before = end
