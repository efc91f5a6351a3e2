"""How the robot floats and moves through water (`buoyancy`, `drag`) and where it starts in it
(`depth`); the forces: component.py and physics/water.py."""

from __future__ import annotations

from dataclasses import dataclass, field

from eyesim.scene.diagnostics import quoted
from eyesim.scene.lexer import Line, format_number
from eyesim.parts.part import Part, PartReader, at_least, coordinate, in_schema, record_of, ref


@dataclass(frozen=True)
class BuoyancySpec:
    """Displaced volume in litres (1 litre of water lifts about 1 kg) acting at the centre of
    buoyancy (mm, robot frame)."""

    volume: float = field(metadata=in_schema(at_least(0, "Volume", "displaced litres")))
    x: float = field(default=0.0, metadata=in_schema(coordinate("x")))
    y: float = field(default=0.0, metadata=in_schema(coordinate("y")))
    z: float = field(default=0.0, metadata=in_schema(coordinate("z")))


@dataclass(frozen=True)
class DragSpec:
    """Linear drag in water: force per speed along the robot's x, y, z axes in N/(m/s), and a
    rotational drag torque per turn rate in N*m/(rad/s)."""

    x: float = field(metadata=in_schema(at_least(0, "Drag along x", "N/(m/s) along x")))
    y: float = field(metadata=in_schema(at_least(0, "Drag along y", "N/(m/s) along y")))
    z: float = field(metadata=in_schema(at_least(0, "Drag along z", "N/(m/s) along z")))
    rotation: float = field(default=0.0, metadata=in_schema(at_least(0, "Rotational drag", "N*m/(rad/s)")))


@dataclass(frozen=True, kw_only=True)
class WaterFields:
    """What a robot type says about how it floats and moves through water."""

    buoyancy: BuoyancySpec | None = field(default=None, metadata=in_schema(ref("buoyancy")))
    drag: DragSpec | None = field(default=None, metadata=in_schema(ref("drag")))
    start_depth: float | None = field(  # mm the hull's top starts below the surface
        default=None,
        metadata=in_schema(
            at_least(
                0,
                "Start depth",
                "mm the hull's top starts below the water's surface "
                "(a robot placed in a scene under water; else it starts afloat if it "
                "floats, on the pool floor if not)",
            )
        ),
    )


def read_buoyancy(reader: PartReader, line: Line) -> None:
    if not reader.arity(line, (1, 4), "<volume in litres> [<x> <y> <z>]"):
        return
    values = reader.numbers(line, 1, ("volume in litres", "centre x", "centre y", "centre z")[: len(line.args)])
    if values:
        if values[0] < 0:
            reader.error(line, f"buoyancy: expected a volume >= 0, found {quoted(line.tokens[1].text)}", 1, "bad-value")
            return
        reader.fields["buoyancy"] = BuoyancySpec(*(v + 0.0 for v in values))


def read_drag(reader: PartReader, line: Line) -> None:
    if not reader.arity(line, (3, 4), "<x> <y> <z> [<rotation>]"):
        return
    names = ("drag along x", "drag along y", "drag along z", "rotational drag")
    values = reader.numbers(line, 1, names[: len(line.args)])
    if values:
        if any(v < 0 for v in values):
            reader.error(line, "drag: expected coefficients >= 0", 1, "bad-value")
            return
        reader.fields["drag"] = DragSpec(*(v + 0.0 for v in values))


def read_depth(reader: PartReader, line: Line) -> None:
    if not reader.arity(line, (1,), "<mm>"):
        return
    values = reader.numbers(line, 1, ("depth in mm",))
    if values:
        if values[0] < 0:
            reader.error(
                line, f"depth: expected mm >= 0 below the surface, found {quoted(line.tokens[1].text)}", 1, "bad-value"
            )
            return
        reader.fields["start_depth"] = values[0] + 0.0


def write(robot) -> list[str]:
    f = format_number
    out = []
    if robot.start_depth is not None:
        out.append(f"depth {f(robot.start_depth)}")
    if robot.buoyancy is not None:
        b = robot.buoyancy
        out.append(f"buoyancy {f(b.volume)} {f(b.x)} {f(b.y)} {f(b.z)}")
    if robot.drag is not None:
        d = robot.drag
        out.append(f"drag {f(d.x)} {f(d.y)} {f(d.z)} {f(d.rotation)}")
    return out


PART = Part(
    "water",
    components=("eyesim.parts.water.component:create",),
    fields=WaterFields,
    keywords={"buoyancy": read_buoyancy, "drag": read_drag, "depth": read_depth},
    write=write,
    defs={
        "buoyancy": record_of(BuoyancySpec, "Buoyancy", "buoyancy and its centre (mm)"),
        "drag": record_of(DragSpec, "Drag", "linear drag in water"),
    },
)
