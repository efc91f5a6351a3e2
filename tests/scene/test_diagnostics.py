"""Diagnostics collection and the SceneError message."""

from eyesim.scene.description import Location
from eyesim.scene.diagnostics import Diagnostics, SceneError, quoted


def test_scene_error_lists_every_diagnostic_in_file_order():
    diagnostics = Diagnostics()
    diagnostics.error(Location("b.sim", 2, 1), "second")
    diagnostics.warning(Location("a.wld", 9, 4), "note")
    diagnostics.error(Location("b.sim", 1, 5), "first")
    error = SceneError(diagnostics.items)
    assert str(error).splitlines() == [
        "a.wld:9:4: warning: note",
        "b.sim:1:5: error: first",
        "b.sim:2:1: error: second",
    ]
    assert [d.message for d in error.errors] == ["first", "second"]


def test_raise_only_on_errors():
    diagnostics = Diagnostics()
    diagnostics.warning(Location("a"), "w")
    diagnostics.raise_if_errors()
    assert [d.kind for d in diagnostics.warnings] == ["warning"]


def test_quoted_shows_the_offending_text():
    assert quoted("abc") == "'abc'"
    assert quoted("it's") == '"it\'s"'
    assert quoted("a\tb") == "'a\\tb'"
    assert len(quoted("x" * 200)) < 70
