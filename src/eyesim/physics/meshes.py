"""Wavefront .obj models: reading them (with their .mtl colours) and placing them in a body's frame.

A model is only for looks: collisions use the declared colliders. Its triangles are grouped by
material, one part per material, each with the material's diffuse colour (`Kd`). Vertices are in
the file's own units and axes (metres after the .esObj `scale`; Y up). A file that cannot be used
gives warnings naming file:line (on the "eyesim" logger) and no mesh, so the body keeps its
collider shapes; nothing here raises for a bad file."""

from __future__ import annotations

import logging
import math
import os
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path

import numpy as np

from eyesim.scene import paths

log = logging.getLogger("eyesim")

MAX_FILE_BYTES = 64 * 1024 * 1024  # larger files are refused: reading them would stall the simulator
MAX_TRIANGLES = 1_000_000
MAX_WARNINGS = 5  # per file; the rest are counted
DEFAULT_COLOR = (0.7, 0.7, 0.7)  # a face without a (known) material


@dataclass(frozen=True)
class MeshPart:
    """The triangles of one material: vertices (n, 3) float64 and triangles (m, 3) int32."""

    material: str
    color: tuple[float, float, float]  # 0..1
    vertices: np.ndarray
    triangles: np.ndarray


@dataclass(frozen=True)
class Mesh:
    path: str
    parts: tuple[MeshPart, ...]
    warnings: tuple[str, ...] = ()

    def bounds(self) -> tuple[np.ndarray, np.ndarray]:
        """Lowest and highest corner of the parts' vertices."""
        points = np.concatenate([p.vertices for p in self.parts])
        return points.min(axis=0), points.max(axis=0)


class _Warnings:
    """Warnings of one file, the first few logged in full."""

    def __init__(self, path: str):
        self.path = path
        self.texts: list[str] = []

    def add(self, line: int | None, text: str) -> None:
        where = f"{self.path}:{line}" if line is not None else self.path
        self.texts.append(f"{where}: {text}")

    def publish(self) -> tuple[str, ...]:
        for text in self.texts[:MAX_WARNINGS]:
            log.warning("%s", text)
        if len(self.texts) > MAX_WARNINGS:
            log.warning("%s: %d more warnings", self.path, len(self.texts) - MAX_WARNINGS)
        return tuple(self.texts)


def model_mesh(model: str | None) -> Mesh | None:
    """The mesh of a type's `model`: only Wavefront .obj files are read; other formats (EyeSim 6's
    .ms3d) and missing models give None, and the type is drawn as its colliders."""
    if model is None or not model.lower().endswith(".obj"):
        return None
    return read_obj(model)


def read_obj(path: str | Path) -> Mesh | None:
    """The model in `path`, or None (with warnings logged) when it has nothing usable. Cached per
    file until the file changes."""
    try:
        stat = os.stat(path)
    except OSError as error:
        log.warning("%s: cannot read the 3-D model (%s); drawn as its colliders", path, error.strerror)
        return None
    return _read_cached(str(path), stat.st_mtime_ns, stat.st_size)


@lru_cache(maxsize=64)
def _read_cached(path: str, mtime_ns: int, size: int) -> Mesh | None:
    warnings = _Warnings(path)
    mesh = _read(path, size, warnings)
    published = warnings.publish()
    if mesh is None:
        log.warning("%s: the 3-D model is not used; drawn as its colliders", path)
        return None
    return Mesh(mesh.path, mesh.parts, published)


