"""The .robi robot format: EyeSim 6, VR 0.9 and VR 1.x dialects, our own keywords, the writer."""

import dataclasses

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from eyesim.scene.description import (
    ArmSpec,
    BuoyancySpec,
    CameraSpec,
    Collider,
    DragSpec,
    GripperSpec,
    JointSpec,
    LidarSpec,
    PsdSpec,
    RobotType,
    SteeringSpec,
    ThrusterSpec,
    WheelSpec,
)
from eyesim.scene.diagnostics import Diagnostics
from eyesim.scene.lexer import read_text
from eyesim.scene.robi import detect_dialect, parse_robi, write_robi
from scene_testing import CORPUS, corpus_texts, mutated, random_text

ROBOTS = CORPUS / "ASAX21__VRRoboticProject/Test Assets/robots"


def parse(text, source="r.robi"):
    diagnostics = Diagnostics()
    return parse_robi(text, source, diagnostics), diagnostics


def corpus_robot(relative):
    return parse(read_text(CORPUS / relative), str(CORPUS / relative))


def geometry(robot):
    return robot.psds, robot.wheels, (robot.camera.x, robot.camera.y, robot.camera.z)


def test_vr_and_eyesim6_s4_have_the_same_geometry():
    e6, _ = parse(read_text(ROBOTS / "S4.robi"))
    vr, _ = parse(read_text(ROBOTS / "S4/S4.robi"))
    assert geometry(e6) == geometry(vr)
    assert e6.wheels == WheelSpec(54, 3600, 1100, 90)
    assert [(p.id, p.name, p.x, p.y, p.z, p.heading) for p in e6.psds] == [
        (1, "PSD_FRONT", 60, 20, 30, 0),
        (2, "PSD_LEFT", 56, 45, 30, 90),
        (3, "PSD_RIGHT", 56, -45, 30, -90),
    ]


def test_vr_s4_body_is_converted_from_model_space():
    vr, diagnostics = parse(read_text(ROBOTS / "S4/S4.robi"))
    assert vr.colliders[0] == Collider("box", (65, 95, 74), (-50, 0, 46))
    assert vr.colliders[2] == Collider("capsule", (10, 50), (-60, 0, 21), "z")
    assert (vr.length, vr.width, vr.height) == (157.5, 95, 83)
    assert (vr.axis_offset, vr.axle_height) == (10.8, 22.7)
    assert vr.center_of_mass == (-30, 0, 30)
    assert vr.mass == 0.62 and [d.code for d in diagnostics.items] == ["implausible-mass"]


def test_s4blue_vr1_dialect():
    robot, diagnostics = corpus_robot("NoahWMueller__Eyesim/Sims/Updated_Robots/S4blue.robi")
    e6, _ = parse(read_text(ROBOTS / "S4.robi"))
    assert robot.psds[:3] == e6.psds
    assert robot.psds[3] == PsdSpec(4, "PSD_BACK", 61, 20, -30, 180)
    assert (robot.camera.x, robot.camera.y, robot.camera.z) == (62, 0, 60)  # written as (right, front, up)
    assert robot.camera.fisheye and robot.camera.fov == 150
    assert robot.wheels.track == 90
    codes = sorted(d.code for d in diagnostics.items)
    assert codes == ["below-floor", "implausible-mass", "unknown-keyword"]


def test_labbot_files():
    e6, _ = parse(read_text(CORPUS / "ASAX21__VRRoboticProject/RobotVR/Assets/Robots/LabBot.robi"))
    assert (e6.name, e6.length, e6.width, e6.axis_offset, e6.wheels.track) == ("LabBot", 260, 260, 40, 145)
    assert e6.drive_motors == ("MOTOR_LEFT", "QUAD_LEFT", "MOTOR_RIGHT", "QUAD_RIGHT")
    vr, _ = parse(read_text(ROBOTS / "LabBot/LabBot.robi"))
    assert (vr.name, vr.length, vr.width, vr.height) == ("LabBot2", 200, 180, 154.5)
    assert vr.wheels.track == 140 and vr.lidar == LidarSpec(360, 0)
    assert vr.camera.pan_range == (-90, 90)


def test_ackermann_axles_and_wheels():
    robot, diagnostics = parse(read_text(ROBOTS / "Ackermann/Ackermann.robi"))
    assert robot.drive == "ackermann" and not diagnostics.items
    assert (robot.axis_offset, robot.axle_height) == (-94, 22.7)
    assert robot.wheels == WheelSpec(40, 7200, 640, 89)
    assert robot.steering == SteeringSpec(66.1, 12.6, WheelSpec(28, 7200, 640, 81.26))
    assert robot.model_rotation == (0, 180, 0)


