"""Grading through a real Dask cluster — a scheduler and two worker processes started here, as a
course would start them on its machines — gives the results the local pool gives."""

from __future__ import annotations

import json
import subprocess
import sys
import time

import pytest
from support.grading import LAB_SPEC, grade

from eyesim.grade.summary import deterministic_view


@pytest.fixture
def dask_cluster(tmp_path):
    """The scheduler's address, once two workers have joined it."""
    from distributed import Client

    scheduler_file = tmp_path / "scheduler.json"
    common = ["--no-dashboard"]
    scheduler = subprocess.Popen(
        [
            sys.executable,
            "-m",
            "dask",
            "scheduler",
            "--host",
            "127.0.0.1",
            "--port",
            "0",
            "--scheduler-file",
            str(scheduler_file),
            *common,
        ],
        cwd=tmp_path,
        stdout=subprocess.DEVNULL,
        stderr=subprocess.DEVNULL,
    )
    workers = subprocess.Popen(
        [
            sys.executable,
            "-m",
            "dask",
            "worker",
            "--scheduler-file",
            str(scheduler_file),
            "--nworkers",
            "2",
            "--nthreads",
            "1",
            "--host",
            "127.0.0.1",
            *common,
        ],
        cwd=tmp_path,
        stdout=subprocess.DEVNULL,
        stderr=subprocess.DEVNULL,
    )
    try:
        for _ in range(600):  # the scheduler writes its file when it listens
            if scheduler_file.exists() and scheduler_file.stat().st_size:
                break
            time.sleep(0.1)
        address = json.loads(scheduler_file.read_text())["address"]
        with Client(address, timeout="30s") as client:
            client.wait_for_workers(2, timeout=120)
        yield address
    finally:
        for process in (workers, scheduler):
            process.terminate()
        for process in (workers, scheduler):
            try:
                process.wait(timeout=30)
            except subprocess.TimeoutExpired:
                process.kill()
                process.wait()


def test_the_lab_graded_on_a_dask_cluster_equals_the_local_grading(lab, graded_lab, dask_cluster, tmp_path):
    local_out, local_report, _ = graded_lab
    out = tmp_path / "dask-report"
    result = grade(str(LAB_SPEC), str(lab[0]), "--out", str(out), "--cluster", dask_cluster, cwd=tmp_path)
    assert result.returncode == 0, result.stdout + result.stderr
    report = json.loads((out / "report.json").read_text())
    assert report["executor"] == f"Dask cluster {dask_cluster} (2 worker(s))"
    assert [(s["name"], s["score"]) for s in report["students"]] == [
        (s["name"], s["score"]) for s in local_report["students"]
    ]
    compared = 0
    for student, local_student in zip(report["students"], local_report["students"]):
        for case, local_case in zip(student["cases"], local_student["cases"]):
            assert deterministic_view(case) == deterministic_view(local_case), (student["name"], case["case"])
            for name, path in case["files"].items():
                if name.endswith("-lcd.png"):
                    assert (out / path).read_bytes() == (local_out / local_case["files"][name]).read_bytes()
            compared += 1
    assert compared == 14


def test_a_cluster_that_cannot_be_reached_or_a_bad_local_size_is_a_usage_error(lab, tmp_path):
    for address, message in (
        ("local:zero", "expected local:N with N workers"),
        ("tcp://127.0.0.1:9", "cannot reach the Dask scheduler at tcp://127.0.0.1:9"),
    ):
        result = grade(
            str(LAB_SPEC), str(lab[0]), "--out", str(tmp_path / "out"), "--cluster", address, cwd=tmp_path, timeout=120
        )
        assert result.returncode == 2 and message in result.stderr, result.stderr
        assert "Traceback" not in result.stderr
