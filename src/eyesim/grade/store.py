"""Results on disk, one file per finished case, written as they arrive: an interrupted grading
run loses nothing it finished, and the next run with the same spec and submissions picks up
where it stopped.

    OUT/cases/<student>/<case>.json      the result (evidence, checks, score)
    OUT/cases/<student>/<case>/...       its files: final LCD images, its recording (case.mcap)
"""

from __future__ import annotations

import json
import os
from pathlib import Path


def _write_atomically(path: Path, data: bytes) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    temporary = path.with_name(path.name + ".partial")
    temporary.write_bytes(data)
    os.replace(temporary, path)


class ResultStore:
    def __init__(self, out: Path):
        self.out = out
        self.cases = out / "cases"

    def path(self, student: str, case: str) -> Path:
        return self.cases / student / f"{case}.json"

    def load(self, student: str, case: str, key: dict) -> dict | None:
        """A stored result of this student and case made from the same spec and submission."""
        path = self.path(student, case)
        try:
            result = json.loads(path.read_text())
        except (OSError, ValueError):
            return None
        return result if result.get("key") == key else None

    def save(self, result: dict) -> dict:
        """Store a result from a case process; its artifacts become files next to it."""
        result = dict(result)
        artifacts = result.pop("artifacts", {}) or {}
        folder = self.cases / result["student"] / result["case"]
        result["files"] = {}
        for name, data in sorted(artifacts.items()):
            _write_atomically(folder / name, data)
            result["files"][name] = (folder / name).relative_to(self.out).as_posix()
        # The result file last: its presence says the case is complete.
        _write_atomically(
            self.path(result["student"], result["case"]), json.dumps(result, indent=1, sort_keys=True).encode()
        )
        return result