def test_eyesim6_negative_ids_and_servo_camera():
    odw, _ = corpus_robot("ASAX21__VRRoboticProject/Test Assets/examples/omni/odw.robi")
    assert [p.id for p in odw.psds] == [1, 2, 3, 4, 5, 6, 7]
    assert odw.drive == "omni" and odw.wheels.track == 220
    s4y, _ = corpus_robot("ASAX21__VRRoboticProject/Test Assets/examples/pantilt/S4Y.robi")
    assert [p.id for p in s4y.psds] == [1, 2, 3]  # the 5-argument form has no id
    assert (s4y.camera.pan_servo, s4y.camera.pan_range) == (1, (-90, 90))
    assert (s4y.camera.tilt_servo, s4y.camera.tilt_range) == (2, (-95, 85))


def test_psd_argument_orders_agree():
    forms = [
        "psd PSD_LEFT 2 56 45 30 90",
        "psd 2 PSD_LEFT 56 45 30 0 90 0",
        "psd PSD_LEFT 56 45 30 90",
        "psd PSD_LEFT -205 56 45 30 90",
    ]
    psds = {parse("dialect eyesim\nwheel 54 3600 1100 90\n" + f)[0].psds for f in forms}
    assert psds == {(PsdSpec(2, "PSD_LEFT", 56, 45, 30, 90),)}


def test_pitch_from_the_eight_argument_form():
    robot, _ = parse("wheel 54 3600 1100 45\npsd 5 PSD_DOWN 80 0 50 -30 0 0\n")
    assert robot.psds == (PsdSpec(5, "PSD_DOWN", 80, 0, 50, 0, -30),)


@pytest.mark.parametrize(
    "text, dialect",
    [
        ("drive DIFFERENTIAL_DRIVE MOTOR_LEFT QUAD_LEFT\nwheel 1 1 1 1", "eyesim6"),
        ("drive DIFFERENTIAL_DRIVE\nmass 1 0 0 0", "vr"),
        ("model a.obj 0 0 0 0 90 0", "vr"),
        ("axis 22.7 10.8", "vr"),
        ("wheel drive 40 7200 640 44.5", "vr"),
        ("psd 1 PSD_FRONT 1 2 3 0 0 0", "vr1"),
        ("fisheye 120", "vr1"),
        ("dialect eyesim\nmass 1 0 0 0\nfisheye 120", "eyesim"),
    ],
)
def test_dialect_detection(text, dialect):
    from eyesim.scene.lexer import split_lines

    assert detect_dialect(split_lines(text, "r", Diagnostics())) == dialect


def test_camera_last_numbers_by_dialect():
    e6, _ = parse("drive DIFFERENTIAL_DRIVE MOTOR_LEFT QUAD_LEFT\nwheel 54 3600 1100 90\ncamera 62 0 60 0 0 80 60")
    vr, _ = parse("axis 0 0\nwheel 54 3600 1100 45\ncamera 62 0 60 0 0 80 60")
    image, _ = parse("axis 0 0\nwheel 54 3600 1100 45\ncamera 62 0 60 0 0 482 162")
    assert e6.camera.pan_range == (-90, 90)  # EyeSim 6: image size, not limits
    assert (vr.camera.pan_range, vr.camera.tilt_range) == ((-80, 80), (-60, 60))
    assert image.camera.pan_range == (-90, 90)


SUBMARINE = """\
dialect eyesim
drive SUBMARINE
name Mako
size 600 300 250
mass 4.5 0 0 110
thruster LEFT  1 -250  120 125  1 0 0  20
thruster RIGHT 2 -250 -120 125  1 0 0  20
thruster FRONT 3  200    0 125  0 0 1  10
thruster BACK  4 -200    0 125  0 0 1  10
buoyancy 4.6 0 0 150
drag 30 60 60 2
psd PSD_FRONT 1 300 0 125 0
camera 290 0 150 0 0 90 90
"""

ARM = """\
dialect eyesim
drive ARM
name Arm3
size 150 150 80
mass 2
arm 0 0 80
joint BASE     1 revolute    100 0   0  90 -150 150
joint SHOULDER 2 revolute      0 90 200  0  -90  90
joint SLIDE    3 prismatic    10 0   0   0    0 120
gripper 4 60 15
"""

MOBILE_MANIPULATOR = """\
dialect eyesim
drive DIFFERENTIAL_DRIVE
name Picker
size 250 200 120
mass 2.5
wheel 65 3600 1100 180
camera 120 0 140 0 0 90 90
arm 60 0 120 0
joint BASE     1 revolute 80 0   0 90 -180 180
joint ELBOW    2 revolute  0 0 120  0 -120 120
gripper 3 50 10
"""


