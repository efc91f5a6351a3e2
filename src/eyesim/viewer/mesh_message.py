"""The .obj model of a robot or object for the viewer: its triangles in the body's frame, by colour.

Taken from the compiled MuJoCo model (the geoms physics/visual_mesh.py added), so the viewer draws
exactly what the OpenGL cameras see, placed like the physics body (docs/viewer-channel.md)."""

from __future__ import annotations

import mujoco
import numpy as np

from eyesim.physics.visual_mesh import mesh_geoms


def mesh_url(kind: str, thing_id: int) -> str:
    return f"/scene/mesh/{kind}/{thing_id}"


def body_of(sim, kind: str, thing_id: int) -> int | None:
    """The MuJoCo body of robot or object `thing_id`, None when there is none."""
    things = sim.robots if kind == "robot" else sim.objects if kind == "object" else []
    return things[thing_id - 1].body if 1 <= thing_id <= len(things) else None


def has_mesh(sim, body: int) -> bool:
    return bool(mesh_geoms(sim.world.model, body))


def mesh_message(model: mujoco.MjModel, body: int) -> dict:
    """{"parts": [{"color": [r, g, b] 0-255, "vertices": [x, y, z, ...] m, "triangles": [i, j, k, ...]}]}"""
    parts = []
    for geom in mesh_geoms(model, body):
        mesh = model.geom_dataid[geom]
        first, count = model.mesh_vertadr[mesh], model.mesh_vertnum[mesh]
        face_first, face_count = model.mesh_faceadr[mesh], model.mesh_facenum[mesh]
        rotation = np.zeros(9)
        mujoco.mju_quat2Mat(rotation, model.geom_quat[geom])
        # MuJoCo keeps a mesh in its own (inertial) frame and the geom's pos/quat place it on the body
        vertices = model.mesh_vert[first : first + count] @ rotation.reshape(3, 3).T + model.geom_pos[geom]
        parts.append(
            {
                "color": [round(float(c) * 255) for c in model.geom_rgba[geom][:3]],
                "vertices": np.round(vertices, 6).ravel().tolist(),
                "triangles": model.mesh_face[face_first : face_first + face_count].ravel().tolist(),
            }
        )
    return {"parts": parts}
