"""The example mecanum robot under a real C program: sideways and straight by its encoders."""

import math

import pytest


def test_the_mecanum_robot_drives_sideways_and_ahead(drive):
    run = drive(["Mecanum 1500 1000 30"], {1: "omni_sideways"}, robots=["Mecanum"])
    [[x0, y0, phi0]] = run.values(1, "start")
    [[x1, y1, phi1]] = run.values(1, "left")
    [[x2, y2, phi2]] = run.values(1, "forward")
    heading = math.radians(phi0)
    left = -(x1 - x0) * math.sin(heading) + (y1 - y0) * math.cos(heading)
    sideways_drift = (x1 - x0) * math.cos(heading) + (y1 - y0) * math.sin(heading)
    assert left == pytest.approx(500, rel=0.02)
    assert abs(sideways_drift) < 10
    forward = (x2 - x1) * math.cos(heading) + (y2 - y1) * math.sin(heading)
    assert forward == pytest.approx(300, rel=0.02)
    assert phi0 == phi1 == phi2  # no turning
