"""The chassis: name, size, colour, mass, speed limits, drive axle position, 3-D model and colliders."""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING

from eyesim.scene.diagnostics import Location, quoted
from eyesim.scene.lexer import LARGEST, Line, format_number, quote_token
from eyesim.parts.part import (
    VR_AXIS,
    Part,
    PartReader,
    choice,
    coordinate,
    in_schema,
    list_of,
    numbers,
    positive,
    record_of,
    text,
)

if TYPE_CHECKING:
    from eyesim.scene.parts import RobotType

DEFAULT_HEIGHT = 80.0  # mm of a robot whose file gives only a diameter
CHASSIS_CLEARANCE = 0.012  # m between the floor and the chassis bottom of a wheeled robot
GLIDER_LIFT = 1.0  # mm a gliding hull collider stays above the floor at least (as the drives' casters)
MAX_DENSITY = 8.0  # g/cm3: a robot heavier than solid steel of its size is a typo
ESTIMATED_DENSITY = 0.5  # g/cm3 of a typical small robot (S4: 0.8 kg in 2.4 litres)
DEFAULTS = {"length": 180.0, "width": 150.0, "height": 80.0}
POINT = "(x, y, z) in mm"
COLLIDER_FORMS = {
    "box": ("<sx> <sy> <sz> <cx> <cy> <cz>", 6),
    "sphere": ("<r> <cx> <cy> <cz>", 4),
    "capsule": ("<r> <h> <cx> <cy> <cz> [x|y|z]", 5),
    "cylinder": ("<r> <h> <cx> <cy> <cz> [x|y|z]", 5),
}
COLLIDER_SIZES = {
    "box": ("size x", "size y", "size z"),
    "sphere": ("radius",),
    "capsule": ("radius", "height"),
    "cylinder": ("radius", "height"),
}


@dataclass(frozen=True)
class Collider:
    """A collision shape in the robot/object frame (mm): kind 'box' (size = sx, sy, sz),
    'sphere' (size = (r,)), 'capsule' (size = (r, h)) or 'cylinder' (size = (r, h)), with its
    centre and, for capsules/cylinders, the axis letter. A capsule's h is its full length
    including the two caps (as in the VR files)."""

    kind: str = field(metadata=in_schema(choice("Shape", ["box", "sphere", "capsule", "cylinder"])))
    size: tuple[float, ...] = field(
        metadata=in_schema(
            {
                "title": "Size",
                "type": "array",
                "items": {"type": "number", "exclusiveMinimum": 0, "maximum": LARGEST},
                "minItems": 1,
                "maxItems": 3,
                "description": "box: (sx, sy, sz); sphere: (r); capsule, cylinder: (r, h) in mm",
            }
        )
    )
    center: tuple[float, float, float] = field(default=(0.0, 0.0, 0.0), metadata=in_schema(numbers(3, "Centre", POINT)))
    axis: str = field(default="z", metadata=in_schema(choice("Axis", ["x", "y", "z"], "capsule or cylinder axis")))


@dataclass(frozen=True, kw_only=True)
class BodyFields:
    """What a robot type says about its chassis (its name is the robot type's own)."""

    mass: float = field(default=0.6, metadata=in_schema(positive("Mass", "kg")))
    length: float = field(default=DEFAULTS["length"], metadata=in_schema(positive("Length", "chassis mm")))
    width: float = field(default=DEFAULTS["width"], metadata=in_schema(positive("Width", "chassis mm")))
    height: float = field(default=DEFAULTS["height"], metadata=in_schema(positive("Height", "chassis mm")))
    color: tuple[int, int, int] = field(
        default=(40, 90, 200),
        metadata=in_schema(
            numbers(
                3, "Colour", "colour (red, green, blue), each 0..255", {"type": "integer", "minimum": 0, "maximum": 255}
            )
        ),
    )
    max_speed: float = field(default=600.0, metadata=in_schema(positive("Top speed", "mm/s")))
    max_turn: float = field(default=300.0, metadata=in_schema(positive("Top turn rate", "deg/s")))
    axis_offset: float = field(  # mm the drive axle sits ahead (+) of the robot centre
        default=0.0,
        metadata=in_schema(coordinate("Drive axle position", "mm the drive axle sits ahead of the centre")),
    )
    axle_height: float | None = field(  # None = the wheel radius
        default=None, metadata=in_schema(positive("Drive axle height", "mm"))
    )
    model: str | None = field(
        default=None, metadata=in_schema(text("3-D model", "3-D model file, relative to this file"))
    )
    model_offset: tuple[float, float, float] = field(
        default=(0.0, 0.0, 0.0),
        metadata=in_schema(numbers(3, "Model offset", "mesh offset in the mesh's axes (X right, Y up, Z forward), mm")),
    )
    model_rotation: tuple[float, float, float] = field(
        default=(0.0, 0.0, 0.0),
        metadata=in_schema(numbers(3, "Model rotation", "mesh rotation about the mesh's X, Y, Z axes, degrees")),
    )
    colliders: tuple[Collider, ...] = field(default=(), metadata=in_schema(list_of("collider", "Colliders")))
    center_of_mass: tuple[float, float, float] | None = field(  # robot frame
        default=None, metadata=in_schema(numbers(3, "Centre of mass", POINT))
    )