def _read(path: str, size: int, warnings: _Warnings) -> Mesh | None:
    if size > MAX_FILE_BYTES:
        warnings.add(None, f"model file too large ({size // 1_000_000} MB, at most {MAX_FILE_BYTES // 1_000_000} MB)")
        return None
    try:
        with open(path, "rb") as file:
            text = file.read().decode("utf-8", errors="replace")
    except OSError as error:
        warnings.add(None, f"cannot read the 3-D model ({error.strerror})")
        return None
    vertices: list[tuple[float, float, float]] = []
    faces: dict[str, list[tuple[int, int, int]]] = {}  # material -> triangles (0-based, may be bad)
    colors: dict[str, tuple[float, float, float]] | None = None  # None: no library read
    material = ""
    triangles = 0
    for number, raw in enumerate(text.splitlines(), start=1):
        words = raw.split("#", 1)[0].split()
        if not words:
            continue
        keyword, args = words[0], words[1:]
        if keyword == "v":
            vertices.append(_vertex(args, number, warnings))
        elif keyword == "f":
            corners = _face(args, len(vertices), number, warnings)
            if corners is not None:
                # a convex polygon as a fan of triangles from its first corner
                faces.setdefault(material, []).extend(
                    (corners[0], corners[i], corners[i + 1]) for i in range(1, len(corners) - 1)
                )
                triangles += len(corners) - 2
                if triangles > MAX_TRIANGLES:
                    warnings.add(number, f"more than {MAX_TRIANGLES} triangles; the model is too detailed")
                    return None
        elif keyword == "usemtl":
            material = " ".join(args)
        elif keyword == "mtllib":
            for name in _library_names(raw):
                library = _read_mtl(name, path, number, warnings)
                if library is not None:
                    colors = {**(colors or {}), **library}
        # vt, vn, o, g, s, l and the rest change nothing here: parts are per material colour
    return _assemble(path, vertices, faces, colors, warnings)


def _vertex(args: list[str], line: int, warnings: _Warnings) -> tuple[float, float, float]:
    """x, y, z of a `v` line; NaN (faces using it are dropped) when it is not three numbers."""
    try:
        point = tuple(float(a) for a in args[:3])
        if len(point) == 3 and all(math.isfinite(v) for v in point):
            return point
    except ValueError:
        pass
    warnings.add(line, f"expected a vertex 'v <x> <y> <z>', found {' '.join(['v', *args])!r}")
    return (math.nan, math.nan, math.nan)


def _face(args: list[str], count: int, line: int, warnings: _Warnings) -> list[int] | None:
    """The 0-based vertex indices of an `f` line (forms v, v/vt, v//vn, v/vt/vn; negative indices
    count back from the last vertex), or None with a warning."""
    if len(args) < 3:
        warnings.add(line, f"a face needs at least 3 corners, found {len(args)}")
        return None
    corners = []
    for word in args:
        try:
            index = int(word.split("/", 1)[0])
        except ValueError:
            warnings.add(line, f"expected a face corner like 3, 3/1, 3//2 or 3/1/2, found {word!r}")
            return None
        resolved = index - 1 if index > 0 else count + index
        if index == 0 or not 0 <= resolved < count:
            warnings.add(line, f"face corner {index} names no vertex (there are {count} so far)")
            return None
        corners.append(resolved)
    return corners


def _library_names(raw: str) -> list[str]:
    """The .mtl files of an `mtllib` line: usually one name, which may contain spaces."""
    rest = raw.split("#", 1)[0].strip()[len("mtllib") :].strip()
    return [rest] if rest else []


def _read_mtl(name: str, obj_path: str, line: int, warnings: _Warnings) -> dict[str, tuple[float, float, float]] | None:
    """Material name -> diffuse colour (Kd) of an .mtl file found next to the .obj; None (with a
    warning) when the library cannot be read."""
    found = paths.resolve(name, obj_path)
    if found is None:
        warnings.add(line, f"material library {name!r} not found; its materials are grey")
        return None
    try:
        text = found.read_bytes().decode("utf-8", errors="replace")
    except OSError as error:
        warnings.add(line, f"cannot read material library {name!r} ({error.strerror}); its materials are grey")
        return None
    colors: dict[str, tuple[float, float, float]] = {}
    material = None
    for number, raw in enumerate(text.splitlines(), start=1):
        words = raw.split("#", 1)[0].split()
        if not words:
            continue
        if words[0] == "newmtl":
            material = " ".join(words[1:])
        elif words[0] == "Kd" and material is not None:
            try:
                rgb = tuple(min(max(float(v), 0.0), 1.0) for v in words[1:4])
            except ValueError:
                rgb = ()
            if len(rgb) == 3:
                colors[material] = rgb
            else:
                log.warning("%s:%d: expected 'Kd <r> <g> <b>' (0..1), found %r", found, number, raw.strip())
    return colors


