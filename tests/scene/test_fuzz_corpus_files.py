"""Real corpus files cut short or with bytes changed, loaded as whole scenes where they lie (their
worlds, robots, objects and textures resolve as in the original folder): `load_scene` returns a
Scene or raises SceneError whose every diagnostic names a file and a line, never anything else.

The other scene fuzzers mutate text for one parser (test_sim.py, test_wld.py, ...) or load random
bytes (test_loader.py); these go through the loader with the references intact and cut at any
byte, also inside a UTF-8 sequence or a CRLF. The corpus is read from ../shared/corpus and the
changed copy written to a temporary folder beside links to the original's neighbours.

For a longer run set FUZZ_EXAMPLES (e.g. 5000) and FUZZ_SEED."""

from __future__ import annotations

import tempfile
from pathlib import Path

from hypothesis import given
from hypothesis import strategies as st
from support.fuzz import examples, fuzz_settings

from eyesim.scene import Scene, SceneError, load_scene
from scene_testing import CORPUS, manifest

EXAMPLES = examples(150)
SCENE_FILES = sorted(relative for relative, kind in manifest() if kind in ("sim", "wld", "maz"))
REFERENCED = sorted(relative for relative, kind in manifest() if kind in ("robi", "esObj"))


@st.composite
def changed(draw, content: bytes):
    """`content` cut short, with bytes changed, or both."""
    data = bytearray(content)
    if draw(st.booleans()):
        del data[draw(st.integers(0, len(data))) :]
    for _ in range(draw(st.integers(0, 6))):
        position = draw(st.integers(0, len(data)))
        piece = draw(
            st.binary(min_size=1, max_size=4)
            | st.sampled_from([b"\n", b"\r\n", b"\xe2\x82", b"-", b"9" * 40, b"1e999", b"\x00", b"\t"])
        )
        if draw(st.booleans()):
            data[position : position + len(piece)] = piece
        else:
            data[position:position] = piece
    return bytes(data)


def load_in_place(relative: str, content: bytes, scene: str | None = None):
    """Load `content` as the corpus file `relative` from a folder that links to every other file of
    the original's folder; `scene` (a corpus .sim beside it) is loaded instead when given."""
    original = CORPUS / relative
    with tempfile.TemporaryDirectory() as directory:
        folder = Path(directory)
        for neighbour in original.parent.iterdir():
            if neighbour.name != original.name:
                (folder / neighbour.name).symlink_to(neighbour)
        (folder / original.name).write_bytes(content)
        target = folder / (Path(scene).name if scene else original.name)
        try:
            loaded = load_scene(target)
        except SceneError as error:
            assert error.diagnostics and any(d.kind == "error" for d in error.diagnostics)
            for diagnostic in error.diagnostics:
                assert diagnostic.location.file, diagnostic
                assert diagnostic.location.line >= 0, diagnostic
            first = str(error).splitlines()[0]
            assert first.startswith(f"{error.diagnostics[0].location.file}:"), first
            return error
        assert isinstance(loaded, Scene)
        return loaded


@st.composite
def corpus_file_changed(draw, files):
    relative = draw(st.sampled_from(files))
    return relative, draw(changed((CORPUS / relative).read_bytes()))


@fuzz_settings(EXAMPLES)
@given(corpus_file_changed(SCENE_FILES))
def test_cut_or_changed_corpus_scenes_load_or_say_where_they_are_wrong(case):
    relative, content = case
    load_in_place(relative, content)


def _scenes_using(relative: str) -> list[str]:
    """The corpus .sim files in the same folder as a robot or object file (they may name it)."""
    folder = (CORPUS / relative).parent
    return sorted(p.name for p in folder.glob("*.sim"))


USED_DEFINITIONS = [r for r in REFERENCED if _scenes_using(r)]


@fuzz_settings(EXAMPLES)
@given(corpus_file_changed(USED_DEFINITIONS), st.data())
def test_cut_or_changed_robot_and_object_files_inside_their_scenes(case, data):
    relative, content = case
    scene = data.draw(st.sampled_from(_scenes_using(relative)))
    load_in_place(relative, content, scene)


def test_every_cut_of_one_scene_file_loads_or_says_where():
    """Not random: one world and one scene with references cut at every 7th byte."""
    for relative in (SCENE_FILES[0], next(r for r in SCENE_FILES if r.endswith(".sim"))):
        content = (CORPUS / relative).read_bytes()
        for end in range(0, len(content), 7):
            load_in_place(relative, content[:end])
        assert isinstance(load_in_place(relative, content), Scene)