def read_name(reader: PartReader, line: Line) -> None:
    if not line.args:
        reader.error(line, "name: expected a robot name, found nothing")
        return
    if len(line.args) == 1:
        reader.fields["name"] = line.args[0].text
    else:  # EyeSim 6: the rest of the line
        reader.fields["name"] = " ".join(t.text for t in line.args)


def _single(reader: PartReader, line: Line, field: str, name: str) -> None:
    if reader.arity(line, (1,), f"<{name}>"):
        values = reader.numbers(line, 1, (name,))
        if values and reader.positive(line, values[0], 1, name):
            reader.fields[field] = values[0]


def read_diameter(reader: PartReader, line: Line) -> None:
    if reader.arity(line, (1,), "<mm>"):
        values = reader.numbers(line, 1, ("diameter in mm",))
        if values and reader.positive(line, values[0], 1, "diameter"):
            reader.collected["diameter"] = values[0]


def read_size(reader: PartReader, line: Line) -> None:
    if reader.arity(line, (3,), "<length> <width> <height>"):
        values = reader.numbers(line, 1, ("length in mm", "width in mm", "height in mm"))
        if values and all(
            reader.positive(line, v, 1 + i, n) for i, (v, n) in enumerate(zip(values, ("length", "width", "height")))
        ):
            reader.collected["size"] = (values[0], values[1], values[2])


def read_color(reader: PartReader, line: Line) -> None:
    if reader.arity(line, (3,), "<r> <g> <b>"):
        read = [reader.whole(line, 1 + i, c + " (0..255)", 0) for i, c in enumerate(("red", "green", "blue"))]
        rgb = [c for c in read if c is not None]
        if len(rgb) == 3:
            if any(c > 255 for c in rgb):
                reader.error(
                    line, "color: expected components 0..255, found " + " ".join(str(c) for c in rgb), 1, "bad-value"
                )
            else:
                reader.fields["color"] = tuple(rgb)


def read_model(reader: PartReader, line: Line) -> None:
    if not reader.arity(line, (1, 7), "<file> [<x> <y> <z> <rx> <ry> <rz>]"):
        return
    reader.fields["model"] = line.args[0].text
    reader.where["model"] = reader.at(line, 1)
    if len(line.args) == 7:
        values = reader.numbers(line, 2, ("x offset", "y offset", "z offset", "x rotation", "y rotation", "z rotation"))
        if values:
            reader.fields["model_offset"] = tuple(v + 0.0 for v in values[:3])
            reader.fields["model_rotation"] = tuple(v + 0.0 for v in values[3:])


def read_mass(reader: PartReader, line: Line) -> None:
    if not reader.arity(line, (1, 4), "<kg> [<cx> <cy> <cz>]"):
        return
    values = reader.numbers(line, 1, ("mass in kg", "centre x", "centre y", "centre z")[: len(line.args)])
    if values and reader.positive(line, values[0], 1, "mass"):
        reader.fields["mass"] = values[0]
        reader.remember("mass", line)
        if len(values) == 4:
            reader.fields["center_of_mass"] = reader.body_point(*values[1:])


def read_axis(reader: PartReader, line: Line) -> None:
    if not reader.arity(line, (1, 2), "[<vertical>] <forward>"):
        return
    names = ("forward offset",) if len(line.args) == 1 else ("vertical offset", "forward offset")
    values = reader.numbers(line, 1, names)
    if values:
        reader.fields["axis_offset"] = values[-1]
        if len(values) == 2 and values[0] > 0:
            reader.fields["axle_height"] = values[0]


