"""Thrusters (`thruster` lines); how they push: component.py."""

from __future__ import annotations

from dataclasses import dataclass, field

from eyesim.scene.lexer import Line, format_number, quote_token
from eyesim.parts.part import Part, PartReader, coordinate, in_schema, list_of, positive, record_of, text, whole


@dataclass(frozen=True)
class ThrusterSpec:
    """A thruster: RoBIOS motor number, position (mm, robot frame), thrust direction (robot
    frame, any length), and the thrust in newtons at motor speed 100 (negative speeds reverse)."""

    name: str = field(metadata=in_schema(text("Name")))
    motor: int = field(metadata=in_schema(whole(1, "Motor", "RoBIOS motor number")))
    x: float = field(metadata=in_schema(coordinate("x", "mm forward")))
    y: float = field(metadata=in_schema(coordinate("y", "mm left")))
    z: float = field(metadata=in_schema(coordinate("z", "mm up")))
    dx: float = field(metadata=in_schema(coordinate("Direction x")))
    dy: float = field(metadata=in_schema(coordinate("Direction y")))
    dz: float = field(metadata=in_schema(coordinate("Direction z")))
    max_thrust: float = field(metadata=in_schema(positive("Thrust", "newtons at motor speed 100")))


@dataclass(frozen=True, kw_only=True)
class ThrustersFields:
    """What a robot type says about its thrusters."""

    thrusters: tuple[ThrusterSpec, ...] = field(default=(), metadata=in_schema(list_of("thruster", "Thrusters")))


def read_thruster(reader: PartReader, line: Line) -> None:
    if not reader.arity(line, (9,), "<NAME> <motor> <x> <y> <z> <dx> <dy> <dz> <max thrust N>"):
        return
    motor = reader.whole(line, 2, "motor number", 1)
    values = reader.numbers(
        line, 3, ("x", "y", "z", "direction x", "direction y", "direction z", "maximum thrust in N")
    )
    if motor is None or not values or not reader.positive(line, values[6], 9, "maximum thrust"):
        return
    thrusters = reader.fields.setdefault("thrusters", ())
    reader.fields["thrusters"] = thrusters + (ThrusterSpec(line.args[0].text, motor, *(v + 0.0 for v in values)),)
    reader.remember(f"thruster:{len(thrusters)}", line)


def check(robot, diagnostics, at) -> dict:
    seen: dict[int, str] = {}
    for i, thruster in enumerate(robot.thrusters):
        if thruster.motor < 1:
            diagnostics.error(
                at(f"thruster:{i}"),
                f"thruster {thruster.name}: expected a motor number from 1, found {thruster.motor}",
                "bad-value",
            )
        elif thruster.motor in seen:
            diagnostics.error(
                at(f"thruster:{i}"),
                f"motor {thruster.motor} of thruster {thruster.name} is already used by {seen[thruster.motor]}",
                "duplicate",
            )
        if (thruster.dx, thruster.dy, thruster.dz) == (0, 0, 0):
            diagnostics.error(
                at(f"thruster:{i}"), f"thruster {thruster.name}: expected a direction, found 0 0 0", "bad-value"
            )
        seen.setdefault(thruster.motor, thruster.name)
    return {}


def write(robot) -> list[str]:
    return [
        f"thruster {quote_token(t.name)} {t.motor} "
        + " ".join(format_number(v) for v in (t.x, t.y, t.z, t.dx, t.dy, t.dz, t.max_thrust))
        for t in robot.thrusters
    ]


PART = Part(
    "thrusters",
    components=("eyesim.parts.thrusters.component:create",),
    fields=ThrustersFields,
    keywords={"thruster": read_thruster},
    write=write,
    defs={"thruster": record_of(ThrusterSpec, "Thruster", "a thruster")},
    json_locations=lambda robot, positions: {
        f"thruster:{i}": positions.value(["thrusters", i]) for i in range(len(robot.thrusters))
    },
    check=check,
)
