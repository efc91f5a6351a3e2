"""The robot part declarations (scene/parts/): the .robi reader, writer, JSON and schema built
from them read every real robot file as before and agree with each other."""

import dataclasses
import json
import typing
from pathlib import Path

import jsonschema
import pytest

from eyesim.scene.description import RobotType
from eyesim.scene.diagnostics import Diagnostics
from eyesim.scene.json_format import dumps, parse_json, schema, to_json
from eyesim.scene.lexer import read_text
from eyesim.parts.part import coordinate, in_schema, positive, record_of
from eyesim.parts.psd.declaration import PsdSpec
from eyesim.scene.parts import KEYWORDS, PARTS, check_bases
from eyesim.scene.robi import parse_robi, write_robi
from robi_snapshot import robi_files, snapshot
from scene_testing import without_locations

EXPECTED = json.loads((Path(__file__).parent / "robi_descriptions.json").read_text(encoding="utf-8"))


def test_every_robot_file_reads_and_writes_as_before_the_part_declarations():
    now = snapshot()
    assert len(now) >= 14 and now.keys() == EXPECTED.keys()
    for key, expected in EXPECTED.items():
        assert now[key] == expected, key


@pytest.mark.parametrize("key", list(robi_files()))
def test_robi_and_json_round_trips(key):
    """robi -> description -> robi -> description, and description -> JSON -> description."""
    robot = parse_robi(read_text(robi_files()[key]), key, Diagnostics())
    diagnostics = Diagnostics()
    again = parse_robi(write_robi(robot), "again.robi", diagnostics)
    assert not diagnostics.has_errors
    assert without_locations(again) == without_locations(robot)
    assert write_robi(again) == write_robi(robot)
    text = dumps(to_json("robot", robot))
    diagnostics = Diagnostics()
    kind, from_json = parse_json(text, "again.json", diagnostics)
    assert kind == "robot" and not diagnostics.has_errors
    assert without_locations(from_json) == without_locations(robot)


def test_each_keyword_and_field_belongs_to_one_part():
    assert len(KEYWORDS) == sum(len(part.keywords) for part in PARTS)
    fields = [f.name for part in PARTS for f in dataclasses.fields(part.fields)]
    assert len(fields) == len(set(fields))
    assert ["name", "source"] + fields == [f.name for f in dataclasses.fields(RobotType)]


def test_robot_type_derives_from_every_parts_fields_in_order():
    """A part in PARTS whose fields RobotType lacks (or in another order) is refused by name."""
    check_bases(RobotType, PARTS)
    with pytest.raises(TypeError, match="last part first: DriveFields, ArmFields, .* BodyFields, Named$"):
        check_bases(RobotType, PARTS[1:] + PARTS[:1])
    assert typing.get_type_hints(RobotType)["psds"] == tuple[PsdSpec, ...]


def test_the_components_a_part_names_are_what_the_robot_builder_calls():
    from eyesim.robot.components import factories  # imports the physics: only here, not when reading

    named = [name for part in PARTS for name in part.components]
    assert {"eyesim.parts.psd.component:create", "eyesim.parts.arm.component:create"} <= set(named)
    called = {f"{factory.__module__}:{factory.__name__}" for factory in factories()}
    assert set(named) <= called


def test_the_schema_is_assembled_from_the_parts_fragments():
    published = schema("robot")
    fields = [f.name for part in PARTS for f in dataclasses.fields(part.fields)]
    assert list(published["properties"]) == ["format", "version", "name", *fields]  # in the order files are written
    referenced = {ref.rsplit("/", 1)[1] for ref in _refs(published)}
    assert referenced == set(published["$defs"])  # every definition used, none missing
    for part in PARTS:
        for name, definition in part.properties.items():
            assert published["properties"][name] == definition, (part.name, name)


def test_every_field_of_the_schema_has_a_title():
    """The robot editor labels its form fields with them."""

    def walk(node, path):
        if isinstance(node, dict):
            for name, field in node.get("properties", {}).items():
                assert "title" in field or "$ref" in field, f"{path}/{name}"
            for key, value in node.items():
                walk(value, f"{path}/{key}")

    published = schema("robot")
    walk(published, "")
    assert all("title" in definition for definition in published["$defs"].values())


def test_the_schema_accepts_what_the_writer_writes_and_rejects_unknown_parts():
    robot = parse_robi(read_text(robi_files()["builtin/S4.robi"]), "S4.robi", Diagnostics())
    data = to_json("robot", robot)
    jsonschema.validate(data, schema("robot"))
    with pytest.raises(jsonschema.ValidationError):
        jsonschema.validate({**data, "sonar": []}, schema("robot"))


def test_a_keyword_error_keeps_its_file_and_line():
    diagnostics = Diagnostics()
    parse_robi("name x\npsd PSD_FRONT 1 10 0 y 0\ncamera 1 2\n", "bot.robi", diagnostics)
    assert [str(d) for d in diagnostics.items] == [
        "bot.robi:2:22: error: psd: expected z (a number), found 'y'",
        "bot.robi:3:1: error: camera: expected 7 arguments (camera <x> <y> <z> <pan> <tilt> <a> <b>), found 2: '1 2'",
    ]


def _refs(node):
    if isinstance(node, dict):
        for key, value in node.items():
            if key == "$ref":
                yield value
            else:
                yield from _refs(value)
    elif isinstance(node, list):
        for value in node:
            yield from _refs(value)


def test_a_spec_dataclass_states_its_schema_on_its_fields():
    """record_of: the fields in order, each with its own schema; those without a default required."""

    @dataclasses.dataclass(frozen=True)
    class Strip:
        x: float = dataclasses.field(metadata=in_schema(coordinate("x", "mm forward")))
        width: float = dataclasses.field(default=10.0, metadata=in_schema(positive("Width", "mm")))

    schema = record_of(Strip, "Strip", "a strip")
    assert list(schema["properties"]) == ["x", "width"] and schema["required"] == ["x"]
    assert schema["properties"]["width"] == positive("Width", "mm")

    @dataclasses.dataclass(frozen=True)
    class Unstated:
        x: float = dataclasses.field(metadata=in_schema(coordinate("x")))
        y: float = 0.0

    with pytest.raises(ValueError, match="Unstated: fields without a schema \\(in_schema\\): y"):
        record_of(Unstated, "Unstated", "no")