def read_collider(reader: PartReader, line: Line) -> None:
    kind = line.args[0].text.lower() if line.args else ""
    if kind not in COLLIDER_FORMS:
        found = quoted(line.args[0].text) if line.args else "nothing"
        reader.error(line, f"collider: expected box, sphere, capsule or cylinder, found {found}", 1)
        return
    form, count = COLLIDER_FORMS[kind]
    counts = (count + 1, count + 2) if kind in ("capsule", "cylinder") else (count + 1,)
    if not reader.arity(line, counts, f"{kind} {form}"):
        return
    names = COLLIDER_SIZES[kind]
    values = reader.numbers(line, 2, names + ("centre x", "centre y", "centre z"))
    if not values:
        return
    size, centre = values[: len(names)], values[len(names) :]
    if not all(reader.positive(line, v, 2 + i, n) for i, (v, n) in enumerate(zip(size, names))):
        return
    axis = "y" if reader.dialect != "eyesim" else "z"
    if len(line.args) == count + 2:
        axis = line.args[-1].text.lower()
        if axis not in ("x", "y", "z"):
            reader.error(line, f"collider: expected axis x, y or z, found {quoted(line.args[-1].text)}", len(line.args))
            return
    if reader.dialect != "eyesim":
        axis = VR_AXIS[axis]
        if kind == "box":
            size = [size[2], size[0], size[1]]
    reader.collected.setdefault("colliders", []).append(
        Collider(
            kind,
            tuple(v + 0.0 for v in size),
            reader.body_point(*centre),
            axis if kind in ("capsule", "cylinder") else "z",
        )
    )


def finish(reader: PartReader) -> None:
    fields = reader.fields
    if "name" not in fields:
        fields["name"] = Path(reader.source).stem
        reader.diagnostics.warning(
            Location(reader.source, 1, 1),
            f"no 'name' line: the robot type is called {quoted(fields['name'])} after its file",
            "no-name",
        )
    fields["colliders"] = tuple(reader.collected.get("colliders", ()))
    fields["length"], fields["width"], fields["height"] = _dimensions(reader.collected)


def _dimensions(collected: dict) -> tuple[float, float, float]:
    """Chassis size: `size`, else the colliders' extent, else `diameter`, else the default."""
    if "size" in collected:
        return collected["size"]
    if collected.get("colliders"):
        low, high = [float("inf")] * 3, [float("-inf")] * 3
        for collider in collected["colliders"]:
            half = _half_extent(collider)
            for i in range(3):
                low[i] = min(low[i], collider.center[i] - half[i])
                high[i] = max(high[i], collider.center[i] + half[i])
        return (round(high[0] - low[0], 6), round(high[1] - low[1], 6), round(max(high[2], 1.0), 6))
    if "diameter" in collected:
        return (collected["diameter"], collected["diameter"], DEFAULT_HEIGHT)
    return (DEFAULTS["length"], DEFAULTS["width"], DEFAULTS["height"])


def collider_bottom(collider: Collider) -> float:
    """mm the collider's lowest point lies above the robot's origin (its floor)."""
    return collider.center[2] - _half_extent(collider)[2]


def collider_volume(collider: Collider) -> float:
    """mm^3 of a collider (a capsule's height includes its caps)."""
    r = collider.size[0]
    if collider.kind == "box":
        return collider.size[0] * collider.size[1] * collider.size[2]
    if collider.kind == "sphere":
        return 4 / 3 * math.pi * r**3
    if collider.kind == "capsule":
        return math.pi * r * r * max(collider.size[1] - 2 * r, 0.0) + 4 / 3 * math.pi * r**3
    return math.pi * r * r * collider.size[1]


def hull_centroid(robot_type: RobotType) -> tuple[float, float, float]:
    """mm: the centre of the hull's volume (its colliders' centroid by volume), robot frame."""
    colliders = hull_colliders(robot_type)
    volumes = [collider_volume(c) for c in colliders]
    total = sum(volumes) or 1.0
    x, y, z = (sum(v * c.center[i] for v, c in zip(volumes, colliders)) / total for i in range(3))
    return x, y, z


def _half_extent(collider: Collider) -> tuple[float, float, float]:
    if collider.kind == "box":
        sx, sy, sz = collider.size
        return sx / 2, sy / 2, sz / 2
    r = collider.size[0]
    if collider.kind == "sphere":
        return (r, r, r)
    along = max(collider.size[1] / 2, r)  # a capsule's height includes its caps
    x, y, z = (along if axis == collider.axis else r for axis in "xyz")
    return x, y, z


