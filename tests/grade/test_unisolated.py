"""Where bubblewrap is missing, `eyesim grade` says that cases are not isolated, and
--require-isolation refuses to grade, whether the cases run in the local pool or on a `local:N`
Dask cluster (its workers run on this machine too). A remote cluster is left to its workers.

Here bubblewrap is missing for real: `eyesim grade` runs with a PATH that has every program of
this machine's PATH but bwrap."""

from __future__ import annotations

import json
import os
from pathlib import Path

import pytest
from support.grading import ARRIVE_SPEC, ARRIVES, grade

WARNING = "eyesim grade: warning: cases are not isolated from each other: bubblewrap is not installed"


@pytest.fixture
def without_bubblewrap(tmp_path, monkeypatch):
    """PATH as a folder of links to the programs on PATH, bwrap left out (the first of a name wins)."""
    programs = tmp_path / "path"
    programs.mkdir()
    for folder in os.environ["PATH"].split(os.pathsep):
        for program in sorted(Path(folder).glob("*")) if Path(folder).is_dir() else []:
            link = programs / program.name
            if program.name != "bwrap" and not link.exists() and os.access(program, os.X_OK):
                link.symlink_to(program)
    assert (programs / "cc").exists() and not (programs / "bwrap").exists()
    monkeypatch.setenv("PATH", str(programs))


@pytest.fixture
def grading_class(tmp_path):
    (tmp_path / "spec.toml").write_text(ARRIVE_SPEC)
    (tmp_path / "subs" / "ada").mkdir(parents=True)
    (tmp_path / "subs" / "ada" / "prog.c").write_text(ARRIVES)
    return tmp_path


@pytest.mark.parametrize("where", [[], ["--cluster", "local:1"]], ids=["local pool", "local cluster"])
def test_cases_graded_on_this_machine_without_bubblewrap_are_said_not_isolated(
    without_bubblewrap, grading_class, where
):
    done = grade("spec.toml", "subs", "--out", "report", *where, cwd=grading_class)
    assert done.returncode == 0, done.stdout + done.stderr
    assert done.stderr.count(WARNING) == 1, done.stderr
    report = json.loads((grading_class / "report" / "report.json").read_text())
    assert [(case["status"], case["score"]) for case in report["students"][0]["cases"]] == [("ok", 1.0)]


@pytest.mark.parametrize("where", [[], ["--cluster", "local:1"]], ids=["local pool", "local cluster"])
def test_require_isolation_refuses_to_grade_on_this_machine_without_bubblewrap(
    without_bubblewrap, grading_class, where
):
    done = grade("spec.toml", "subs", "--out", "report", "--require-isolation", *where, cwd=grading_class)
    assert done.returncode == 2
    assert done.stderr.startswith("eyesim grade: --require-isolation: cases are not isolated from each other"), (
        done.stderr
    )
    assert not (grading_class / "report").exists()  # refused before anything ran


def test_a_remote_cluster_is_left_to_check_its_own_workers(without_bubblewrap, grading_class):
    done = grade(
        "spec.toml",
        "subs",
        "--out",
        "report",
        "--require-isolation",
        "--cluster",
        "tcp://127.0.0.1:9",
        cwd=grading_class,
        timeout=120,
    )
    assert done.returncode == 2
    assert "not isolated" not in done.stderr, done.stderr
    assert "cannot reach the Dask scheduler at tcp://127.0.0.1:9" in done.stderr, done.stderr
