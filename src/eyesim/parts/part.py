"""What one kind of robot part declares, and the helpers its declarations share.

A part kind (the PSDs, the camera, the wheels ...) owns its configuration in one declaration
module (`parts/<kind>/declaration.py`, or `scene/parts/<kind>.py` for the kinds not yet in a
folder of their own): the fields it adds to a robot type and their spec dataclass, the `.robi`
keywords it reads and the lines it writes, the JSON Schema of its fields and the checks of what
was read. The `.robi` reader (scene/robi.py), the JSON reader and writer (scene/json_format.py),
the robot type's checks (scene/robot_type.py) and the published robot schema all work from these
declarations (registry: scene/parts/__init__.py). They need no physics: what a part does in the
simulation is its component. This module sits outside the registry's package so that a
declaration can be imported before the registry, which imports every declaration.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass, field
from typing import Any, Callable

from eyesim.scene.diagnostics import Location
from eyesim.scene.diagnostics import Diagnostics, quoted
from eyesim.scene.keyword_reader import KeywordReader
from eyesim.scene.lexer import LARGEST, Line, integer, number, quote_token


@dataclass(frozen=True)
class Part:
    """One kind of robot part.

    `fields`: the robot type fields it owns, as a frozen keyword-only dataclass whose every field
    has its type, its default and its JSON Schema (`in_schema`); RobotType derives from it (scene/parts/).
    The robot schema's `properties` are its fields' schemas. `keywords`: `.robi`
    keyword (lower case) -> function(reader, line) that reads such a line into `reader.fields`
    (or collects it in `reader.collected` for `finish`). `finish(reader)`: after the last line,
    turns what was collected into fields. `write(robot)`: its `.robi` lines in our dialect.
    `defs`: the schemas its fields refer to (robot.schema.json `$defs`, made with `record_of`). `json_locations(robot, positions)`: where its values are in a JSON file, under the
    keys its checks use ('psd:0', 'camera', ...). `check(robot, diagnostics, at)`: reports
    contradictions (errors) and what a usable robot lacks (warnings) once the robot type is read
    from either format, `at(key)` giving where a key was written; returns the fields it fills in.
    `servos(robot)`: (servo number, user, location key) of each servo the part drives (the robot
    type checks that no two parts share one). `components`: the factories that build what the part
    does in the simulation, as "module:function" (robot/components/; named, not imported, so that
    reading files never loads the physics), called in this order with the robot's build context."""

    name: str
    fields: type
    keywords: dict[str, Callable[[PartReader, Line], None]]
    write: Callable[[Any], list[str]]
    defs: dict = field(default_factory=dict)
    finish: Callable[[PartReader], None] = lambda reader: None
    json_locations: Callable[[Any, Any], dict[str, Location]] = lambda robot, positions: {}
    check: Callable[[Any, Diagnostics, Callable[[str], Location]], dict] = lambda robot, diagnostics, at: {}
    servos: Callable[[Any], list[tuple[int, str, str]]] = lambda robot: []
    components: tuple[str, ...] = ()

    @property
    def properties(self) -> dict[str, dict]:
        """The JSON Schema of each robot type field the part owns (robot.schema.json `properties`)."""
        return schemas_of(self.fields)


class PartReader(KeywordReader):
    """The state of reading one `.robi` file that the parts' keyword functions share."""

    def __init__(self, source: str, diagnostics: Diagnostics, dialect: str):
        super().__init__(source, diagnostics)
        self.dialect = dialect
        self.fields: dict = {}  # robot type fields read so far
        self.where: dict[str, Location] = {}  # where a field or part was written (robot_type checks)
        self.collected: dict = {}  # what a part gathers for its `finish`, under the part's own keys

    def positive(self, line: Line, value: float, index: int, name: str) -> bool:
        if value <= 0:
            self.error(
                line,
                f"{line.keyword}: expected {name} > 0, found {quoted(line.tokens[index].text)}",
                index,
                "bad-value",
            )
            return False
        return True

    def whole(self, line: Line, index: int, name: str, minimum: int | None = None) -> int | None:
        text = line.tokens[index].text
        value = integer(text)
        if value is None or (minimum is not None and value < minimum):
            need = f"a whole number >= {minimum}" if minimum is not None else "a whole number"
            self.error(line, f"{line.keyword}: expected {name} ({need}), found {quoted(text)}", index)
            return None
        return value

    def body_point(self, x: float, y: float, z: float) -> tuple[float, float, float]:
        """A mass centre or collider position in the robot frame."""
        return (x + 0.0, y + 0.0, z + 0.0) if self.dialect == "eyesim" else vr_to_robot(x, y, z)

    def remember(self, key: str, line: Line) -> None:
        self.where.setdefault(key, self.at(line))


