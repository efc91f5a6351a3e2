"""What a robot file says about a bumper: `bumper <id> <x> <y> <angle> <width>` (mm, degrees)."""

from __future__ import annotations

from dataclasses import dataclass, field

from eyesim.scene.lexer import Line, format_number
from eyesim.parts.part import Part, PartReader, coordinate, in_schema, list_of, positive, record_of, whole

FIRST_LINE = 8  # bumper n is wired to digital input line 8 + n (lines 1..8 stay free for the program)
MAX_ID = 8  # the I/O board has 16 lines


@dataclass(frozen=True)
class BumperSpec:
    """A contact strip: its id (1..8), the middle of the strip in the robot frame (mm), the
    direction it faces (degrees, left positive: 0 = forward) and its width (mm)."""

    id: int = field(metadata=in_schema(whole(1, "Id", f"1..{MAX_ID}: digital input line 8 + id reads 0 while pressed")))
    x: float = field(metadata=in_schema(coordinate("x", "mm forward, middle of the strip")))
    y: float = field(metadata=in_schema(coordinate("y", "mm left, middle of the strip")))
    angle: float = field(
        metadata=in_schema(coordinate("Angle", "degrees the strip faces, left positive (0 = forward)"))
    )
    width: float = field(metadata=in_schema(positive("Width", "mm")))

    @property
    def line(self) -> int:
        """The digital input line the strip's switch is wired to."""
        return FIRST_LINE + self.id


@dataclass(frozen=True, kw_only=True)
class BumperFields:
    """What a robot type says about its bumpers."""

    bumpers: tuple[BumperSpec, ...] = field(default=(), metadata=in_schema(list_of("bumper", "Bumpers")))


def read_bumper(reader: PartReader, line: Line) -> None:
    if len(line.args) != 5:
        reader.arity(line, (5,), "<id> <x> <y> <angle> <width>")
        return
    ident = reader.whole(line, 1, f"bumper id, 1..{MAX_ID}", minimum=1)
    values = reader.numbers(line, 2, ("x", "y", "angle", "width"))
    if ident is None or not values:
        return
    if ident > MAX_ID:
        reader.error(
            line,
            f"bumper: expected bumper id 1..{MAX_ID} (digital lines {FIRST_LINE + 1}.."
            f"{FIRST_LINE + MAX_ID}), found {ident}",
            1,
            "bad-value",
        )
        return
    if not reader.positive(line, values[3], 5, "width"):
        return
    spec = BumperSpec(ident, values[0] + 0.0, values[1] + 0.0, values[2] + 0.0, values[3] + 0.0)
    reader.collected.setdefault("bumpers", []).append((spec, reader.at(line)))


def finish(reader: PartReader) -> None:
    bumpers = reader.collected.get("bumpers", [])
    for i, (_, location) in enumerate(bumpers):
        reader.where[f"bumper:{i}"] = location
    if bumpers:
        reader.fields["bumpers"] = tuple(spec for spec, _ in bumpers)


def check(robot, diagnostics, at) -> dict:
    seen: set[int] = set()
    for i, bumper in enumerate(robot.bumpers):
        if bumper.id > MAX_ID:
            diagnostics.error(at(f"bumper:{i}"), f"bumper id {bumper.id} is not 1..{MAX_ID}", "bad-value")
        elif bumper.id in seen:
            diagnostics.error(
                at(f"bumper:{i}"), f"bumper id {bumper.id} is already used: expected a different id", "duplicate"
            )
        seen.add(bumper.id)
    return {}


def write(robot) -> list[str]:
    f = format_number
    return [f"bumper {b.id} {f(b.x)} {f(b.y)} {f(b.angle)} {f(b.width)}" for b in robot.bumpers]


PART = Part(
    "bumper",
    components=("eyesim.parts.bumper.component:create",),
    fields=BumperFields,
    keywords={"bumper": read_bumper},
    write=write,
    finish=finish,
    defs={
        "bumper": record_of(BumperSpec, "Bumper", "a contact strip on the chassis edge, wired to digital input 8 + id")
    },
    json_locations=lambda robot, positions: {
        f"bumper:{i}": positions.value(["bumpers", i]) for i in range(len(robot.bumpers))
    },
    check=check,
)