def test_submarine_keywords():
    robot, diagnostics = parse(SUBMARINE)
    assert not diagnostics.items
    assert robot.drive == "submarine" and robot.wheels is None
    assert robot.thrusters[0] == ThrusterSpec("LEFT", 1, -250, 120, 125, 1, 0, 0, 20)
    assert robot.buoyancy == BuoyancySpec(4.6, 0, 0, 150)
    assert robot.drag == DragSpec(30, 60, 60, 2)


def test_arm_keywords():
    robot, diagnostics = parse(ARM)
    assert not diagnostics.items
    assert robot.drive == "arm"
    assert robot.arm == ArmSpec(
        0,
        0,
        80,
        0,
        (
            JointSpec("BASE", 1, "revolute", 100, 0, 0, 90, -150, 150),
            JointSpec("SHOULDER", 2, "revolute", 0, 90, 200, 0, -90, 90),
            JointSpec("SLIDE", 3, "prismatic", 10, 0, 0, 0, 0, 120),
        ),
        GripperSpec(4, 60, 15),
    )


def test_a_drive_base_that_carries_an_arm():
    robot, diagnostics = parse(MOBILE_MANIPULATOR)
    assert not diagnostics.items
    assert robot.drive == "differential" and robot.wheels.track == 180
    assert len(robot.arm.joints) == 2 and robot.arm.gripper.servo == 3


def test_joints_without_an_arm_line_sit_on_top_of_the_chassis():
    robot, _ = parse("dialect eyesim\ndrive ARM\nsize 100 100 70\njoint J 1 revolute 0 0 50 0 -90 90\n")
    assert (robot.arm.x, robot.arm.y, robot.arm.z) == (0, 0, 70)


@pytest.mark.parametrize(
    "line, code, column",
    [
        ("drive TANK", "syntax", 7),
        ("psd PSD_FRONT 1 a 0 0 0", "syntax", 17),
        ("wheel 54 3600 11.5 90", "syntax", 15),
        ("wheel 0 3600 1100 90", "bad-value", 7),
        ("camera 1 2 3 SERVO1(-90) 0 90 90", "syntax", 14),
        ("joint J 1 rotary 0 0 0 0 0 1", "syntax", 11),
        ("lidar 360 95", "bad-value", 11),
        ("collider cone 1 2 3", "syntax", 10),
        ("size 100 0 50", "bad-value", 10),
        ("color 300 0 0", "bad-value", 7),
        ("thruster T 1 0 0 0 0 0 0 -5", "bad-value", 26),
        ("dialect klingon", "syntax", 9),
    ],
)
def test_errors_point_at_the_offending_text(line, code, column):
    _, diagnostics = parse("dialect eyesim\n" + line)
    errors = [d for d in diagnostics.items if d.kind == "error"]
    assert [(d.code, d.location.line, d.location.column) for d in errors][:1] == [(code, 2, column)]


@pytest.mark.parametrize(
    "text, needle",
    [
        ("wheel 1 1 1 1\npsd A 1 0 0 0 0\npsd B 1 0 0 0 0", "already used by A"),
        ("wheel 1 1 1 1\ncamera 0 0 0 SERVO1(-90,90) 0 90 90\njoint J 1 revolute 0 0 0 0 0 1", "servo 1"),
        ("drive ARM\njoint J 1 revolute 0 0 0 0 10 1", "min <= max"),
        ("drive SUBMARINE\nthruster A 1 0 0 0 0 0 0 5", "direction"),
        ("drive SUBMARINE\nthruster A 1 0 0 0 1 0 0 5\nthruster B 1 0 0 0 1 0 0 5", "motor 1"),
    ],
)
def test_contradictions_are_errors(text, needle):
    _, diagnostics = parse("dialect eyesim\n" + text)
    assert any(d.kind == "error" and needle in d.message for d in diagnostics.items)


def test_unknown_keywords_and_missing_name_are_warnings():
    robot, diagnostics = parse("Robi file:\nwheel 54 3600 1100 90\n", "/x/MyBot.robi")
    assert robot.name == "MyBot"
    assert sorted(d.code for d in diagnostics.items) == ["no-name", "unknown-keyword"]


@pytest.mark.parametrize("text", corpus_texts("robi") + [SUBMARINE, ARM, MOBILE_MANIPULATOR])
def test_write_and_read_back(text):
    robot, _ = parse(text)
    again, diagnostics = parse(write_robi(robot))
    assert again == robot
    assert not [d for d in diagnostics.items if d.code not in ("below-floor",)]


names = st.text(alphabet=st.sampled_from("abcXYZ_0189 -"), min_size=1, max_size=12).map(str.strip).filter(bool)
tokens = st.text(alphabet=st.sampled_from("ABCMOTR_QUAD12"), min_size=1, max_size=10)
coord = st.floats(-1000, 1000, allow_nan=False)
size = st.floats(1, 1000, allow_nan=False)


