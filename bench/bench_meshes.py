"""Benchmark: what .obj models cost, as ratios to the same scene without them, in the same run.

A 2 m room with the real stop sign (corpus, 144 triangles) and the real S4blue robot (corpus,
8 008 triangles) looking at it:
1. reading each real .obj file (cold, the cache cleared) against reading its bytes;
2. building the world (load + MuJoCo compile) with the models against with `model` removed;
3. a 320x240 camera image, OpenGL and ray caster, with the models against without them.

Run:  PYTHONPATH=src python3 bench/bench_meshes.py
Prints a table and writes bench/results/meshes.json."""

from __future__ import annotations

import dataclasses
import tempfile
import time
from pathlib import Path

import numpy as np
from common import print_table, write_results

from eyesim.core.engine import Simulation
from eyesim.physics import meshes, render, render_gl
from eyesim.physics.render_raycast import RayCastRenderer
from eyesim.scene.loader import load_scene

REPO = Path(__file__).resolve().parents[1]
CORPUS = REPO.parent / "shared" / "corpus"
STOP_SIGN = CORPUS / "NoahWMueller__Eyesim/Sims/Objects/StopSign/stopsign.esObj"
S4BLUE = CORPUS / "NoahWMueller__Eyesim/Sims/Updated_Robots/S4blue.robi"


def best_ms(action, repeats: int = 7) -> float:
    best = float("inf")
    for _ in range(repeats):
        start = time.perf_counter()
        action()
        best = min(best, time.perf_counter() - start)
    return best * 1000


def scene(directory: Path):
    (directory / "room.wld").write_text("floor 2000 2000\n")
    sim_file = directory / "models.sim"
    sim_file.write_text(
        f'world room.wld\nobj "{STOP_SIGN}"\nrobi "{S4BLUE}"\nS4blue 500 1000 0\nStopSign 1000 1000 0\n'
    )
    return load_scene(sim_file)


def without_models(description):
    return dataclasses.replace(
        description,
        robot_types={k: dataclasses.replace(t, model=None) for k, t in description.robot_types.items()},
        object_types={k: dataclasses.replace(t, model=None) for k, t in description.object_types.items()},
    )


def read_rows() -> list[tuple]:
    rows = []
    for path in sorted(CORPUS.rglob("*.obj"), key=lambda p: p.stat().st_size):
        baseline = best_ms(path.read_bytes)

        def cold_read(path=path):
            meshes._read_cached.cache_clear()
            meshes.read_obj(path)

        reading = best_ms(cold_read, repeats=3)
        triangles = sum(len(p.triangles) for p in meshes.read_obj(path).parts)
        rows.append(
            (str(path.relative_to(CORPUS)), triangles, round(baseline, 3), round(reading, 1), round(reading / baseline))
        )
    return rows


def main() -> None:
    results = {"read": read_rows()}
    print_table(
        "Reading the real .obj files (cold)",
        results["read"],
        ("file", "triangles", "read bytes ms", "read_obj ms", "x bytes"),
    )

    with tempfile.TemporaryDirectory() as directory:
        with_models = scene(Path(directory))
    plain = without_models(with_models)
    build = [("build world, no models (baseline)", round(best_ms(lambda: Simulation(plain)), 1), 1.0)]
    with_ms = best_ms(lambda: Simulation(with_models))
    build.append(("build world, with models (cached)", round(with_ms, 1), round(with_ms / build[0][1], 2)))

    view = render.View((0.6, 1.0, 0.15), (1.0, 0.0, 0.0), (0.0, 0.0, 1.0), 320, 240, 60)
    sims = {"no models": Simulation(plain), "models": Simulation(with_models)}
    renderers = {"ray caster": RayCastRenderer()}
    try:
        renderers["opengl"] = render_gl.GlRenderer(render_gl.choose_backend(""))
    except render_gl.NoOpenGL:
        pass
    camera = []
    for name, renderer in renderers.items():
        times = {k: best_ms(lambda s=s, r=renderer: r.render(s.world, view), repeats=20) for k, s in sims.items()}
        camera.append((f"{name}, no models (baseline)", round(times["no models"], 2), 1.0))
        camera.append((f"{name}, models", round(times["models"], 2), round(times["models"] / times["no models"], 2)))
    # the two renderers' images of the model scene differ where OpenGL draws the models
    if "opengl" in renderers:
        gl_image = renderers["opengl"].render(sims["models"].world, view).astype(int)
        cast_image = renderers["ray caster"].render(sims["models"].world, view).astype(int)
        results["pixels_differing"] = round(float((np.abs(gl_image - cast_image).max(axis=2) > 40).mean()), 3)
    results["build"], results["camera"] = build, camera
    print_table("Building the world", build, ("what", "ms", "x baseline"))
    print_table("One 320x240 camera image", camera, ("renderer", "ms", "x baseline"))
    print(f"results: {write_results('meshes', results)}")


if __name__ == "__main__":
    main()
