"""What the .robi reader makes of every corpus robot file and built-in robot: the full
description (every field, defaults included), the diagnostics and the text the writer gives.

tests/scene/robi_descriptions.json holds these as the reader before the part declarations
(scene/parts/) gave them; `python tests/scene/robi_snapshot.py OUT` writes them anew."""

from __future__ import annotations

import dataclasses
import json
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))  # tests/, also when run as a script
from support.corpus import CORPUS  # noqa: E402

HERE = Path(__file__).resolve().parent
BUILTIN_ROBOTS = HERE.parents[1] / "src" / "eyesim" / "data" / "robots"


def robi_files() -> dict[str, Path]:
    """Key (corpus-relative path, or builtin/<name>) -> file."""
    files = {str(p.relative_to(CORPUS)): p for p in CORPUS.rglob("*") if p.suffix.lower() == ".robi"}
    files.update({f"builtin/{p.relative_to(BUILTIN_ROBOTS)}": p for p in BUILTIN_ROBOTS.rglob("*.robi")})
    return dict(sorted(files.items()))


def plain(value):
    if dataclasses.is_dataclass(value):
        return {f.name: plain(getattr(value, f.name)) for f in dataclasses.fields(value) if f.name != "source"}
    if isinstance(value, (tuple, list)):
        return [plain(v) for v in value]
    return value


def snapshot() -> dict:
    from eyesim.scene.diagnostics import Diagnostics
    from eyesim.scene.lexer import read_text
    from eyesim.scene.robi import parse_robi, write_robi

    result = {}
    for key, path in robi_files().items():
        diagnostics = Diagnostics()
        robot = parse_robi(read_text(path), key, diagnostics)
        result[key] = {
            "description": plain(robot),
            "diagnostics": [str(d) for d in diagnostics.items],
            "written": write_robi(robot),
        }
    return result


if __name__ == "__main__":
    Path(sys.argv[1]).write_text(json.dumps(snapshot(), indent=1, sort_keys=True) + "\n", encoding="utf-8")