@st.composite
def robots(draw):
    drive = draw(st.sampled_from(["differential", "ackermann", "omni", "submarine", "arm"]))
    length, width, height = draw(size), draw(size), draw(size)
    mass = draw(st.floats(0.01, 1)) * 7.9e-6 * length * width * height
    wheel = st.builds(WheelSpec, size, size, st.integers(1, 10_000), size)
    servos = iter(range(1, 100))
    camera = None
    if draw(st.booleans()):
        pan_servo = next(servos) if draw(st.booleans()) else None
        lo = draw(st.floats(-180, 0))
        camera = CameraSpec(
            draw(coord),
            draw(coord),
            draw(coord),
            pan=0.0 if pan_servo else draw(coord),
            tilt=draw(coord),
            fov=draw(st.floats(1, 360)),
            pan_servo=pan_servo,
            pan_range=(lo, draw(st.floats(lo, 180))) if pan_servo else (lo, -lo),
            fisheye=draw(st.booleans()),
        )
    psds = tuple(
        PsdSpec(i + 1, draw(tokens), draw(coord), draw(coord), draw(st.floats(0, 500)), draw(coord), draw(coord))
        for i in range(draw(st.integers(0, 4)))
    )
    arm = None
    if drive == "arm" or draw(st.booleans()):
        joints = tuple(
            JointSpec(
                draw(tokens),
                next(servos),
                draw(st.sampled_from(["revolute", "prismatic"])),
                draw(coord),
                draw(coord),
                draw(coord),
                draw(coord),
                -10.0,
                draw(st.floats(-10, 100)),
            )
            for _ in range(draw(st.integers(1, 3)))
        )
        gripper = GripperSpec(next(servos), draw(size), draw(size)) if draw(st.booleans()) else None
        arm = ArmSpec(draw(coord), draw(coord), draw(coord), draw(coord), joints, gripper)
    thrusters = ()
    if drive == "submarine":
        thrusters = tuple(
            ThrusterSpec(
                draw(tokens), i + 1, draw(coord), draw(coord), draw(coord), 1.0, draw(coord), draw(coord), draw(size)
            )
            for i in range(draw(st.integers(1, 4)))
        )
    collider = st.one_of(
        st.builds(Collider, st.just("box"), st.tuples(size, size, size), st.tuples(coord, coord, coord)),
        st.builds(Collider, st.just("sphere"), st.tuples(size), st.tuples(coord, coord, coord)),
        st.builds(
            Collider,
            st.sampled_from(["capsule", "cylinder"]),
            st.tuples(size, size),
            st.tuples(coord, coord, coord),
            st.sampled_from("xyz"),
        ),
    )
    return RobotType(
        name=draw(names),
        source="r.robi",
        drive=drive,
        mass=mass,
        length=length,
        width=width,
        height=height,
        color=draw(st.tuples(*[st.integers(0, 255)] * 3)),
        max_speed=draw(size),
        max_turn=draw(size),
        axis_offset=draw(coord),
        wheels=draw(wheel) if drive not in ("submarine", "arm") else draw(st.none() | wheel),
        psds=psds,
        camera=camera,
        lidar=draw(st.none() | st.builds(LidarSpec, st.integers(1, 2000), st.floats(-89, 89))),
        model=draw(st.none() | st.just("models/my bot.obj")),
        colliders=tuple(draw(st.lists(collider, max_size=3))),
        drive_motors=tuple(draw(st.lists(tokens, max_size=4))),
        center_of_mass=draw(st.none() | st.tuples(coord, coord, coord)),
        axle_height=draw(st.none() | size),
        steering=draw(st.none() | st.builds(SteeringSpec, coord, st.none() | size, st.none() | wheel)),
        model_offset=draw(st.tuples(coord, coord, coord)),
        model_rotation=draw(st.tuples(coord, coord, coord)),
        thrusters=thrusters,
        buoyancy=draw(st.none() | st.builds(BuoyancySpec, size, coord, coord, coord)),
        drag=draw(st.none() | st.builds(DragSpec, size, size, size, size)),
        arm=arm,
    )


@settings(max_examples=200, deadline=None)
@given(robots())
def test_any_robot_type_survives_writing_and_reading(robot):
    if robot.model is None:
        robot = dataclasses.replace(robot, model_offset=(0.0, 0.0, 0.0), model_rotation=(0.0, 0.0, 0.0))
    again, diagnostics = parse(write_robi(robot))
    assert not diagnostics.has_errors
    assert again == robot


@settings(max_examples=200, deadline=None)
@given(random_text())
def test_random_text_never_crashes(text):
    parse(text)


@settings(max_examples=300, deadline=None)
@given(mutated(corpus_texts("robi")))
def test_mutated_robots_never_crash(text):
    parse(text)
