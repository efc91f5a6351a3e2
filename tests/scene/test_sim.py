"""The .sim scene format: every statement of the three dialects, placements, errors, writer."""

import pytest
from hypothesis import given, settings

from eyesim.scene.description import Marker, Settings
from eyesim.scene.diagnostics import Diagnostics
from eyesim.scene.json_format import dumps, parse_json, to_json
from eyesim.scene.sim import Placement, Reference, parse_sim, write_sim
from scene_testing import corpus_texts, mutated, random_text, without_locations


def parse(text):
    diagnostics = Diagnostics()
    return parse_sim(text, "s.sim", diagnostics), diagnostics


def test_vr_scene():
    doc, diagnostics = parse(
        'world "./noReturn_world.wld"\nsettings VIS trace\nrobot custom/Rover.robi\n'
        "object props/cone.esObj\nRover 600 400 90 rover.py\nS4 1500 400 180\nCan 800 300 45\n"
        "marker 1800 1800 255 0 0\nmarker 1 2\nmarker 798 451 255 196 44 128\n"
    )
    assert not diagnostics.items
    assert doc.world.path == "./noReturn_world.wld"
    assert doc.settings == Settings(vis=True, trace=True)
    assert [r.path for r in doc.robot_files] == ["custom/Rover.robi"]
    assert [r.path for r in doc.object_files] == ["props/cone.esObj"]
    assert [(p.type_name, p.x, p.y, p.phi, p.program) for p in doc.placements] == [
        ("Rover", 600, 400, 90, "rover.py"),
        ("S4", 1500, 400, 180, None),
        ("Can", 800, 300, 45, None),
    ]
    assert doc.markers == (Marker(1800, 1800, (255, 0, 0, 255)), Marker(1, 2), Marker(798, 451, (255, 196, 44, 128)))


def test_keywords_are_case_insensitive_and_names_keep_their_case():
    doc, _ = parse("World a.wld\nSETTINGS Vis\nLabbot 1 2 3\n")
    assert doc.world.path == "a.wld" and doc.settings.vis and doc.placements[0].type_name == "Labbot"


def test_maze_start_letters():
    doc, diagnostics = parse("world m.maz\nlabbot s\nS4 S 90 maze.x\nS4 U 65 03-predator.py\nS4 S prog.py\n")
    assert not diagnostics.items
    assert [(p.type_name, p.start, p.phi, p.program) for p in doc.placements] == [
        ("labbot", "s", None, None),
        ("S4", "S", 90, "maze.x"),
        ("S4", "U", 65, "03-predator.py"),
        ("S4", "S", None, "prog.py"),
    ]


def test_eyesim6_statements():
    doc, diagnostics = parse(
        "maze\t%sim%/worlds/mazes/maze1.maz\nrobi\t%sim%/robots/Eve/Eve.robi  maze.dll\n"
        "robi S4Y.robi servo.dll  400 800 0\nobject  800 800 0 0.0 %sim%/worlds/objects/can/can.ms3d\n"
        'robi ../robots/S4/S4.robi\nobj "Path\\To\\customObject.esObj"\n'
    )
    assert not diagnostics.items
    assert doc.world.path == "%sim%/worlds/mazes/maze1.maz"
    assert doc.placements[0] == Placement(
        robi="%sim%/robots/Eve/Eve.robi", program="maze.dll", location=doc.placements[0].location
    )
    assert (doc.placements[1].x, doc.placements[1].y, doc.placements[1].phi) == (400, 800, 0)
    assert (doc.placements[2].model, doc.placements[2].friction) == ("%sim%/worlds/objects/can/can.ms3d", 0)
    assert [r.path for r in doc.robot_files] == ["../robots/S4/S4.robi"]
    assert [r.path for r in doc.object_files] == ["Path\\To\\customObject.esObj"]


@pytest.mark.parametrize(
    "line, column, needle",
    [
        ("world a.wld b.wld", 1, "expected one world file"),
        ("robi a.robi prog.x 1 2", 1, "robi <file.robi> <program>"),
        ("marker 1 2 3", 1, "marker <x> <y>"),
        ("marker 1 2 255 0 256", 18, "0..255"),
        ("marker a 2", 8, "expected x in mm"),
        ("S4 1 2 3 prog.x extra", 17, "found extra 'extra'"),
        ("S4 500", 1, "expected <x> <y> <phi>"),
        ("S4 north", 4, "a position"),
        ("S4", 1, "unknown keyword 'S4'"),
        ("object 1 2 3 x can.ms3d", 14, "friction"),
    ],
)
def test_errors(line, column, needle):
    _, diagnostics = parse(line)
    (d,) = [d for d in diagnostics.items if d.kind == "error"]
    assert d.location.column == column and needle in d.message


def test_warnings():
    doc, diagnostics = parse("world a.wld\nworld b.wld\nsettings VIS FAST\n")
    assert doc.world == Reference("b.wld", doc.world.location)
    assert [d.code for d in diagnostics.items] == ["second-world", "unknown-setting"]


@pytest.mark.parametrize("text", corpus_texts("sim"))
def test_write_and_read_back(text):
    doc, _ = parse(text)
    again, diagnostics = parse(write_sim(doc))
    assert without_locations(again) == without_locations(doc) and not diagnostics.items


def test_names_that_look_like_keywords_are_quoted():
    doc, _ = parse('"world" 1 2 3\n')
    assert doc.placements[0].type_name == "world"
    again, _ = parse(write_sim(doc))
    assert again.placements[0].type_name == "world" and again.world is None


@settings(max_examples=200, deadline=None)
@given(random_text())
def test_random_text_never_crashes(text):
    parse(text)


@settings(max_examples=200, deadline=None)
@given(mutated(corpus_texts("sim")))
def test_mutated_scenes_never_crash_and_write_back(text):
    doc, diagnostics = parse(text)
    if not diagnostics.has_errors:
        again, more = parse(write_sim(doc))
        assert without_locations(again) == without_locations(doc) and not more.has_errors


def test_the_eyesim6_psd_setting_is_read_written_and_converted():
    doc, diagnostics = parse("settings eyesim6psd VIS\n")
    assert not diagnostics.items and doc.settings == Settings(vis=True, eyesim6_psd=True)
    again, _ = parse(write_sim(doc))
    assert again.settings == doc.settings
    kind, from_json = parse_json(dumps(to_json("scene", doc)), "a.json", Diagnostics())
    assert kind == "scene" and from_json.settings == doc.settings
    doc, diagnostics = parse("settings EYESIM6PSD=1\n")  # a flag takes no value
    assert [d.code for d in diagnostics.items] == ["unknown-setting"] and not doc.settings.eyesim6_psd
