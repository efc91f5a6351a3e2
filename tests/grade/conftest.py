"""The wall-following lab of examples/grading, graded once per session on the local pool; the
tests read its reports, resume it, and grade it again through a Dask cluster."""

from __future__ import annotations

import json

import pytest
from support.grading import LAB_SPEC, grade, lab_submissions_module


@pytest.fixture(scope="session")
def lab(tmp_path_factory):
    """(submissions folder, student -> variant): one student per variant."""
    folder = tmp_path_factory.mktemp("lab") / "submissions"
    return folder, lab_submissions_module().write_submissions(folder)


@pytest.fixture(scope="session")
def graded_lab(lab, tmp_path_factory):
    """The lab graded by `eyesim grade` on a local pool of 2: (output directory, report.json, process)."""
    submissions, _ = lab
    out = tmp_path_factory.mktemp("lab-report") / "report"
    result = grade(str(LAB_SPEC), str(submissions), "--out", str(out), "--workers", "2", cwd=out.parent)
    assert result.returncode == 0, result.stdout + result.stderr
    return out, json.loads((out / "report.json").read_text()), result
