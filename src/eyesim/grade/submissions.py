"""Student submissions: one directory each, named after the student. Their files travel with
each case to whichever worker runs it, so no worker needs to see the submissions folder."""

from __future__ import annotations

import hashlib
from dataclasses import dataclass
from pathlib import Path

MAX_BYTES = 20 << 20  # a submission larger than this is refused (a stray video, a build tree)
SKIPPED_DIRS = {".git", "__pycache__", ".venv", "node_modules"}


class SubmissionError(Exception):
    pass


@dataclass
class Submission:
    name: str
    path: Path
    files: dict[str, bytes]  # path relative to the submission (POSIX separators) -> content
    digest: str

    def matching(self, pattern: str) -> list[str]:
        """The submission's files matching a spec's source pattern, sorted (glob, any case of
        the name's letters when nothing matches exactly: students rename)."""
        exact = sorted(name for name in self.files if Path(name).match(pattern))
        if exact:
            return exact
        return sorted(name for name in self.files if Path(name.lower()).match(pattern.lower()))


def read_submission(path: Path, name: str | None = None) -> Submission:
    files: dict[str, bytes] = {}
    total = 0
    for file in sorted(path.rglob("*")):
        relative = file.relative_to(path)
        if any(part in SKIPPED_DIRS or part.startswith(".") for part in relative.parts) or not file.is_file():
            continue
        data = file.read_bytes()
        total += len(data)
        if total > MAX_BYTES:
            raise SubmissionError(f"{path}: more than {MAX_BYTES >> 20} MiB of files")
        files[relative.as_posix()] = data
    digest = hashlib.sha256()
    for file_name, data in files.items():
        digest.update(file_name.encode() + b"\0" + hashlib.sha256(data).digest())
    return Submission(name or path.name, path, files, digest.hexdigest()[:16])


def find_submissions(folder: Path) -> list[Path]:
    """Every directory directly in `folder` (hidden ones aside), sorted by name."""
    if not folder.is_dir():
        raise SubmissionError(f"{folder}: not a directory of submissions")
    found = sorted(p for p in folder.iterdir() if p.is_dir() and not p.name.startswith("."))
    if not found:
        raise SubmissionError(f"{folder}: no submissions (expected one directory per student)")
    return found
