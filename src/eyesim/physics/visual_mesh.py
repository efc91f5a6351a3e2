"""A body's .obj model in the MuJoCo model: visual geoms that OpenGL cameras see and nothing collides with.

Geom groups split what each consumer uses (MuJoCo's default view shows groups 0-2):
- MESH_GROUP: the model's triangles, one geom per material colour, no contacts, no mass. The OpenGL
  camera renderer draws them; ray casts for sensors (PSD, lidar) skip them (RAY_GROUPS), because
  on the real EyeSim the sensors see the colliders too.
- COVERED_GROUP: the colliders of a body that has a model. Hidden from OpenGL (so the camera sees
  the model instead of the stand-in shapes) but still colliding and sensed; the CPU ray caster
  draws them instead of the model, which keeps it on its fast analytic path.
"""

from __future__ import annotations

import logging

import mujoco
import numpy as np

from eyesim.physics.meshes import Mesh, placed

log = logging.getLogger("eyesim")

MESH_GROUP = 2
COVERED_GROUP = 3
RAY_GROUPS = np.array([1, 1, 0, 1, 1, 1], dtype=np.uint8)  # mj_ray's geomgroup: everything but models
MIN_AREA = 1e-10  # m²: MuJoCo refuses meshes with (almost) no surface


def add_model(
    spec: mujoco.MjSpec,
    body: mujoco.MjsBody,
    name: str,
    mesh: Mesh,
    scale: float = 1.0,
    offset_mm=(0.0, 0.0, 0.0),
    rotation_deg=(0.0, 0.0, 0.0),
    shift=(0.0, 0.0, 0.0),
) -> int:
    """Adds the model's geoms to `body` (placement as in meshes.placed) and moves the body's
    existing geoms into COVERED_GROUP. Returns how many mesh geoms were added (0: the body keeps
    its colliders as its look)."""
    covered = list(body.geoms)
    added = 0
    for index, part in enumerate(placed(mesh, scale, offset_mm, rotation_deg, shift)):
        if len(part.vertices) < 4 or _area(part) < MIN_AREA:
            log.warning("%s: material %r has too few or too small faces to draw; left out", mesh.path, part.material)
            continue
        mesh_name = f"{name}/mesh{index}"
        asset = spec.add_mesh(
            name=mesh_name, uservert=part.vertices.ravel().tolist(), userface=part.triangles.ravel().tolist()
        )
        asset.inertia = mujoco.mjtMeshInertia.mjMESH_INERTIA_SHELL  # open (sheet) models are fine
        body.add_geom(
            name=mesh_name,
            type=mujoco.mjtGeom.mjGEOM_MESH,
            meshname=mesh_name,
            contype=0,
            conaffinity=0,
            group=MESH_GROUP,
            mass=0.0,
            rgba=[*part.color, 1.0],
        )
        added += 1
    if added:
        for geom in covered:
            geom.group = COVERED_GROUP
    return added


def mesh_geoms(model: mujoco.MjModel, body: int) -> list[int]:
    """The model's geoms on a body."""
    start = model.body_geomadr[body]
    return [g for g in range(start, start + model.body_geomnum[body]) if model.geom_group[g] == MESH_GROUP]


def _area(part) -> float:
    a, b, c = (part.vertices[part.triangles[:, i]] for i in range(3))
    return float(np.linalg.norm(np.cross(b - a, c - a), axis=1).sum() / 2)
