"""Benchmark: how long `eyesim run --headless --until 0` takes from start to exit, beside the
floor it cannot go below in the same run: a Python that only imports MuJoCo and numpy (the engine
needs both), and a bare Python.

Run:  python3 bench/bench_startup.py [--runs 15]
Prints medians and writes bench/results/startup.json. Target (issue 26): <= 0.3 s.
"""

from __future__ import annotations

import argparse
import json
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from common import eyesim  # noqa: E402

RESULTS = Path(__file__).resolve().parent / "results"


def seconds(command: list[str], cwd: str) -> float:
    started = time.perf_counter()
    subprocess.run(command, cwd=cwd, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return time.perf_counter() - started


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=15)
    args = parser.parse_args()
    commands = {
        "eyesim run --headless --until 0": eyesim("run", "--headless", "--port", "0", "--until", "0"),
        "python -c 'import mujoco, numpy'": [sys.executable, "-c", "import mujoco, numpy"],
        "python -c pass": [sys.executable, "-c", "pass"],
    }
    times: dict[str, list[float]] = {name: [] for name in commands}
    with tempfile.TemporaryDirectory() as folder:
        for _ in range(args.runs):  # interleaved, so that load on the machine hits all alike
            for name, command in commands.items():
                times[name].append(seconds(command, folder))
    medians = {name: statistics.median(values) for name, values in times.items()}
    floor = medians["python -c 'import mujoco, numpy'"]
    for name, median in medians.items():
        print(f"{name:36s} {median * 1000:7.0f} ms  ({median / floor:.2f}x the MuJoCo import)")
    RESULTS.mkdir(exist_ok=True)
    (RESULTS / "startup.json").write_text(json.dumps({"runs": args.runs, "median_s": medians}, indent=1))


if __name__ == "__main__":
    main()
