"""What a robot file says about PSD infrared distance sensors: `psd` lines in three forms."""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass, field

from eyesim.protocol import constants
from eyesim.scene.lexer import Line, Token, format_number, integer
from eyesim.parts.part import Part, PartReader, coordinate, in_schema, list_of, name_token, record_of, text, whole

# RoBIOS 7: PSD_FRONT 1 .. PSD_BACK 4 (the group's values are all numbers)
PSD_IDS = {name: value for name, value in constants.GROUPS["psd"].items() if isinstance(value, int)}
ID_NAMES = ", ".join(f"{name}={value}" for name, value in PSD_IDS.items())


@dataclass(frozen=True)
class PsdSpec:
    """A PSD distance sensor: RoBIOS id (PSD_FRONT=1 ...), name, position in the robot frame (mm)
    and beam direction (heading deg, left positive; pitch deg, up positive)."""

    id: int = field(metadata=in_schema(whole(1, "RoBIOS id", f"RoBIOS id ({ID_NAMES})")))
    name: str = field(metadata=in_schema(text("Name")))
    x: float = field(metadata=in_schema(coordinate("x", "mm forward")))
    y: float = field(metadata=in_schema(coordinate("y", "mm left")))
    z: float = field(metadata=in_schema(coordinate("z", "mm up")))
    heading: float = field(metadata=in_schema(coordinate("Heading", "degrees, left positive")))
    pitch: float = field(default=0.0, metadata=in_schema(coordinate("Pitch", "degrees, up positive")))


@dataclass(frozen=True, kw_only=True)
class PsdFields:
    """What a robot type says about its PSDs."""

    psds: tuple[PsdSpec, ...] = field(default=(), metadata=in_schema(list_of("psd", "PSD sensors")))


def read_psd(reader: PartReader, line: Line) -> None:
    """Three forms: EyeSim 6 `psd NAME [id] x y z angle`, VR 1.x `psd id NAME x y z angle` and
    the 8-argument form with pitch, heading and roll."""
    args = line.args
    if len(args) not in (5, 6, 8):
        reader.arity(line, (5, 6, 8), "<NAME> [<id>] <x> <y> <z> <angle>, or <id> <NAME> <x> <y> <z> <rx> <ry> <rz>")
        return
    if len(args) == 5:
        ident, name_index, first = None, 1, 2
    elif is_integer(args[0]) and not is_integer(args[1]):
        ident, name_index, first = integer(args[0].text), 2, 3
    else:
        ident = reader.whole(line, 2, "PSD id")
        if ident is None:
            return
        name_index, first = 1, 3
    names = ("x", "y", "z") + (("angle",) if len(args) < 8 else ("pitch", "heading", "roll"))
    values = reader.numbers(line, first, names)
    if not values:
        return
    heading, pitch = (values[3], 0.0) if len(args) < 8 else (values[4], values[3])
    spec = PsdSpec(
        ident if ident is not None and ident > 0 else 0,
        line.tokens[name_index].text,
        values[0],
        values[1],
        values[2],
        heading + 0.0,
        pitch + 0.0,
    )
    reader.collected.setdefault("psds", []).append((ident, spec, reader.at(line)))


def is_integer(token: Token) -> bool:
    return not token.quoted and integer(token.text) is not None


def finish(reader: PartReader) -> None:
    """RoBIOS ids: as written when positive; EyeSim 6's negative hdt ids and missing ids
    become PSD_FRONT=1 .. PSD_BACK=4 by name, other sensors number on after the highest."""
    psds = reader.collected.get("psds", [])
    taken = {ident for ident, _, _ in psds if ident is not None and ident > 0}
    ids: list[int | None] = []
    for ident, spec, _ in psds:
        if ident is not None and ident > 0:
            ids.append(ident)
        elif PSD_IDS.get(spec.name.upper()) and PSD_IDS[spec.name.upper()] not in taken:
            ids.append(PSD_IDS[spec.name.upper()])
            taken.add(ids[-1])
        else:
            ids.append(None)
    next_id = max(taken, default=0) + 1
    result = []
    for i, (value, (_, spec, location)) in enumerate(zip(ids, psds)):
        if value is None:
            value, next_id = next_id, next_id + 1
        result.append(dataclasses.replace(spec, id=value))
        reader.where[f"psd:{i}"] = location
    reader.fields["psds"] = tuple(result)


def check(robot, diagnostics, at) -> dict:
    seen: dict[int, str] = {}
    for i, psd in enumerate(robot.psds):
        if psd.id in seen:
            diagnostics.error(
                at(f"psd:{i}"),
                f"PSD id {psd.id} of {psd.name} is already used by {seen[psd.id]}: expected a different id",
                "duplicate",
            )
        seen.setdefault(psd.id, psd.name)
    for i, psd in enumerate(robot.psds):
        if psd.z < 0:
            diagnostics.warning(
                at(f"psd:{i}"),
                f"{psd.name} sits {format_number(-psd.z)} mm below the floor "
                f"(z = {format_number(psd.z)}); kept as written",
                "below-floor",
            )
    return {}


def write(robot) -> list[str]:
    f = format_number
    out = []
    for p in robot.psds:
        if p.pitch:
            out.append(f"psd {p.id} {name_token(p.name)} {f(p.x)} {f(p.y)} {f(p.z)} {f(p.pitch)} {f(p.heading)} 0")
        else:
            out.append(f"psd {name_token(p.name)} {p.id} {f(p.x)} {f(p.y)} {f(p.z)} {f(p.heading)}")
    return out


PART = Part(
    "psd",
    components=("eyesim.parts.psd.component:create",),
    fields=PsdFields,
    keywords={"psd": read_psd},
    write=write,
    finish=finish,
    defs={"psd": record_of(PsdSpec, "PSD sensor", "a PSD distance sensor (robot frame)")},
    json_locations=lambda robot, positions: {f"psd:{i}": positions.value(["psds", i]) for i in range(len(robot.psds))},
    check=check,
)
