"""Recordings of a real C program (tests/e2e/programs/record_tour.c) for the recording and replay tests."""

from __future__ import annotations

from pathlib import Path

from eyesim.paths import DATA_DIR

from support.programs import build, run_headless

# Three S4s in the bundled arena, with sensor rays and paths drawn.
TOUR_SCENE = """world {arena}
settings VIS TRACE
S4 500 500 0
S4 1500 500 90
S4 500 1500 -45
"""


def record_tour(directory: Path, robots: int = 1, *extra: str) -> Path:
    """Runs record_tour on `robots` robots of TOUR_SCENE headless and deterministic into
    directory/tour.mcap (with directory/tour.csv and the final LCDs in directory/lcd); returns the .mcap."""
    program = build("record_tour", directory)
    scene = directory / "tour.sim"
    scene.write_text(TOUR_SCENE.format(arena=DATA_DIR / "scenes" / "arena.wld"))
    programs = [arg for robot in range(1, robots + 1) for arg in ("--program", f"{robot}={program}")]
    result = run_headless(
        str(scene),
        *programs,
        "--record",
        "tour.mcap",
        "--record",
        "tour.csv",
        "--save-lcd",
        "lcd",
        *extra,
        cwd=directory,
    )
    assert result.returncode == 0, result.stdout + result.stderr
    return directory / "tour.mcap"
