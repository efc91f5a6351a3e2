"""The Wavefront .obj reader: every face form, materials and their colours, bad lines and files
(warnings naming file:line, no mesh, never an exception), placement, and every real .obj file."""

import logging

import numpy as np
import pytest
from support.corpus import CORPUS

from eyesim.physics import meshes
from eyesim.physics.meshes import model_mesh, placed, read_obj

CORPUS_OBJS = sorted(CORPUS.rglob("*.obj"))


def write(tmp_path, name, text):
    path = tmp_path / name
    path.write_text(text)
    return path


def triangles_as_points(part):
    """Each triangle as a tuple of its corner points, for comparisons that ignore renumbering."""
    return sorted(tuple(tuple(part.vertices[i]) for i in tri) for tri in part.triangles)


def test_every_face_form_and_negative_indices_give_the_same_triangles(tmp_path):
    corners = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\n"
    forms = {
        "plain": "f 1 2 3\n",
        "texture": "f 1/1 2/1 3/1\n",
        "normal": "f 1//1 2//1 3//1\n",
        "both": "f 1/1/1 2/1/1 3/1/1\n",
        "negative": "f -4 -3/1 -2//1\n",
    }
    for name, face in forms.items():
        mesh = read_obj(write(tmp_path, f"{name}.obj", corners + face))
        assert len(mesh.parts) == 1, name
        assert triangles_as_points(mesh.parts[0]) == [((0, 0, 0), (1, 0, 0), (1, 1, 0))], name


def test_polygons_become_a_fan_of_triangles(tmp_path):
    mesh = read_obj(write(tmp_path, "quad.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv -1 0.5 0\nf 1 2 3 4 5\n"))
    part = mesh.parts[0]
    assert len(part.triangles) == 3 and len(part.vertices) == 5
    first = part.vertices[part.triangles[:, 0]]
    assert (first == [0, 0, 0]).all()  # every triangle starts at the polygon's first corner


def test_materials_group_faces_and_take_their_diffuse_colour_from_the_mtl(tmp_path):
    write(tmp_path, "paint.mtl", "newmtl red\nKd 1 0 0\nnewmtl blue\nKd 0 0 1 # a comment\nnewmtl crimson\nKd 1 0 0\n")
    mesh = read_obj(
        write(
            tmp_path,
            "two.obj",
            "mtllib paint.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
            "o first\nusemtl red\nf 1 2 3\ng second\nusemtl blue\nf 1 2 4\nf 1 3 4\n"
            "usemtl crimson\nf 2 3 4\n",
        )
    )
    by_colour = {p.color: p for p in mesh.parts}
    # red and crimson have one colour: one part (one geom) for both
    assert set(by_colour) == {(1.0, 0.0, 0.0), (0.0, 0.0, 1.0)}
    assert len(by_colour[(1.0, 0.0, 0.0)].triangles) == 2 and len(by_colour[(0.0, 0.0, 1.0)].triangles) == 2
    assert mesh.warnings == ()


def test_a_missing_mtl_warns_once_with_file_and_line_and_draws_grey(tmp_path, caplog):
    path = write(tmp_path, "lost.obj", "# header\nmtllib gone.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl red\nf 1 2 3\n")
    with caplog.at_level(logging.WARNING, logger="eyesim"):
        mesh = read_obj(path)
    assert mesh.parts[0].color == meshes.DEFAULT_COLOR
    assert mesh.warnings == (f"{path}:2: material library 'gone.mtl' not found; its materials are grey",)
    assert f"{path}:2: material library 'gone.mtl' not found" in caplog.text


def test_bad_lines_are_skipped_with_warnings_and_the_rest_is_kept(tmp_path):
    path = write(
        tmp_path,
        "bad.obj",
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv one 2 3\nv 0 0 1\nf 1 2 3\nf 1 2\nf 1 2 9\nf 0 1 2\nf 1 x 3\nf 1 2 4\nf 1 2 5\n",
    )
    mesh = read_obj(path)
    texts = "\n".join(mesh.warnings)
    assert f"{path}:4: expected a vertex 'v <x> <y> <z>', found 'v one 2 3'" in texts
    assert f"{path}:7: a face needs at least 3 corners, found 2" in texts
    assert f"{path}:8: face corner 9 names no vertex (there are 5 so far)" in texts
    assert f"{path}:9: face corner 0 names no vertex" in texts
    assert f"{path}:10: expected a face corner like 3, 3/1, 3//2 or 3/1/2, found 'x'" in texts
    # f 1 2 4 uses the bad vertex and is dropped; f 1 2 3 and f 1 2 5 remain
    assert triangles_as_points(mesh.parts[0]) == [((0, 0, 0), (1, 0, 0), (0, 0, 1)), ((0, 0, 0), (1, 0, 0), (0, 1, 0))]


