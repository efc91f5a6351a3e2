"""The JSON form of every scene format: plain data to and from documents, checked by the schemas.

Each JSON file says what it is in `"format"` (eyesim.scene, eyesim.world, eyesim.maze,
eyesim.robot, eyesim.object) and `"version"`. Fields at their default value are left out when
writing. The schemas in eyesim/scene/schemas/ and the robot schema, which the part kinds declare
(scene/parts/), are the published definition (`eyesim schema export docs/schemas`).
"""

from __future__ import annotations

import dataclasses
import json
import types
import typing
from functools import lru_cache
from pathlib import Path
from typing import TYPE_CHECKING, Any, Mapping

from eyesim.scene import limits
from eyesim.scene.description import Location, Marker, ObjectPlacement, ObjectType, Pose, RobotType, Settings, World
from eyesim.scene.diagnostics import Diagnostics, quoted
from eyesim.scene.jsonpos import json_positions
from eyesim.scene.maz import MazeDocument
from eyesim.scene.parts import PARTS, robot_schema
from eyesim.scene.robot_type import finish_robot_type
from eyesim.scene.sim import Placement, Reference, SimDocument
from eyesim.scene.wld import BALL_TYPE

if TYPE_CHECKING:
    import jsonschema

SCHEMA_DIR = Path(__file__).resolve().parent / "schemas"
KINDS = ("scene", "world", "maze", "robot", "object")
VERSION = 1
_SKIP = {"source", "location", "row_lines"}


@lru_cache(maxsize=None)
def schema(kind: str) -> dict:
    """The published JSON Schema of one kind."""
    if kind == "robot":
        return robot_schema()
    return json.loads((SCHEMA_DIR / f"{kind}.schema.json").read_text(encoding="utf-8"))


def local_refs(schema: dict) -> dict:
    """The schema to validate with: without its `$id`, so that `#/$defs/...` references resolve
    within the document itself. jsonschema 4.17 (the last without a Rust extension, which Windows
    under Wine needs) joins them to a `urn:` id through urllib, which gives '' and a failed fetch."""
    return {key: value for key, value in schema.items() if key != "$id"}


def schema_text(kind: str) -> str:
    """The schema as published in docs/schemas/<kind>.schema.json."""
    return json.dumps(schema(kind), indent=2) + "\n"


def export_schemas(folder: Path) -> list[Path]:
    """Writes every kind's published schema into `folder` (docs/schemas/ in the repository)."""
    folder.mkdir(parents=True, exist_ok=True)
    written = []
    for kind in KINDS:
        path = folder / f"{kind}.schema.json"
        path.write_text(schema_text(kind), encoding="utf-8")
        written.append(path)
    return written


# -- documents to plain data -------------------------------------------------------------------
def to_json(kind: str, document) -> dict:
    data = {"format": f"eyesim.{kind}", "version": VERSION}
    data.update(_WRITERS[kind](document))
    return data


def dumps(data: dict) -> str:
    return json.dumps(data, indent=2) + "\n"


def _plain(value):
    """A dataclass as a dict without its default-valued fields; tuples as lists."""
    if dataclasses.is_dataclass(value):
        out = {}
        for f in dataclasses.fields(value):
            if f.name in _SKIP:
                continue
            v = getattr(value, f.name)
            default = f.default if f.default is not dataclasses.MISSING else dataclasses.MISSING
            if default is not dataclasses.MISSING and v == default:
                continue
            out[f.name] = _plain(v)
        return out
    if isinstance(value, (tuple, list)):
        return [_plain(v) for v in value]
    return value


def _world_json(world: World) -> dict:
    data = _plain(dataclasses.replace(world, objects=(), walls=(), start_positions=(), markers=()))
    if world.objects:
        data["balls"] = [{"x": b.pose.x, "y": b.pose.y} for b in world.objects]
    data["walls"] = [_plain(w) for w in world.walls]
    return data


def _scene_json(doc: SimDocument) -> dict:
    data: dict = {}
    if doc.world is not None:
        data["world"] = doc.world.path
    if doc.settings != Settings():
        data["settings"] = {
            name: value for name, value in vars(doc.settings).items() if value != getattr(Settings(), name)
        }
    if doc.robot_files:
        data["robot_files"] = [r.path for r in doc.robot_files]
    if doc.object_files:
        data["object_files"] = [r.path for r in doc.object_files]
    data["placements"] = [_placement_json(p) for p in doc.placements]
    data["markers"] = [_plain(m) for m in doc.markers]
    return data


