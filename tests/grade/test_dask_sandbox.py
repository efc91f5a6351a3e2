"""The hostile submissions of test_sandbox.py, graded through Dask (`eyesim grade --cluster
local:2`), fail as they do on the local pool, and the honest student beside them gets full marks.

All six are graded here, not a sample: the path differs. A Dask worker is a process that lives on
after each case, with the warm runners (grade/warm.py) of its threads, kept by a worker plugin
(grade/dask_workers.py) where the grader is root as in CI, rather than the local pool's.
Whatever the worker keeps (its process tree, its runners, its temporary folders) must not help a
case."""

from __future__ import annotations

import json
import subprocess

from grade.test_sandbox import HONEST, SPEC, case_of, lcd, write_hostile, write_submission
from support.grading import grade

from eyesim.grade import sandbox


def test_the_sandbox_attacks_fail_on_dask_workers_as_they_do_locally(tmp_path):
    assert sandbox.bwrap() is not None, "the sandbox needs bubblewrap: make test installs it (apt install bubblewrap)"
    (tmp_path / "spec.toml").write_text(SPEC)
    submissions, out = tmp_path / "class", tmp_path / "out"
    write_submission(submissions, "alice", HONEST % ("SECRET_ALICE", 250))
    host_tmp, marker = write_hostile(submissions, out)

    done = grade(str(tmp_path / "spec.toml"), str(submissions), "--out", str(out), "--cluster", "local:2", cwd=tmp_path)
    assert done.returncode == 0, done.stdout + done.stderr
    report = json.loads((out / "report.json").read_text())
    assert report["executor"] == "Dask cluster local:2 (2 worker(s))"

    assert case_of(report, "alice")["score"] == 1.0
    assert "classmate:none grader:none" in lcd(report, "hostile_reader")
    assert "plant:no forge:no" in lcd(report, "hostile_planter")
    assert not (submissions / "alice" / "planted.c").exists()
    assert json.loads((out / "cases" / "alice" / "drive.json").read_text())["score"] == 1.0
    assert "outside:no" in lcd(report, "hostile_writer") and not host_tmp.exists()
    assert "wrote 300 MB" not in lcd(report, "hostile_writer")
    assert case_of(report, "hostile_writer")["programs"]["1"]["crashed"]  # SIGXFSZ at the file size limit
    assert int(lcd(report, "hostile_forker").split("forked ")[1].split()[0]) < 300
    assert case_of(report, "hostile_devzero")["status"] == "compile_error"
    assert case_of(report, "hostile_devzero")["timing"]["case_seconds"] < 60
    assert subprocess.run(["pgrep", "-f", f"sleep {marker}"], capture_output=True, text=True).stdout == ""
    assert "100/100" not in (out / "index.html").read_text()
