"""What a robot file says about a scanning lidar: its `lidar` line."""

from __future__ import annotations

from dataclasses import dataclass, field

from eyesim.parts.part import Part, PartReader, between, in_schema, record_of, ref, whole
from eyesim.scene.diagnostics import quoted
from eyesim.scene.lexer import Line, format_number


@dataclass(frozen=True)
class LidarSpec:
    """A scanning lidar: `points` beams over 360 degrees, scan plane tilted by `tilt` degrees
    against the driving plane."""

    points: int = field(default=360, metadata=in_schema(whole(1, "Points")))
    tilt: float = field(
        default=0.0, metadata=in_schema(between(-90, 90, "Tilt", "scan plane tilt in degrees", exclusive_high=True))
    )


@dataclass(frozen=True, kw_only=True)
class LidarFields:
    """What a robot type says about its lidar."""

    lidar: LidarSpec | None = field(default=None, metadata=in_schema(ref("lidar")))


def read_lidar(reader: PartReader, line: Line) -> None:
    if not reader.arity(line, (2, 3), "<points> <tilt>"):
        return
    points = reader.whole(line, 1, "number of points", 1)
    tilt = reader.numbers(line, 2, ("tilt in degrees",))
    if points is None or not tilt:
        return
    if not -90 < tilt[0] < 90:
        reader.error(
            line,
            f"lidar: expected a tilt between -90 and 90 degrees, found {quoted(line.tokens[2].text)}",
            2,
            "bad-value",
        )
        return
    if len(line.args) == 3:
        reader.diagnostics.warning(
            reader.at(line, 3),
            f"lidar: third argument {quoted(line.args[2].text)} (EyeSim VR 2018) has no known meaning; ignored",
            "ignored-argument",
        )
    reader.fields["lidar"] = LidarSpec(points, tilt[0])


def write(robot) -> list[str]:
    if robot.lidar is None:
        return []
    return [f"lidar {robot.lidar.points} {format_number(robot.lidar.tilt)}"]


PART = Part(
    "lidar",
    components=("eyesim.parts.lidar.component:create",),
    fields=LidarFields,
    keywords={"lidar": read_lidar},
    write=write,
    defs={"lidar": record_of(LidarSpec, "Lidar", "a 360-degree scanning lidar")},
)