def vr_to_robot(x: float, y: float, z: float) -> tuple[float, float, float]:
    """VR model space (X right, Y up, Z forward) to the robot frame (x forward, y left, z up)."""
    return (z + 0.0, -x + 0.0, y + 0.0)


VR_AXIS = {"x": "y", "y": "z", "z": "x"}  # a VR model-space axis in the robot frame


def name_token(name: str) -> str:
    """A name token for writing: quoted when it would read as a number."""
    token = quote_token(name)
    return f'"{name}"' if token == name and number(name) is not None else token


# -- JSON Schema fragments ---------------------------------------------------------------------
# Every field has a title (a label for forms) and, where it has a unit, a description naming it.
def _field(title: str, schema: dict, description: str | None) -> dict:
    return {"title": title, **schema, **({"description": description} if description else {})}


def coordinate(title: str, description: str | None = None) -> dict:
    """Any number (a position, an angle, an offset)."""
    return _field(title, {"type": "number", "minimum": -LARGEST, "maximum": LARGEST}, description)


def positive(title: str, description: str | None = None) -> dict:
    return _field(title, {"type": "number", "exclusiveMinimum": 0, "maximum": LARGEST}, description)


def at_least(minimum: float, title: str, description: str | None = None) -> dict:
    return _field(title, {"type": "number", "minimum": minimum, "maximum": LARGEST}, description)


def between(low: float, high: float, title: str, description: str, exclusive_high: bool = False) -> dict:
    """A number above `low` and up to `high` (below it when `exclusive_high`)."""
    top = {"exclusiveMaximum": high} if exclusive_high else {"maximum": high}
    return _field(title, {"type": "number", "exclusiveMinimum": low, **top}, description)


def whole(minimum: int, title: str, description: str | None = None) -> dict:
    return _field(title, {"type": "integer", "minimum": minimum, "maximum": LARGEST}, description)


def text(title: str, description: str | None = None) -> dict:
    return _field(title, {"type": "string", "minLength": 1}, description)


def choice(title: str, values: list, description: str | None = None) -> dict:
    return _field(title, {"enum": values}, description)


def flag(title: str) -> dict:
    return {"title": title, "type": "boolean"}


def numbers(count: int, title: str, description: str | None = None, item: dict | None = None) -> dict:
    """A list of exactly `count` numbers (coordinates unless `item` says otherwise)."""
    item = item or {"type": "number", "minimum": -LARGEST, "maximum": LARGEST}
    return _field(title, {"type": "array", "items": item, "minItems": count, "maxItems": count}, description)


def list_of(definition: str, title: str) -> dict:
    return {"title": title, "type": "array", "items": ref(definition)}


def ref(definition: str) -> dict:
    """A field whose schema is in `$defs` (its title is the definition's)."""
    return {"$ref": f"#/$defs/{definition}"}


def record(title: str, description: str, properties: dict, required: tuple[str, ...] = ()) -> dict:
    """An object with exactly these properties."""
    schema: dict = {"title": title, "type": "object", "description": description}
    if required:
        schema["required"] = list(required)
    return {**schema, "additionalProperties": False, "properties": properties}


SCHEMA = "schema"  # a spec field's metadata key for its JSON Schema


def in_schema(schema: dict) -> dict:
    """A spec dataclass field's metadata giving its JSON Schema (a fragment of the helpers above):
    `x: float = field(metadata=in_schema(coordinate("x", "mm forward")))`."""
    return {SCHEMA: schema}


def schemas_of(spec: type) -> dict[str, dict]:
    """Each field of a dataclass with its own schema (`in_schema`), in the order they are declared."""
    fields = dataclasses.fields(spec)
    unstated = [f.name for f in fields if SCHEMA not in f.metadata]
    if unstated:
        raise ValueError(f"{spec.__name__}: fields without a schema (in_schema): {', '.join(unstated)}")
    return {f.name: f.metadata[SCHEMA] for f in fields}


def record_of(spec: type, title: str, description: str) -> dict:
    """The JSON Schema of a spec dataclass, from its fields (`schemas_of`); those without a
    default are required."""
    required = tuple(
        f.name
        for f in dataclasses.fields(spec)
        if f.default is dataclasses.MISSING and f.default_factory is dataclasses.MISSING
    )
    return record(title, description, schemas_of(spec), required)