def _placement_json(p: Placement) -> dict:
    out: dict[str, Any]
    if p.robi is not None:
        out = {"robi": p.robi, "program": p.program or ""}
    elif p.model is not None:
        out = {"model": p.model}
    else:
        out = {"type": p.type_name}
    if p.start is not None:
        out["start"] = p.start
        if p.phi is not None:
            out["phi"] = p.phi
    elif p.x is not None:
        out.update(x=p.x, y=p.y, phi=p.phi if p.phi is not None else 0.0)
    if p.friction is not None:
        out["friction"] = p.friction
    if p.program is not None and p.robi is None:
        out["program"] = p.program
    return out


_WRITERS = {
    "world": _world_json,
    "maze": lambda m: {**({"cell_size": m.cell_size} if m.cell_size is not None else {}), "rows": list(m.rows)},
    "robot": _plain,
    "object": _plain,
    "scene": _scene_json,
}


# -- plain data to documents -------------------------------------------------------------------
def parse_json(
    text: str, source: str, diagnostics: Diagnostics, expected: tuple[str, ...] = KINDS, where: dict | None = None
):
    """(kind, document) from JSON text, or (kind or None, None) after reporting every problem.
    `where`, when given, receives the locations of the 'floor_texture' and 'model' references."""
    try:
        data = json.loads(text, parse_constant=_reject_constant)
    except json.JSONDecodeError as e:
        diagnostics.error(Location(source, e.lineno, e.colno), f"invalid JSON: {e.msg}", "json")
        return None, None
    except ValueError as e:
        diagnostics.error(Location(source, 1, 1), f"invalid JSON: {e}", "json")
        return None, None
    except RecursionError:
        diagnostics.error(Location(source, 1, 1), "invalid JSON: nested too deeply", "json")
        return None, None
    fmt = data.get("format") if isinstance(data, dict) else None
    kind = fmt[len("eyesim.") :] if isinstance(fmt, str) and fmt.startswith("eyesim.") else None
    if kind not in expected:
        names = ", ".join(f"eyesim.{k}" for k in expected)
        found = quoted(str(fmt)) if fmt is not None else "no format"
        diagnostics.error(
            Location(source, 1, 1), f'expected a JSON object with "format" one of {names}, found {found}', "json"
        )
        return None, None
    if _too_many(data, source, diagnostics):
        return kind, None
    positions = _Positions(text, source)
    import jsonschema  # here, not at the top: a run of a .sim scene does not need it (start-up time)

    validator = jsonschema.Draft202012Validator(local_refs(schema(kind)))
    errors = sorted(validator.iter_errors(data), key=lambda e: list(e.absolute_path))
    for error in errors:
        _report(error, positions, diagnostics)
    if errors:
        return kind, None
    if where is not None:
        for key in ("floor_texture", "model"):
            if key in data:
                where[key] = positions.value([key])
    return kind, _READERS[kind](data, source, positions, diagnostics)


def _too_many(data: dict, source: str, diagnostics: Diagnostics) -> bool:
    """Past a count limit (checked before the schema: validating 100 000 walls takes seconds)."""
    where = Location(source, 1, 1)
    counts = [
        ("walls", limits.MAX_WALLS, "a world"),
        ("placements", limits.MAX_ROBOTS + limits.MAX_OBJECTS, "a scene"),
        ("markers", limits.MAX_MARKERS, "a scene"),
        ("rows", limits.MAX_LINES, "a maze"),
    ]
    if any(
        isinstance(data.get(key), list) and limits.too_many(len(data[key]), limit, key, where, diagnostics, scope)
        for key, limit, scope in counts
    ):
        return True
    rows = data.get("rows")
    longest = max((len(row) for row in rows if isinstance(row, str)), default=0) if isinstance(rows, list) else 0
    if longest > limits.MAX_LINE_CHARS:  # a maze row is a line of a .maz file
        diagnostics.error(
            where,
            f"a maze row is {longest} characters long, more than {limits.MAX_LINE_CHARS}, the "
            "limit for a line of a scene file",
            limits.LIMIT,
        )
        return True
    return False


def _reject_constant(name: str):
    raise ValueError(f"{name} is not a number JSON allows")