@pytest.mark.parametrize("text", ["", "# nothing\nv 0 0 0\n", "\x00\xff binary \x01\n" * 10, "f 1 2 3\n"])
def test_files_without_usable_faces_give_no_mesh(tmp_path, text, caplog):
    path = tmp_path / "empty.obj"
    path.write_bytes(text.encode("latin-1"))
    with caplog.at_level(logging.WARNING, logger="eyesim"):
        assert read_obj(path) is None
    assert f"{path}: the 3-D model is not used; drawn as its colliders" in caplog.text


def test_huge_files_are_refused(tmp_path, monkeypatch, caplog):
    path = write(tmp_path, "big.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n" + "f 1 2 3\n" * 20)
    monkeypatch.setattr(meshes, "MAX_TRIANGLES", 10)
    with caplog.at_level(logging.WARNING, logger="eyesim"):
        assert read_obj(path) is None
    assert f"{path}:14: more than 10 triangles; the model is too detailed" in caplog.text
    monkeypatch.setattr(meshes, "MAX_FILE_BYTES", 50)
    other = write(tmp_path, "big2.obj", "v 0 0 0\n" * 10)
    assert read_obj(other) is None
    assert "model file too large" in caplog.text


def test_missing_files_and_other_formats_give_no_mesh(tmp_path, caplog):
    assert read_obj(tmp_path / "nowhere.obj") is None
    assert "cannot read the 3-D model" in caplog.text
    write(tmp_path, "robot.ms3d", "MS3D000000")
    assert model_mesh(str(tmp_path / "robot.ms3d")) is None
    assert model_mesh(None) is None


def test_a_file_is_read_once_until_it_changes(tmp_path):
    path = write(tmp_path, "once.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")
    assert read_obj(path) is read_obj(path)
    path.write_text("v 0 0 0\nv 2 0 0\nv 0 2 0\nv 0 0 2\nf 1 2 3\nf 1 2 4\n")
    assert len(read_obj(path).parts[0].triangles) == 2


def test_placement_scales_turns_the_model_into_the_body_frame_and_applies_the_robi_offset(tmp_path):
    # A point 1 up (Y), 2 forward (Z) and 3 to the .obj's +x, which EyeSim VR's importer mirrors to
    # its left: in the body frame x forward, y left, z up.
    mesh = read_obj(write(tmp_path, "p.obj", "v 3 1 2\nv 0 0 0\nv 0 0 1\nv 1 0 0\nf 1 2 3\nf 2 3 4\n"))

    def point(parts):
        return parts[0].vertices[0]

    assert np.allclose(point(placed(mesh)), [2, 3, 1])
    assert np.allclose(point(placed(mesh, scale=0.5, shift=(0, 0, -1))), [1, 1.5, -0.5])
    # .robi `model <file> 14 0 0 0 90 0`: turned 90 degrees about the up axis, then 14 mm to the right
    turned = point(placed(mesh, offset_mm=(14, 0, 0), rotation_deg=(0, 90, 0)))
    assert np.allclose(turned, [3, -2.014, 1])


@pytest.mark.parametrize("path", CORPUS_OBJS, ids=lambda p: str(p.relative_to(CORPUS)))
def test_every_real_obj_file_loads(path):
    mesh = read_obj(path)
    assert mesh is not None and mesh.parts
    low, high = mesh.bounds()
    assert (high - low > 0).all()
    for part in mesh.parts:
        assert part.triangles.min() >= 0 and part.triangles.max() < len(part.vertices)


def test_the_corpus_has_all_thirteen_obj_files():
    assert len(CORPUS_OBJS) == 13
