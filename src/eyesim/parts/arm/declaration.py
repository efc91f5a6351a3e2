"""A manipulator arm (`arm`, `joint` lines) and its gripper (`gripper`); how they move:
component.py."""

from __future__ import annotations

from dataclasses import dataclass, field

from eyesim.scene.diagnostics import quoted
from eyesim.scene.lexer import Line, format_number, quote_token
from eyesim.parts.part import (
    Part,
    PartReader,
    choice,
    coordinate,
    in_schema,
    list_of,
    positive,
    record_of,
    ref,
    text,
    whole,
)


@dataclass(frozen=True)
class JointSpec:
    """One arm joint by its standard Denavit-Hartenberg parameters (link i: rotate theta about
    z, move d along z, move a along x, rotate alpha about x). A 'revolute' joint turns: theta is
    its zero offset and the limits are degrees; a 'prismatic' joint slides: d is its zero offset
    and the limits are mm. SERVOSet(servo, 0..255) maps linearly onto [min, max]."""

    name: str = field(metadata=in_schema(text("Name")))
    servo: int = field(metadata=in_schema(whole(1, "Servo")))
    kind: str = field(metadata=in_schema(choice("Kind", ["revolute", "prismatic"])))
    d: float = field(metadata=in_schema(coordinate("d", "mm")))
    theta: float = field(metadata=in_schema(coordinate("theta", "degrees")))
    a: float = field(metadata=in_schema(coordinate("a", "mm")))
    alpha: float = field(metadata=in_schema(coordinate("alpha", "degrees")))
    min: float = field(metadata=in_schema(coordinate("Minimum", "degrees (revolute) or mm (prismatic)")))
    max: float = field(metadata=in_schema(coordinate("Maximum")))


@dataclass(frozen=True)
class GripperSpec:
    """A two-finger gripper on the last joint: servo 0 = closed, 255 = open `opening` mm;
    it squeezes with at most `force` newtons."""

    servo: int = field(metadata=in_schema(whole(1, "Servo")))
    opening: float = field(metadata=in_schema(positive("Opening", "mm")))
    force: float = field(metadata=in_schema(positive("Force", "N")))


@dataclass(frozen=True)
class ArmSpec:
    """A manipulator arm mounted at (x, y, z) mm on the robot (robot frame), its base turned
    by `heading` degrees; joints from the base outwards."""

    x: float = field(default=0.0, metadata=in_schema(coordinate("x")))
    y: float = field(default=0.0, metadata=in_schema(coordinate("y")))
    z: float = field(default=0.0, metadata=in_schema(coordinate("z")))
    heading: float = field(default=0.0, metadata=in_schema(coordinate("Heading")))
    joints: tuple[JointSpec, ...] = field(default=(), metadata=in_schema(list_of("joint", "Joints")))
    gripper: GripperSpec | None = field(default=None, metadata=in_schema(ref("gripper")))


@dataclass(frozen=True, kw_only=True)
class ArmFields:
    """What a robot type says about its arm."""

    arm: ArmSpec | None = field(default=None, metadata=in_schema(ref("arm")))


def read_arm(reader: PartReader, line: Line) -> None:
    if reader.arity(line, (3, 4), "<x> <y> <z> [<heading>]"):
        values = reader.numbers(line, 1, ("x", "y", "z", "heading")[: len(line.args)])
        if values:
            reader.collected["arm"] = tuple(v + 0.0 for v in values) + ((0.0,) if len(values) == 3 else ())


def read_joint(reader: PartReader, line: Line) -> None:
    if not reader.arity(line, (9,), "<NAME> <servo> revolute|prismatic <d> <theta> <a> <alpha> <min> <max>"):
        return
    servo = reader.whole(line, 2, "servo number", 1)
    kind = line.args[2].text.lower()
    if kind not in ("revolute", "prismatic"):
        reader.error(line, f"joint: expected revolute or prismatic, found {quoted(line.args[2].text)}", 3)
        return
    values = reader.numbers(
        line, 4, ("d in mm", "theta in degrees", "a in mm", "alpha in degrees", "minimum", "maximum")
    )
    if servo is None or not values:
        return
    joints = reader.collected.setdefault("joints", [])
    joints.append(JointSpec(line.args[0].text, servo, kind, *(v + 0.0 for v in values)))
    reader.remember(f"joint:{len(joints) - 1}", line)


def read_gripper(reader: PartReader, line: Line) -> None:
    if not reader.arity(line, (3,), "<servo> <opening mm> <force N>"):
        return
    servo = reader.whole(line, 1, "servo number", 1)
    values = reader.numbers(line, 2, ("opening in mm", "force in N"))
    if servo is None or not values:
        return
    if reader.positive(line, values[0], 2, "opening") and reader.positive(line, values[1], 3, "force"):
        reader.collected["gripper"] = GripperSpec(servo, values[0], values[1])
        reader.remember("gripper", line)


def finish(reader: PartReader) -> None:
    """An arm when any of its lines was given; mounted on top of the chassis unless `arm` says
    where (so this part finishes after the body)."""
    mount, joints, gripper = (reader.collected.get(key) for key in ("arm", "joints", "gripper"))
    if joints or mount is not None or gripper is not None:
        x, y, z, heading = mount if mount is not None else (0.0, 0.0, reader.fields["height"], 0.0)
        reader.fields["arm"] = ArmSpec(x, y, z, heading, tuple(joints or ()), gripper)


def check(robot, diagnostics, at) -> dict:
    for i, joint in enumerate(robot.arm.joints if robot.arm is not None else ()):
        if joint.min > joint.max:
            diagnostics.error(
                at(f"joint:{i}"),
                f"joint {joint.name}: expected min <= max, found "
                f"{format_number(joint.min)} > {format_number(joint.max)}",
                "bad-value",
            )
    return {}


def servos(robot) -> list[tuple[int, str, str]]:
    if robot.arm is None:
        return []
    users = [(joint.servo, f"joint {joint.name}", f"joint:{i}") for i, joint in enumerate(robot.arm.joints)]
    if robot.arm.gripper is not None:
        users.append((robot.arm.gripper.servo, "the gripper", "gripper"))
    return users


def write(robot) -> list[str]:
    a = robot.arm
    if a is None:
        return []
    f = format_number
    out = [f"arm {f(a.x)} {f(a.y)} {f(a.z)} {f(a.heading)}"]
    for j in a.joints:
        out.append(
            f"joint {quote_token(j.name)} {j.servo} {j.kind} "
            + " ".join(f(v) for v in (j.d, j.theta, j.a, j.alpha, j.min, j.max))
        )
    if a.gripper is not None:
        out.append(f"gripper {a.gripper.servo} {f(a.gripper.opening)} {f(a.gripper.force)}")
    return out


def json_locations(robot, positions) -> dict:
    if robot.arm is None:
        return {}
    where = {f"joint:{i}": positions.value(["arm", "joints", i]) for i in range(len(robot.arm.joints))}
    where["gripper"] = positions.value(["arm", "gripper"])
    return where


PART = Part(
    "arm",
    components=("eyesim.parts.arm.component:create",),
    fields=ArmFields,
    keywords={"arm": read_arm, "joint": read_joint, "gripper": read_gripper},
    write=write,
    finish=finish,
    defs={
        "joint": record_of(JointSpec, "Joint", "an arm joint by its Denavit-Hartenberg parameters"),
        "gripper": record_of(GripperSpec, "Gripper", "a two-finger gripper"),
        "arm": record_of(ArmSpec, "Arm", "a manipulator arm and where it is mounted"),
    },
    json_locations=json_locations,
    check=check,
    servos=servos,
)
