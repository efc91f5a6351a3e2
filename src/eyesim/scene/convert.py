"""Converting a scene file between its text format and its JSON form, in either direction."""

from __future__ import annotations

from pathlib import Path
from typing import Any, Callable

from eyesim.scene.diagnostics import Diagnostics
from eyesim.scene.esobj import write_esobj
from eyesim.scene.json_format import dumps, to_json
from eyesim.scene.loader import kind_of, read_document
from eyesim.scene.maz import write_maz
from eyesim.scene.robi import write_robi
from eyesim.scene.sim import write_sim
from eyesim.scene.wld import write_wld

# kind -> the writer of a document of that kind (read_document gives the kind with the document)
TEXT_WRITERS: dict[str, Callable[[Any], str]] = {
    "scene": write_sim,
    "world": write_wld,
    "maze": write_maz,
    "robot": write_robi,
    "object": write_esobj,
}
TEXT_SUFFIX = {"scene": ".sim", "world": ".wld", "maze": ".maz", "robot": ".robi", "object": ".esObj"}


def convert(path: str | Path, diagnostics: Diagnostics) -> tuple[str, str] | None:
    """(converted text, suffix for it): a text format becomes JSON, JSON becomes its text
    format. None when the file has errors (they are in `diagnostics`)."""
    path = Path(path)
    kind, document = read_document(path, diagnostics)
    if document is None or diagnostics.has_errors:
        return None
    if kind_of(path) == "json":
        return TEXT_WRITERS[kind](document), TEXT_SUFFIX[kind]
    return dumps(to_json(kind, document)), ".json"


def default_output(path: str | Path, suffix: str) -> Path:
    """x.sim -> x.sim.json; x.sim.json -> x.sim; x.json (a world) -> x.wld."""
    path = Path(path)
    if suffix == ".json":
        return path.with_name(path.name + ".json")
    stem = path.name[: -len(".json")] if path.name.lower().endswith(".json") else path.name
    if Path(stem).suffix.lower() == suffix.lower():
        return path.with_name(stem)
    return path.with_name(Path(stem).stem + suffix)
