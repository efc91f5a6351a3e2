"""Fixtures for the part kinds' tests: C programs built once with `eyesim cc`."""

from __future__ import annotations

from pathlib import Path

import pytest
from support.programs import program_builder

PROGRAMS = Path(__file__).resolve().parent / "programs"


@pytest.fixture(scope="session")
def programs(tmp_path_factory):
    """programs(name) -> parts/programs/<name>.c built with `eyesim cc` (once per session)."""
    return program_builder(PROGRAMS, tmp_path_factory.mktemp("part-programs"))
