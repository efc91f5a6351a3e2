"""Completing and checking robot types, whichever file they came from."""

from eyesim.scene.description import (
    ArmSpec,
    CameraSpec,
    GripperSpec,
    JointSpec,
    Location,
    PsdSpec,
    RobotType,
    ThrusterSpec,
)
from eyesim.scene.diagnostics import Diagnostics
from eyesim.scene.parts.wheels import DEFAULT_WHEELS
from eyesim.scene.robot_type import finish_robot_type

HERE = Location("r.robi", 1, 1)


def finish(robot):
    diagnostics = Diagnostics()
    return finish_robot_type(robot, diagnostics, {"mass": Location("r.robi", 7, 1)}, HERE), diagnostics


def test_wheeled_robot_without_wheels_gets_the_s4_wheels():
    robot, diagnostics = finish(RobotType("R", "r"))
    assert robot.wheels == DEFAULT_WHEELS and [d.code for d in diagnostics.items] == ["missing-wheels"]


def test_impossible_mass_is_replaced_by_an_estimate():
    robot, diagnostics = finish(RobotType("R", "r", wheels=DEFAULT_WHEELS, mass=50, length=160, width=95, height=83))
    assert robot.mass == 0.63
    (d,) = diagnostics.items
    assert d.code == "implausible-mass" and d.location.line == 7 and "50 kg" in d.message


def test_plausible_mass_is_kept():
    robot, diagnostics = finish(RobotType("R", "r", wheels=DEFAULT_WHEELS, mass=7, length=200, width=200, height=200))
    assert robot.mass == 7 and not diagnostics.items


def test_conflicts():
    arm = ArmSpec(
        joints=(JointSpec("A", 1, "revolute", 0, 0, 0, 0, 0, 1), JointSpec("B", 1, "revolute", 0, 0, 0, 0, 5, 1)),
        gripper=GripperSpec(0, 1, 1),
    )
    robot = RobotType(
        "R",
        "r",
        drive="submarine",
        arm=arm,
        camera=CameraSpec(0, 0, 0, pan_servo=2, tilt_servo=2),
        psds=(PsdSpec(1, "A", 0, 0, 0, 0), PsdSpec(1, "B", 0, 0, 0, 0)),
        thrusters=(ThrusterSpec("T", 1, 0, 0, 0, 0, 0, 0, 1), ThrusterSpec("U", 1, 0, 0, 0, 1, 0, 0, 1)),
    )
    _, diagnostics = finish(robot)
    errors = sorted(d.message for d in diagnostics.items if d.kind == "error")
    assert len(errors) == 7
    assert any("PSD id 1" in e for e in errors) and any("servo 2" in e for e in errors)
    assert any("servo 1 of joint B" in e for e in errors) and any("min <= max" in e for e in errors)
    assert any("servo number from 1" in e for e in errors) and any("motor 1" in e for e in errors)
    assert any("direction" in e for e in errors)
