"""Benchmark: load every real EyeSim scene file of the corpus; compare with just reading the bytes.

Run:  PYTHONPATH=src python3 bench/bench_scene_load.py [--repeat N]
Prints a table and writes bench/results/scene_load.json. Targets (issue "Scene files"): the whole
corpus under 3 s, the largest world under 50 ms. Then large generated scenes at and below the
limits (docs/file-formats.md, "Limits"): loading and building (MuJoCo model and robots) a world of
10 000 and of 20 000 walls, 256 robots and 2 000 cans; target (reliability issue): each in seconds.
"""

from __future__ import annotations

import argparse
import json
import platform
import statistics
import tempfile
import time
from pathlib import Path

from eyesim.scene import limits, load_scene
from eyesim.scene.diagnostics import Diagnostics
from eyesim.scene.loader import read_definition
from eyesim.world.builder import build_world

REPO = Path(__file__).resolve().parents[1]
CORPUS = REPO.parent / "shared" / "corpus"
RESULTS = REPO / "bench" / "results"
KINDS = {"sim": "scene", "wld": "scene", "maz": "scene", "robi": "robot", "esObj": "object"}


def corpus_files() -> list[tuple[Path, str]]:
    rows = (CORPUS / "MANIFEST.tsv").read_text(encoding="utf-8").splitlines()[1:]
    return [(CORPUS / r.split("\t")[0], r.split("\t")[2]) for r in rows if r.split("\t")[2] in KINDS]


def load(path: Path, kind: str) -> None:
    if KINDS[kind] == "scene":
        load_scene(path)
    else:
        read_definition(path, KINDS[kind], Diagnostics())


def timed(action) -> float:
    start = time.perf_counter()
    action()
    return time.perf_counter() - start


def large_scenes(directory: Path) -> dict[str, Path]:
    """Generated scenes: walls in rows of short segments, robots and cans on grids (apart)."""

    def wld(name: str, walls: int) -> Path:
        lines = ["floor 20000 20000"] + [
            f"{i % 150 * 100} {i // 150 * 100} {i % 150 * 100 + 50} {i // 150 * 100}" for i in range(walls)
        ]
        path = directory / name
        path.write_text("\n".join(lines) + "\n")
        return path

    def sim(name: str, world: Path, placements: list[str]) -> Path:
        path = directory / name
        path.write_text("\n".join([f"world {world.name}", *placements]) + "\n")
        return path

    empty = wld("empty.wld", 0)
    return {
        "10 000 walls": sim("walls10k.sim", wld("walls10k.wld", 10_000), ["S4 25 50 0"]),
        f"{limits.MAX_WALLS} walls (the limit)": sim(
            "walls20k.sim", wld("walls20k.wld", limits.MAX_WALLS), ["S4 25 50 0"]
        ),
        f"{limits.MAX_ROBOTS} robots (the limit)": sim(
            "robots.sim",
            empty,
            [f"S4 {300 + 400 * (i % 40)} {300 + 400 * (i // 40)} 0" for i in range(limits.MAX_ROBOTS)],
        ),
        f"{limits.MAX_OBJECTS} cans (the limit)": sim(
            "cans.sim",
            empty,
            [f"Can {200 + 150 * (i % 100)} {200 + 150 * (i // 100)} 0" for i in range(limits.MAX_OBJECTS)],
        ),
    }


def measure_large(repeat: int) -> list[dict]:
    rows = []
    with tempfile.TemporaryDirectory() as directory:
        for name, path in large_scenes(Path(directory)).items():
            files = [path] + [p for p in Path(directory).glob("*.wld") if p.name in path.read_text()]
            read = min(timed(lambda: [p.read_bytes() for p in files]) for _ in range(repeat))
            loads = [timed(lambda: load_scene(path)) for _ in range(repeat)]
            scene = load_scene(path)
            builds = [timed(lambda: build_world(scene, 0.002)) for _ in range(max(repeat // 2, 2))]
            rows.append(
                {
                    "scene": name,
                    "bytes": sum(p.stat().st_size for p in files),
                    "read_s": read,
                    "load_s": min(loads),
                    "build_s": min(builds),
                }
            )
    return rows


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=5)
    args = parser.parse_args()
    files = corpus_files()
    worlds = [(p, k) for p, k in files if k in ("wld", "maz")]
    largest = max(worlds, key=lambda item: item[0].stat().st_size)

    cold = timed(lambda: [load(p, k) for p, k in files])  # first pass: built-ins parsed, caches empty
    baseline = [timed(lambda: [p.read_bytes() for p, _ in files]) for _ in range(args.repeat)]
    totals = [timed(lambda: [load(p, k) for p, k in files]) for _ in range(args.repeat)]
    largest_times = [timed(lambda: load(*largest)) for _ in range(args.repeat * 4)]
    per_file = sorted(((min(timed(lambda: load(p, k)) for _ in range(3)), p) for p, k in files), reverse=True)

    base, total, big = min(baseline), min(totals), min(largest_times)
    result = {
        "files": len(files),
        "repeat": args.repeat,
        "python": platform.python_version(),
        "machine": platform.machine(),
        "baseline_read_bytes_s": base,
        "load_all_cold_s": cold,
        "load_all_best_s": total,
        "load_all_median_s": statistics.median(totals),
        "ratio_load_to_read": total / base,
        "largest_world": str(largest[0].relative_to(CORPUS)),
        "largest_world_bytes": largest[0].stat().st_size,
        "largest_world_best_s": big,
        "slowest_files": [{"file": str(p.relative_to(CORPUS)), "best_s": t} for t, p in per_file[:5]],
        "targets": {"load_all_s": 3.0, "largest_world_s": 0.050},
    }
    rows = [
        ("read bytes of all files (baseline)", base, 1.0),
        ("load all files, first pass", cold, cold / base),
        ("load all files, best of repeats", total, total / base),
        (f"largest world ({result['largest_world_bytes']} bytes)", big, big / (base / len(files))),
    ]
    print(f"Scene loading: {len(files)} corpus files, best of {args.repeat}")
    print(f"{'what':44} {'time':>10} {'x baseline':>11}")
    for name, seconds, ratio in rows:
        print(f"{name:44} {seconds * 1000:8.1f} ms {ratio:10.1f}x")
    print(f"largest world: {result['largest_world']}")
    print(
        "slowest files: "
        + ", ".join(f"{Path(s['file']).name} {s['best_s'] * 1000:.1f} ms" for s in result["slowest_files"])
    )
    ok = total < 3.0 and big < 0.050
    print("targets (< 3 s in total, largest world < 50 ms): " + ("met" if ok else "NOT met"))
    large = measure_large(args.repeat)
    result["large_scenes"] = large
    print(f"\nLarge generated scenes, best of {args.repeat}")
    print(f"{'scene':26} {'bytes':>9} {'read':>9} {'load':>9} {'x read':>8} {'build':>9}")
    for r in large:
        print(
            f"{r['scene']:26} {r['bytes']:9} {r['read_s'] * 1000:6.2f} ms {r['load_s'] * 1000:6.0f} ms "
            f"{r['load_s'] / r['read_s']:7.0f}x {r['build_s'] * 1000:6.0f} ms"
        )
    slowest = max(r["load_s"] + r["build_s"] for r in large)
    print("target (each loads and builds within 5 s): " + ("met" if slowest < 5 else "NOT met"))
    RESULTS.mkdir(parents=True, exist_ok=True)
    (RESULTS / "scene_load.json").write_text(json.dumps(result, indent=2) + "\n", encoding="utf-8")


if __name__ == "__main__":
    main()
