"""The .esObj object format: corpus objects, frames and scale, tolerance, writer."""

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from eyesim.scene.description import Collider, ObjectType
from eyesim.scene.diagnostics import Diagnostics
from eyesim.scene.esobj import parse_esobj, write_esobj
from eyesim.scene.lexer import read_text
from scene_testing import CORPUS, corpus_texts, mutated, random_text


def parse(text, source="o.esObj"):
    diagnostics = Diagnostics()
    return parse_esobj(text, source, diagnostics), diagnostics


def test_stop_sign_collider_is_scaled_into_the_object_frame():
    sign, diagnostics = parse(read_text(CORPUS / "NoahWMueller__Eyesim/Sims/Objects/StopSign/stopsign.esObj"))
    assert not diagnostics.items
    assert (sign.name, sign.model, sign.scale, sign.mass) == ("StopSign", "Stop.obj", 0.025, 2)
    assert sign.colliders == (Collider("capsule", (3.75, 355), (0, 0, 187.5), "z"),)


def test_crate_with_stray_number_and_fixed():
    crate, diagnostics = parse(read_text(CORPUS / "MoeBuTa__LLMEyesim/LLMEyesim/eyesim/worlds/Crate/Boxes.esObj"))
    assert crate.fixed and crate.name == "Crate1"
    assert crate.colliders == (Collider("box", (360, 360, 200), (0, 0, 100)),)
    assert [(d.code, d.location.line) for d in diagnostics.items] == [("ignored-line", 8)]


def test_box_centre_first_then_size_and_axis_letters():
    obj, _ = parse("collider box 10 20 30 1 2 3\ncollider capsule 0 0 0 5 50 x\ncollider sphere 1 2 3 4\n")
    assert obj.colliders == (
        Collider("box", (3, 1, 2), (30, -10, 20)),
        Collider("capsule", (5, 50), (0, 0, 0), "y"),
        Collider("sphere", (4,), (3, -1, 2)),
    )


def test_bare_2018_shapes_and_name_from_file():
    obj, diagnostics = parse("box 0 0 0 1 1 1\n", "/x/customObject.esObj")
    assert obj.name == "customObject" and len(obj.colliders) == 1 and not diagnostics.items


def test_our_dialect_is_already_in_the_object_frame():
    obj, diagnostics = parse(
        "dialect eyesim\nname Can\nscale 0.5\ncollider cylinder 0 0 61 33 122 z\ncolor 200 30 30\n"
    )
    assert obj.colliders == (Collider("cylinder", (33, 122), (0, 0, 61), "z"),) and obj.color == (200, 30, 30)
    assert not diagnostics.items


@pytest.mark.parametrize(
    "line, column",
    [
        ("scale 0", 7),
        ("mass x", 6),
        ("collider box 1 2 3", 10),
        ("collider capsule 0 0 0 1 2 w", 28),
        ("buoyancy -1", 10),
        ("color 1 2 256", 11),
        ("obj", 1),
    ],
)
def test_errors(line, column):
    _, diagnostics = parse(line)
    assert [(d.kind, d.location.column) for d in diagnostics.items][:1] == [("error", column)]


def test_fixed_with_arguments_and_unknown_keywords_warn():
    obj, diagnostics = parse("fixed yes\nfriction 3\n")
    assert obj.fixed and [d.code for d in diagnostics.items] == ["ignored-argument", "unknown-keyword"]


@pytest.mark.parametrize("text", corpus_texts("esObj"))
def test_write_and_read_back(text):
    obj, _ = parse(text)
    again, diagnostics = parse(write_esobj(obj))
    assert again == obj and not diagnostics.items


coord = st.floats(-1e4, 1e4, allow_nan=False)
size = st.floats(0.001, 1e4, allow_nan=False)
colliders = st.one_of(
    st.builds(Collider, st.just("box"), st.tuples(size, size, size), st.tuples(coord, coord, coord)),
    st.builds(Collider, st.just("sphere"), st.tuples(size), st.tuples(coord, coord, coord)),
    st.builds(
        Collider,
        st.sampled_from(["capsule", "cylinder"]),
        st.tuples(size, size),
        st.tuples(coord, coord, coord),
        st.sampled_from("xyz"),
    ),
)
objects = st.builds(
    ObjectType,
    name=st.text("abc XYZ_1", min_size=1, max_size=10).map(str.strip).filter(bool),
    source=st.just("o.esObj"),
    model=st.none() | st.just("a b.obj"),
    scale=size,
    mass=size,
    colliders=st.lists(colliders, max_size=3).map(tuple),
    color=st.tuples(*[st.integers(0, 255)] * 3),
    buoyancy=st.floats(0, 100),
    fixed=st.booleans(),
    center_of_mass=st.none() | st.tuples(coord, coord, coord),
)


@settings(max_examples=200, deadline=None)
@given(objects)
def test_any_object_type_survives_writing_and_reading(obj):
    again, diagnostics = parse(write_esobj(obj))
    assert again == obj and not diagnostics.items


@settings(max_examples=200, deadline=None)
@given(random_text())
def test_random_text_never_crashes(text):
    parse(text)


@settings(max_examples=200, deadline=None)
@given(mutated(corpus_texts("esObj")))
def test_mutated_objects_never_crash(text):
    parse(text)