class _Positions:
    """Locations of JSON values by path (computed only when first needed)."""

    def __init__(self, text: str, source: str):
        self.text, self.source = text, source
        self._maps: tuple[dict, dict] | None = None  # (values, keys): json_positions

    def _load(self) -> tuple[dict, dict]:
        if self._maps is None:
            try:
                self._maps = json_positions(self.text)
            except RecursionError:  # absurdly deep nesting: report at the start of the file
                self._maps = ({}, {})
        return self._maps

    def value(self, path) -> Location:
        values, _ = self._load()
        path = tuple(path)
        while path not in values and path:
            path = path[:-1]
        line, column = values.get(path, (1, 1))
        return Location(self.source, line, column)

    def key(self, path) -> Location:
        _, keys = self._load()
        if tuple(path) in keys:
            line, column = keys[tuple(path)]
            return Location(self.source, line, column)
        return self.value(path)


def pointer(path) -> str:
    return "/" + "/".join(str(p) for p in path) if path else "(top level)"


def _describe(value) -> str:
    text = json.dumps(value)
    return text if len(text) <= 60 else text[:57] + "..."


def _report(error: "jsonschema.ValidationError", positions: _Positions, diagnostics: Diagnostics) -> None:
    path = list(error.absolute_path)
    if error.validator == "additionalProperties":
        allowed = sorted(_properties(error))
        instance = typing.cast(Any, error.instance)  # set on every error the validator raises
        for key in sorted(k for k in instance if k not in _properties(error)):
            _add(
                diagnostics,
                positions.key(path + [key]),
                f"{pointer(path + [key])}: unknown property {quoted(key)}: expected one of {', '.join(allowed)}",
            )
        return
    _add(diagnostics, positions.value(path), f"{pointer(path)}: {_message(error)}")


def _add(diagnostics: Diagnostics, location: Location, message: str) -> None:
    """One diagnostic per problem (the schema validator repeats some, e.g. one per missing key)."""
    if not any(d.location == location and d.message == message for d in diagnostics.items):
        diagnostics.error(location, message, "json-schema")


def _properties(error: "jsonschema.ValidationError") -> Mapping[str, Any]:
    """The properties the schema that failed allows (none for a schema that is true or false)."""
    return error.schema.get("properties", {}) if isinstance(error.schema, Mapping) else {}


def _message(error: "jsonschema.ValidationError") -> str:
    # validator_value and instance are set on every error the validator raises (Unset only on hand-made ones)
    v, value, instance = error.validator, typing.cast(Any, error.validator_value), typing.cast(Any, error.instance)
    if v == "required":
        missing = [k for k in value if k not in instance]
        return f"missing required propert{'y' if len(missing) == 1 else 'ies'} " + ", ".join(quoted(k) for k in missing)
    if v == "type":
        wanted = value if isinstance(value, str) else " or ".join(value)
        return f"expected {'an' if wanted[0] in 'aeiou' else 'a'} {wanted}, found {_describe(instance)}"
    if v == "enum":
        return f"expected one of {', '.join(_describe(x) for x in value)}, found {_describe(instance)}"
    if v == "const":
        return f"expected {_describe(value)}, found {_describe(instance)}"
    if v in ("minimum", "maximum", "exclusiveMinimum", "exclusiveMaximum"):
        sign = {"minimum": ">=", "maximum": "<=", "exclusiveMinimum": ">", "exclusiveMaximum": "<"}[v]
        return f"expected a number {sign} {value:g}, found {_describe(instance)}"
    if v in ("minItems", "maxItems"):
        bound = "at least" if v == "minItems" else "at most"
        return f"expected {bound} {value} item{'s' if value != 1 else ''}, found {len(instance)}"
    if v == "minLength":
        return f"expected a non-empty string, found {_describe(instance)}"
    if v == "pattern":
        return f"expected text matching {value}, found {_describe(instance)}"
    if v == "dependentRequired":
        return f"x, y and phi go together: found only {', '.join(k for k in ('x', 'y', 'phi') if k in instance)}"
    if v == "additionalProperties":
        extra = sorted(k for k in instance if k not in _properties(error))
        return "unknown propert" + ("y " if len(extra) == 1 else "ies ") + ", ".join(quoted(k) for k in extra)
    if v == "oneOf" and error.context:
        # the form the data comes closest to is the one with the fewest complaints
        branches: dict = {}
        for sub in error.context:
            branches.setdefault(sub.relative_schema_path[0], []).append(sub)
        nearest = min(branches.values(), key=len)
        form = nearest[0].schema.get("description", "an allowed form")
        details = "; ".join(
            f"{pointer(list(e.absolute_path))}: {_message(e)}"
            if list(e.absolute_path) != list(error.absolute_path)
            else _message(e)
            for e in nearest
        )
        return f"matches none of the allowed forms; nearest is {form}: {details}"
    return error.message


