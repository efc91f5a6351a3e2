"""The bundled examples under Windows: their Python versions graded against the project's own
regression spec (the examples' grading/examples.toml, with each C source replaced by its Python
twin), and the camera example rendering through WGL, as on a Windows desktop."""

from __future__ import annotations

import re

from wine_sim import processes_mentioning


def python_spec(c_spec: str) -> str:
    """examples.toml with every program's C source replaced by its Python version (same name, .py)."""
    spec, count = re.subn(
        r'sources = \["(\w+)\.c"\]\nflags = \[[^\]]*\]', r'sources = ["\1.py"]\nlanguage = "python"', c_spec
    )
    assert count == c_spec.count("[programs."), "examples.toml's programs are no longer written as expected"
    return spec


def test_the_examples_python_versions_behave_as_expected(windows, tmp_path):
    # `eyesim examples DIR` under Wine: the examples as the installed Windows package ships them.
    result = windows.run("examples", "examples", cwd=tmp_path)
    assert result.returncode == 0, result.stdout + result.stderr
    examples = tmp_path / "examples"
    spec = examples / "grading" / "examples_python.toml"
    spec.write_text(python_spec((examples / "grading" / "examples.toml").read_text()))
    checks = spec.read_text().count("[[cases.checks]]")

    result = windows.run(
        "grade",
        "grading/examples_python.toml",
        "--submission",
        "programs",
        "--out",
        "report",
        "--workers",
        "2",
        "--require-pass",
        cwd=examples,
        timeout=600,
    )
    assert result.returncode == 0, result.stdout + result.stderr  # FAILED <case>: <check>: <what went wrong>
    assert re.search(rf"^programs +100\.0  \({checks}/{checks} checks\)$", result.stdout, flags=re.MULTILINE), (
        result.stdout
    )


def test_cameras_render_with_opengl_through_wgl(windows, tmp_path, x_display):
    """colour_track.py finds the red pillar with its camera, rendered by MuJoCo through GLFW and
    WGL (Wine's opengl32 on an X display), not the CPU ray caster."""
    result = windows.run("examples", "examples", cwd=tmp_path)
    assert result.returncode == 0, result.stdout + result.stderr
    examples = tmp_path / "examples"
    result = windows.run(
        "run",
        "scenes/colour_track.sim",
        "--headless",
        "--until",
        "30",
        "--port",
        "0",
        "--program",
        "1=programs/colour_track.py",
        "--verbose",
        cwd=examples,
        env=windows.env.environment(DISPLAY=x_display),
    )
    assert result.returncode == 0, result.stdout + result.stderr
    assert "cameras render with OpenGL (glfw)" in result.stdout + result.stderr, result.stdout + result.stderr
    assert "arrived: the target fills" in result.stdout, result.stdout
    assert "program colour_track.py: exit code 0" in result.stdout, result.stdout
    assert not processes_mentioning(windows.path(tmp_path))
