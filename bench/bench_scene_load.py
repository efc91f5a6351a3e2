"""Benchmark: load every real EyeSim scene file of the corpus; compare with just reading the bytes.

Run:  PYTHONPATH=. python3 bench/bench_scene_load.py [--repeat N]
Prints a table and writes bench/results/scene_load.json. Targets (issue "Scene files"): the whole
corpus under 3 s, the largest world under 50 ms.
"""

from __future__ import annotations

import argparse
import json
import platform
import statistics
import time
from pathlib import Path

from eyesim.scene import load_scene
from eyesim.scene.diagnostics import Diagnostics
from eyesim.scene.loader import read_definition

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
    print("slowest files: " + ", ".join(f"{Path(s['file']).name} {s['best_s'] * 1000:.1f} ms"
                                        for s in result["slowest_files"]))
    ok = total < 3.0 and big < 0.050
    print("targets (< 3 s in total, largest world < 50 ms): " + ("met" if ok else "NOT met"))
    RESULTS.mkdir(parents=True, exist_ok=True)
    (RESULTS / "scene_load.json").write_text(json.dumps(result, indent=2) + "\n", encoding="utf-8")


if __name__ == "__main__":
    main()
