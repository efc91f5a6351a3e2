"""The driven wheels (`wheel`) and, on an Ackermann robot, the steered axle (`axel turn`, `wheel turn`)."""

from __future__ import annotations

from dataclasses import dataclass, field

from eyesim.scene.diagnostics import quoted
from eyesim.scene.drives import drive_of
from eyesim.scene.lexer import Line, format_number
from eyesim.parts.part import Part, PartReader, coordinate, in_schema, positive, record_of, ref, whole


@dataclass(frozen=True)
class WheelSpec:
    """Wheels of a wheeled drive: diameter mm, max speed deg/s, encoder ticks per revolution,
    track = full distance between the left and right wheel contact points in mm."""

    diameter: float = field(metadata=in_schema(positive("Diameter", "mm")))
    max_speed: float = field(metadata=in_schema(positive("Top speed", "deg/s")))
    ticks_per_rev: int = field(metadata=in_schema(whole(1, "Encoder ticks", "encoder ticks per revolution")))
    track: float = field(metadata=in_schema(positive("Track", "full distance between the left and right wheels in mm")))


@dataclass(frozen=True)
class SteeringSpec:
    """The steered axle of an Ackermann robot: `offset` mm ahead (+) of the robot centre,
    axle `height` mm above the floor (None = wheel radius) and its wheels (None = as driven)."""

    offset: float = field(metadata=in_schema(coordinate("Position", "mm ahead of the robot centre")))
    height: float | None = field(default=None, metadata=in_schema(positive("Height", "axle height in mm")))
    wheels: WheelSpec | None = field(default=None, metadata=in_schema(ref("wheels")))


@dataclass(frozen=True, kw_only=True)
class WheelsFields:
    """What a robot type says about its driven wheels and, on an Ackermann robot, its steered axle."""

    wheels: WheelSpec | None = field(default=None, metadata=in_schema(ref("wheels")))
    steering: SteeringSpec | None = field(default=None, metadata=in_schema(ref("steering")))  # Ackermann only


DEFAULT_WHEELS = WheelSpec(54.0, 3600.0, 1100, 90.0)  # the S4's


def read_axel(reader: PartReader, line: Line) -> None:
    if not reader.arity(line, (3,), "drive|turn <vertical> <forward>"):
        return
    which = line.args[0].text.lower()
    if which not in ("drive", "turn"):
        reader.error(line, f"axel: expected drive or turn, found {quoted(line.args[0].text)}", 1)
        return
    values = reader.numbers(line, 2, ("vertical offset", "forward offset"))
    if not values:
        return
    height = values[0] if values[0] > 0 else None
    if which == "drive":
        reader.fields["axis_offset"] = values[1]
        if height is not None:
            reader.fields["axle_height"] = height
    else:
        steering = reader.collected.setdefault("steering", {})
        steering["offset"] = values[1]
        steering["height"] = height


def read_wheel(reader: PartReader, line: Line) -> None:
    which = None
    if line.args and line.args[0].text.lower() in ("drive", "turn"):
        which = line.args[0].text.lower()
    first = 2 if which else 1
    if not reader.arity(
        line, (first + 3,), ("drive|turn " if which else "") + "<diameter> <max deg/s> <ticks/rev> <distance>"
    ):
        return
    values = reader.numbers(
        line, first, ("diameter in mm", "maximum speed in deg/s", "ticks per revolution", "wheel distance in mm")
    )
    if not values:
        return
    ticks = reader.whole(line, first + 2, "ticks per revolution", 1)
    if ticks is None or not all(
        reader.positive(line, values[i], first + i, n)
        for i, n in ((0, "diameter"), (1, "maximum speed"), (3, "wheel distance"))
    ):
        return
    # EyeSim VR gives the distance of each wheel from the robot's middle, EyeSim 6 the track.
    track = values[3] * 2 if reader.dialect in ("vr", "vr1") else values[3]
    spec = WheelSpec(values[0], values[1], ticks, track)
    if which == "turn":
        reader.collected.setdefault("steering", {})["wheels"] = spec
    else:
        reader.fields["wheels"] = spec
        reader.remember("wheels", line)


def finish(reader: PartReader) -> None:
    steering = reader.collected.get("steering")
    if steering:
        reader.fields["steering"] = SteeringSpec(
            steering.get("offset", 0.0), steering.get("height"), steering.get("wheels")
        )


def write(robot) -> list[str]:
    f = format_number

    def wheel_line(keyword: str, w: WheelSpec) -> str:
        return f"{keyword} {f(w.diameter)} {f(w.max_speed)} {w.ticks_per_rev} {f(w.track)}"

    out = []
    if robot.wheels is not None:
        out.append(wheel_line(drive_of(robot).wheel_keyword, robot.wheels))
    if robot.steering is not None:
        s = robot.steering
        out.append(f"axel turn {f(s.height) if s.height is not None else 0} {f(s.offset)}")
        if s.wheels is not None:
            out.append(wheel_line("wheel turn", s.wheels))
    return out


PART = Part(
    "wheels",
    fields=WheelsFields,
    keywords={"wheel": read_wheel, "axel": read_axel},
    write=write,
    finish=finish,
    defs={
        "wheels": record_of(WheelSpec, "Wheels", "wheels"),
        "steering": record_of(SteeringSpec, "Steering", "the steered axle (Ackermann)"),
    },
)
