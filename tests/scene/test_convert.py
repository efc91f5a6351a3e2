"""Converting every corpus file to JSON and back without loss."""

from pathlib import Path

import pytest

from eyesim.scene.convert import convert, default_output
from eyesim.scene.diagnostics import Diagnostics
from eyesim.scene.loader import read_document
from scene_testing import CORPUS, manifest, without_locations


@pytest.mark.parametrize("relative, _", manifest())
def test_text_to_json_and_back(relative, _, tmp_path):
    original = CORPUS / relative
    text, suffix = convert(original, Diagnostics())
    assert suffix == ".json"
    as_json = tmp_path / (original.name + ".json")
    as_json.write_text(text, encoding="utf-8")
    back, back_suffix = convert(as_json, Diagnostics())
    assert back_suffix.lower() == original.suffix.lower()
    as_text = tmp_path / ("back" + back_suffix)
    as_text.write_text(back, encoding="utf-8")
    diagnostics = Diagnostics()
    _, before = read_document(original, Diagnostics())
    _, after = read_document(as_text, diagnostics)
    assert not diagnostics.has_errors
    assert without_locations(after) == without_locations(before)
    assert convert(as_text, Diagnostics())[0] == text  # and JSON -> text -> JSON is the identity


def test_errors_give_no_output(tmp_path):
    bad = tmp_path / "bad.robi"
    bad.write_text("wheel x\n")
    diagnostics = Diagnostics()
    assert convert(bad, diagnostics) is None and diagnostics.has_errors


@pytest.mark.parametrize(
    "name, suffix, out",
    [
        ("a.sim", ".json", "a.sim.json"),
        ("a.sim.json", ".sim", "a.sim"),
        ("w.json", ".wld", "w.wld"),
        ("R.robi", ".json", "R.robi.json"),
        ("o.esobj.json", ".esObj", "o.esobj"),
    ],
)
def test_default_output_names(name, suffix, out):
    assert default_output(Path("d") / name, suffix) == Path("d") / out


def test_a_converted_scene_loads_to_the_same_scene(tmp_path):
    from eyesim.scene import load_scene

    for name in ("Cluster.sim", "world1.wld"):
        (tmp_path / name).write_bytes((CORPUS / "mikyeo__CITS2200" / name).read_bytes())
    text, _ = convert(tmp_path / "world1.wld", Diagnostics())
    (tmp_path / "world1.wld.json").write_text(text)
    scene_json, _ = convert(tmp_path / "Cluster.sim", Diagnostics())
    (tmp_path / "Cluster.sim.json").write_text(scene_json.replace('"world1.wld"', '"world1.wld.json"'))
    original, converted = load_scene(tmp_path / "Cluster.sim"), load_scene(tmp_path / "Cluster.sim.json")
    assert converted.world.walls == original.world.walls
    assert [(r.type_name, r.pose, r.program) for r in converted.robots] == [
        (r.type_name, r.pose, r.program) for r in original.robots
    ]
    assert [(o.type_name, o.pose) for o in converted.objects] == [(o.type_name, o.pose) for o in original.objects]
    assert converted.robot_types == original.robot_types and converted.settings == original.settings