def _assemble(path: str, vertices, faces, colors, warnings: _Warnings) -> Mesh | None:
    if not faces:
        warnings.add(None, "the model has no faces")
        return None
    points = np.array(vertices, dtype=np.float64).reshape(-1, 3)
    by_color: dict[tuple[float, float, float], tuple[str, list[np.ndarray]]] = {}  # materials of one colour merge
    for material, triangles in faces.items():
        indices = np.array(triangles, dtype=np.int64)
        indices = indices[np.isfinite(points[indices]).all(axis=(1, 2))]
        if not len(indices):
            continue
        if material and colors is not None and material not in colors:
            warnings.add(None, f"material {material!r} has no colour (Kd) in the material library; drawn grey")
        color = (colors or {}).get(material, DEFAULT_COLOR)
        by_color.setdefault(color, (material, []))[1].append(indices)
    parts = []
    for color, (material, pieces) in by_color.items():
        # each part keeps only the vertices it uses, renumbered
        used, renumbered = np.unique(np.concatenate(pieces), return_inverse=True)
        parts.append(MeshPart(material, color, points[used], renumbered.reshape(-1, 3).astype(np.int32)))
    if not parts:
        warnings.add(None, "no face of the model has usable vertices")
        return None
    return Mesh(path, tuple(parts))


# Placing a model in a body's frame (x forward, y left, z up).


def _euler_unity(rotation_deg) -> np.ndarray:
    """EyeSim VR's rotation (deg about X, Y, Z of its model space, applied Z, then X, then Y)."""
    rx, ry, rz = (math.radians(v) for v in rotation_deg)
    cx, sx, cy, sy, cz, sz = math.cos(rx), math.sin(rx), math.cos(ry), math.sin(ry), math.cos(rz), math.sin(rz)
    about_x = np.array([[1, 0, 0], [0, cx, -sx], [0, sx, cx]])
    about_y = np.array([[cy, 0, sy], [0, 1, 0], [-sy, 0, cy]])
    about_z = np.array([[cz, -sz, 0], [sz, cz, 0], [0, 0, 1]])
    return about_y @ about_x @ about_z


# The .obj file's x, y, z (Y up) -> EyeSim VR model space (X right, Y up, Z forward): its importer
# mirrors x. Model space -> body frame: x = Z, y = -X, z = Y (as for colliders, scene/robi.py).
_OBJ_TO_MODEL = np.diag([-1.0, 1.0, 1.0])
_MODEL_TO_BODY = np.array([[0.0, 0.0, 1.0], [-1.0, 0.0, 0.0], [0.0, 1.0, 0.0]])


def placed(
    mesh: Mesh, scale: float = 1.0, offset_mm=(0.0, 0.0, 0.0), rotation_deg=(0.0, 0.0, 0.0), shift=(0.0, 0.0, 0.0)
) -> list[MeshPart]:
    """The mesh's parts with vertices in the body frame (m): scaled, rotated and offset in model
    space as a .robi `model` line says, turned into the body frame, then moved by `shift` (m)."""
    rotation = _MODEL_TO_BODY @ _euler_unity(rotation_deg) @ _OBJ_TO_MODEL
    offset = _MODEL_TO_BODY @ (np.asarray(offset_mm, dtype=np.float64) / 1000.0) + np.asarray(shift, dtype=np.float64)
    return [MeshPart(p.material, p.color, (p.vertices * scale) @ rotation.T + offset, p.triangles) for p in mesh.parts]
