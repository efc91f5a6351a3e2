"""Shared pieces of the benchmarks: starting the simulator, building C programs, statistics."""

from __future__ import annotations

import json
import os
import re
import statistics
import subprocess
import sys
import time
from pathlib import Path

BENCH = Path(__file__).resolve().parent
RESULTS = BENCH / "results"


def eyesim(*args: str) -> list[str]:
    return [sys.executable, "-m", "eyesim", *args]


def build_c(source: Path, output: Path) -> Path:
    output.parent.mkdir(parents=True, exist_ok=True)
    subprocess.run(eyesim("cc", "-O2", str(source), "-o", str(output)), check=True, cwd=BENCH)
    return output


def start_simulator(*args: str, env: dict | None = None) -> tuple[subprocess.Popen, int]:
    """Start `eyesim run` (headless unless args say otherwise) on a free port; return it and the port."""
    process = subprocess.Popen(
        eyesim("run", "--port", "0", *args), stdout=subprocess.PIPE, text=True, cwd=BENCH, env=env
    )
    deadline = time.time() + 60
    for line in process.stdout:
        match = re.search(r"programs connect to [\d.]+:(\d+)", line)
        if match:
            return process, int(match.group(1))
        if time.time() > deadline:
            break
    process.kill()
    raise RuntimeError("the simulator did not start")


def stop(process: subprocess.Popen) -> None:
    process.terminate()
    try:
        process.wait(timeout=10)
    except subprocess.TimeoutExpired:
        process.kill()


def summary(samples_us: list[float]) -> dict:
    ordered = sorted(samples_us)
    return {
        "n": len(ordered),
        "mean_ms": statistics.fmean(ordered) / 1000,
        "median_ms": ordered[len(ordered) // 2] / 1000,
        "p99_ms": ordered[min(len(ordered) - 1, int(len(ordered) * 0.99))] / 1000,
        "max_ms": ordered[-1] / 1000,
    }


def write_results(name: str, results: dict) -> Path:
    RESULTS.mkdir(exist_ok=True)
    path = RESULTS / f"{name}.json"
    results = dict(results, machine={"cpus": os.cpu_count(), "python": sys.version.split()[0]})
    path.write_text(json.dumps(results, indent=2))
    return path


def print_table(title: str, rows: list[tuple], headers: tuple) -> None:
    print(title)
    widths = [max(len(str(x)) for x in col) for col in zip(headers, *rows)]
    for row in (headers, *rows):
        print("  ".join(str(cell).ljust(width) for cell, width in zip(row, widths)))