def check(robot, diagnostics, at) -> dict:
    volume = robot.length * robot.width * robot.height / 1000.0  # cm3
    if volume > 0 and robot.mass * 1000.0 / volume > MAX_DENSITY:
        estimate = float(f"{volume * ESTIMATED_DENSITY / 1000.0:.2g}")  # two significant digits
        f = format_number
        diagnostics.warning(
            at("mass"),
            f"mass {f(robot.mass)} kg is impossible for a {f(robot.length)} x "
            f"{f(robot.width)} x {f(robot.height)} mm robot (denser than steel); using "
            f"{f(estimate)} kg instead",
            "implausible-mass",
        )
        return {"mass": estimate}
    return {}


def write(robot) -> list[str]:
    f = format_number
    out = [
        f"name {quote_token(robot.name)}",
        f"size {f(robot.length)} {f(robot.width)} {f(robot.height)}",
        "color " + " ".join(str(c) for c in robot.color),
    ]
    mass = f"mass {f(robot.mass)}"
    if robot.center_of_mass is not None:
        mass += " " + " ".join(f(v) for v in robot.center_of_mass)
    out += [mass, f"speed {f(robot.max_speed)}", f"turn {f(robot.max_turn)}"]
    if robot.axle_height is not None:
        out.append(f"axis {f(robot.axle_height)} {f(robot.axis_offset)}")
    else:
        out.append(f"axis {f(robot.axis_offset)}")
    if robot.model is not None:
        line = f"model {quote_token(robot.model)}"
        if robot.model_offset != (0, 0, 0) or robot.model_rotation != (0, 0, 0):
            line += " " + " ".join(f(v) for v in (*robot.model_offset, *robot.model_rotation))
        out.append(line)
    for c in robot.colliders:
        numbers_ = " ".join(f(v) for v in (*c.size, *c.center))
        axis = f" {c.axis}" if c.kind in ("capsule", "cylinder") else ""
        out.append(f"collider {c.kind} {numbers_}{axis}")
    return out


PART = Part(
    "body",
    fields=BodyFields,
    keywords={
        "name": read_name,
        "diameter": read_diameter,
        "speed": lambda reader, line: _single(reader, line, "max_speed", "speed in mm/s"),
        "turn": lambda reader, line: _single(reader, line, "max_turn", "turn rate in deg/s"),
        "size": read_size,
        "color": read_color,
        "model": read_model,
        "mass": read_mass,
        "axis": read_axis,
        "collider": read_collider,
    },
    write=write,
    finish=finish,
    defs={"collider": record_of(Collider, "Collider", "a collision shape (mm)")},
    json_locations=lambda robot, positions: {"mass": positions.key(["mass"])},
    check=check,
)


def glides(robot_type: RobotType, collider: Collider) -> bool:
    """Whether a hull collider of a wheeled robot stands in for a skid or caster: it reaches below
    the chassis clearance, where the wheels alone are meant to touch the floor. Such a collider
    glides without friction, like the drives' own casters, so it never brakes the robot."""
    return robot_type.wheels is not None and collider_bottom(collider) < CHASSIS_CLEARANCE * 1000


def hull_colliders(robot_type: RobotType) -> tuple[Collider, ...]:
    """The chassis shape: the type's colliders, else a box of its size (above the wheels' clearance
    when it has wheels). A gliding collider (`glides`) that reaches lower than GLIDER_LIFT above the
    floor is raised to it: the wheels stand on the floor and carry the robot, as the drives' casters
    leave them to (EyeSim VR files measure from a floor a few mm below the wheels' own)."""
    if robot_type.colliders:
        return tuple(_lifted(c) if glides(robot_type, c) else c for c in robot_type.colliders)
    clearance = CHASSIS_CLEARANCE * 1000 if robot_type.wheels is not None else 0.0
    height = max(robot_type.height - clearance, 10.0)
    # The hull sits slightly behind the axle so a two-wheeler leans on its rear caster, not its nose.
    return (Collider("box", (robot_type.length, robot_type.width, height), (-10.0, 0.0, clearance + height / 2)),)


def _lifted(collider: Collider) -> Collider:
    rise = GLIDER_LIFT - collider_bottom(collider)
    if rise <= 0:
        return collider
    x, y, z = collider.center
    return Collider(collider.kind, collider.size, (x, y, z + rise), collider.axis)