def build(cls, data):
    """A dataclass from schema-valid plain data (lists become tuples, missing fields default)."""
    hints = _hints(cls)
    values = {}
    for f in dataclasses.fields(cls):
        if f.name in data:
            values[f.name] = _convert(hints[f.name], data[f.name])
    return cls(**values)


@lru_cache(maxsize=None)
def _hints(cls):
    return typing.get_type_hints(cls)


def _convert(hint, value):
    if value is None:
        return None
    origin = typing.get_origin(hint)
    if origin in (typing.Union, types.UnionType):
        options = [a for a in typing.get_args(hint) if a is not type(None)]
        return _convert(options[0], value)
    if origin is tuple:
        args = typing.get_args(hint)
        if len(args) == 2 and args[1] is Ellipsis:
            return tuple(_convert(args[0], v) for v in value)
        return tuple(_convert(a, v) for a, v in zip(args, value))
    if dataclasses.is_dataclass(hint):
        return build(hint, value)
    if hint is float:
        return float(value) + 0.0
    if hint is int:
        return int(value)
    return value


def _body(data: dict) -> dict:
    return {k: v for k, v in data.items() if k not in ("format", "version")}


def _read_world(data, source, positions, diagnostics) -> World:
    body = _body(data)
    balls = tuple(
        ObjectPlacement(BALL_TYPE, Pose(float(b["x"]), float(b["y"])), positions.value(["balls", i]))
        for i, b in enumerate(body.pop("balls", []))
    )
    world = build(World, {**body, "source": source})
    walls = []
    for i, wall in enumerate(world.walls):
        if (wall.x1, wall.y1) == (wall.x2, wall.y2):
            diagnostics.warning(
                positions.value(["walls", i]),
                f"{pointer(['walls', i])}: zero-length wall: start and end are the same point; skipped",
                "degenerate-wall",
            )
        else:
            walls.append(wall)
    return dataclasses.replace(world, source=source, walls=tuple(walls), objects=balls)


def _read_maze(data, source, positions, diagnostics) -> MazeDocument:
    rows = tuple(data["rows"])
    return MazeDocument(
        rows,
        float(data["cell_size"]) if "cell_size" in data else None,
        tuple(positions.value(["rows", i]).line for i in range(len(rows))),
    )


def _read_robot(data, source, positions, diagnostics) -> RobotType:
    robot = build(RobotType, {**_body(data), "source": source})
    where = {}
    for part in PARTS:
        where.update(part.json_locations(robot, positions))
    return finish_robot_type(robot, diagnostics, where, Location(source, 1, 1))


def _read_object(data, source, positions, diagnostics) -> ObjectType:
    return build(ObjectType, {**_body(data), "source": source})


def _read_scene(data, source, positions, diagnostics) -> SimDocument:
    world = Reference(data["world"], positions.value(["world"])) if "world" in data else None
    settings = Settings(**data.get("settings", {}))
    robot_files = tuple(
        Reference(p, positions.value(["robot_files", i])) for i, p in enumerate(data.get("robot_files", []))
    )
    object_files = tuple(
        Reference(p, positions.value(["object_files", i])) for i, p in enumerate(data.get("object_files", []))
    )
    placements = []
    for i, p in enumerate(data.get("placements", [])):
        has_xy = "x" in p
        placements.append(
            Placement(
                type_name=p.get("type"),
                x=_float(p.get("x")),
                y=_float(p.get("y")),
                phi=_float(p.get("phi", 0.0 if has_xy else None)),
                start=p.get("start"),
                program=p.get("program"),
                robi=p.get("robi"),
                model=p.get("model"),
                friction=_float(p.get("friction")),
                location=positions.value(["placements", i]),
            )
        )
    markers = tuple(build(Marker, m) for m in data.get("markers", []))
    return SimDocument(source, world, settings, robot_files, object_files, tuple(placements), markers)


def _float(value):
    return None if value is None else float(value) + 0.0


_READERS = {
    "world": _read_world,
    "maze": _read_maze,
    "robot": _read_robot,
    "object": _read_object,
    "scene": _read_scene,
}
