"""A three-line scene cannot exhaust memory: the models of all placements together may hold at most
MAX_SCENE_TRIANGLES triangles (one detailed model placed 50 times took 24 GB), refused with the
placement's file:line, at once and before MuJoCo is asked for anything."""

from __future__ import annotations

from support.programs import run_headless

from eyesim.world.builder import MAX_SCENE_TRIANGLES

TRIANGLES_PER_MODEL = 100_000


def detailed_model(folder) -> None:
    """An object whose .obj has TRIANGLES_PER_MODEL small triangles over a grid of vertices."""
    side = 250
    lines = [f"v {x * 0.0004:.4f} {y * 0.0004:.4f} 0" for y in range(side) for x in range(side)]
    faces = []
    for y in range(side - 1):
        for x in range(side - 1):
            a = y * side + x + 1
            faces += [f"f {a} {a + 1} {a + side}", f"f {a + 1} {a + side + 1} {a + side}"]
    lines += faces[:TRIANGLES_PER_MODEL]
    (folder / "detailed.obj").write_text("\n".join(lines) + "\n")
    (folder / "Detailed.esObj").write_text("obj detailed.obj\nname Detailed\nmass 0.1\nbox 50 50 5 100 100 10\n")


def test_too_many_triangles_together_are_refused_at_the_placement(tmp_path):
    detailed_model(tmp_path)
    count = MAX_SCENE_TRIANGLES // TRIANGLES_PER_MODEL + 1
    placements = [f"Detailed {100 + 120 * (k % 15)} {100 + 120 * (k // 15)} 0" for k in range(count)]
    (tmp_path / "heavy.sim").write_text(
        "\n".join(["world %sim%/scenes/arena.wld", "obj Detailed.esObj", *placements]) + "\n"
    )
    result = run_headless("heavy.sim", "--until", "0.1", cwd=tmp_path, timeout=300)
    assert result.returncode == 2
    line = 2 + count  # the placement that passes the limit
    assert f"heavy.sim:{line}" in result.stderr
    assert f"more than {MAX_SCENE_TRIANGLES} triangles together" in result.stderr
    assert "placed 21 time(s)" in result.stderr and "Traceback" not in result.stderr


def test_a_few_placements_of_the_same_model_are_fine(tmp_path):
    detailed_model(tmp_path)
    (tmp_path / "light.sim").write_text(
        "world %sim%/scenes/arena.wld\nobj Detailed.esObj\nDetailed 500 500 0\nDetailed 800 500 0\n"
    )
    result = run_headless("light.sim", "--until", "0.1", cwd=tmp_path, timeout=300)
    assert result.returncode == 0, result.stderr
