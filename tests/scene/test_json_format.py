"""JSON forms: round trips of every corpus file, schema errors with precise paths, fuzzing."""

import json

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from eyesim.scene.diagnostics import Diagnostics
from eyesim.scene.json_format import dumps, parse_json, to_json
from eyesim.scene.loader import read_document
from scene_testing import CORPUS, manifest, without_locations


def read(text, expected=("scene", "world", "maze", "robot", "object")):
    diagnostics = Diagnostics()
    kind, document = parse_json(text, "x.json", diagnostics, expected)
    return kind, document, diagnostics


@pytest.mark.parametrize("relative, _", manifest())
def test_every_corpus_file_survives_json(relative, _):
    kind, document = read_document(CORPUS / relative, Diagnostics())
    text = dumps(to_json(kind, document))
    again_kind, again, diagnostics = read(text)
    assert again_kind == kind and not diagnostics.has_errors
    assert without_locations(again) == without_locations(document)
    assert dumps(to_json(kind, again)) == text


def errors_of(text):
    _, _, diagnostics = read(text)
    return [(d.location.line, d.location.column, d.message) for d in diagnostics.items if d.kind == "error"]


def test_schema_errors_name_the_path_and_position():
    text = (
        '{"format": "eyesim.world", "version": 1,\n'
        ' "walls": [{"x1": 0, "y1": "a", "x2": 1, "y2": 1, "colour": [1,2,3]}],\n'
        ' "floor_width": -3}\n'
    )
    assert errors_of(text) == [
        (3, 17, "/floor_width: expected a number > 0, found -3"),
        (2, 51, "/walls/0/colour: unknown property 'colour': expected one of color, height, thickness, x1, x2, y1, y2"),
        (2, 28, '/walls/0/y1: expected a number, found "a"'),
    ]


@pytest.mark.parametrize(
    "data, message",
    [
        ({"format": "eyesim.robot", "version": 1}, "(top level): missing required property 'name'"),
        ({"format": "eyesim.robot", "version": 1, "name": "R", "drive": "tank"}, "/drive: expected one of"),
        (
            {"format": "eyesim.robot", "version": 1, "name": "R", "wheels": {"diameter": 5}},
            "/wheels: missing required properties 'max_speed', 'ticks_per_rev', 'track'",
        ),
        ({"format": "eyesim.maze", "version": 1, "rows": ["|Q|"]}, "/rows/0: expected text matching"),
        ({"format": "eyesim.maze", "version": 2, "rows": ["|"]}, "/version: expected 1, found 2"),
        (
            {"format": "eyesim.scene", "version": 1, "placements": [{"type": "S4", "x": 1}]},
            "/placements/0: matches none of the allowed forms; nearest is a robot or object of a type at x, y, phi: "
            "missing required property 'y'",
        ),
        (
            {"format": "eyesim.scene", "version": 1, "placements": [{"robi": "a.robi", "program": "p", "x": 1}]},
            "nearest is EyeSim 6: define the robot of a .robi file and place it: x, y and phi go together: found only x",
        ),
        ('{"format": "eyesim.object", "version": 1, "name": "O", "mass": 1e400}', "/mass: expected a number <= 1e+09"),
    ],
)
def test_schema_messages(data, message):
    (error,) = errors_of(data if isinstance(data, str) else json.dumps(data))
    assert message in error[2]


def test_syntax_errors_and_wrong_kinds():
    assert errors_of('{"format": "eyesim.world",\n "version": 1,,}') == [
        (2, 15, "invalid JSON: Expecting property name enclosed in double quotes")
    ]
    assert "expected a JSON object" in errors_of("[1, 2]")[0][2]
    assert "found 'eyesim.planet'" in errors_of('{"format": "eyesim.planet"}')[0][2]
    assert "invalid JSON: NaN" in errors_of('{"format": "eyesim.world", "version": 1, "floor_width": NaN}')[0][2]
    _, _, diagnostics = read('{"format": "eyesim.robot", "version": 1, "name": "R"}', expected=("world",))
    assert diagnostics.has_errors


def test_semantic_errors_point_into_the_json():
    text = json.dumps(
        {
            "format": "eyesim.robot",
            "version": 1,
            "name": "R",
            "wheels": {"diameter": 54, "max_speed": 3600, "ticks_per_rev": 1100, "track": 90},
            "psds": [
                {"id": 1, "name": "A", "x": 0, "y": 0, "z": 0, "heading": 0},
                {"id": 1, "name": "B", "x": 0, "y": 0, "z": 0, "heading": 0},
            ],
        },
        indent=1,
    )
    (error,) = errors_of(text)
    assert "PSD id 1 of B is already used by A" in error[2]
    assert text.splitlines()[error[0] - 1].strip().startswith("{")


def test_defaults_are_left_out():
    kind, document = read_document(CORPUS / "23082899__distBug/obstacles4k.wld", Diagnostics())
    data = to_json(kind, document)
    assert set(data["walls"][0]) == {"x1", "y1", "x2", "y2"}


json_values = st.recursive(
    st.none() | st.booleans() | st.floats(allow_nan=False) | st.integers() | st.text(max_size=10),
    lambda children: st.lists(children, max_size=4) | st.dictionaries(st.text(max_size=8), children, max_size=4),
    max_leaves=20,
)


@settings(max_examples=200, deadline=None)
@given(
    st.sampled_from(["scene", "world", "maze", "robot", "object"]),
    st.dictionaries(
        st.sampled_from(
            [
                "name",
                "walls",
                "rows",
                "placements",
                "psds",
                "camera",
                "wheels",
                "floor_width",
                "colliders",
                "arm",
                "world",
                "markers",
                "drive",
                "mass",
                "cell_size",
                "start_pose",
                "balls",
            ]
        ),
        json_values,
        max_size=5,
    ),
)
def test_random_json_never_crashes(kind, body):
    read(json.dumps({"format": f"eyesim.{kind}", "version": 1, **body}))


@settings(max_examples=200, deadline=None)
@given(st.text(max_size=200))
def test_random_text_never_crashes(text):
    read(text)
