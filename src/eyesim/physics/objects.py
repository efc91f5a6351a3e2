"""Objects of the scene (cans, balls, crates, ...): their bodies, and where they are.

An object is one body whose geoms are its type's colliders (real size, object frame). The body's
frame sits at the object's centre of mass, so that what a ball or a tumbling can reports as its
position does not swing round as it rolls: an object's x, y are those of its centre of mass, and
its z is how far that centre is above where it is when the object stands on the floor (0 at rest).
It moves freely (a free joint) unless its type is `fixed`, then it is part of the static world.
An .obj model adds visual geoms only (physics/visual_mesh.py): collisions use the colliders."""

from __future__ import annotations

import math

import mujoco

from eyesim.physics.meshes import model_mesh
from eyesim.physics.units import mm, to_mm, yaw_quat
from eyesim.physics.visual_mesh import MESH_GROUP, add_model
from eyesim.physics.world import PhysicsWorld, add_collider, collider_volume, rgba
from eyesim.scene.description import ObjectPlacement, ObjectType

DEFAULT_FRICTION = 0.4  # sliding friction of an object that declares none (wood or plastic on the floor)
ROLLING_FRICTION = 0.0002  # m: balls slow down and stop instead of rolling forever


class FixedObjectError(Exception):
    """Raised when something tries to move a fixed object."""


class SceneObject:
    """An object in the simulation. `id` is its 1-based position in the scene's object list."""

    world: PhysicsWorld  # the world it is in, from bind() once the model is compiled

    def __init__(
        self, object_id: int, object_type: ObjectType, placement: ObjectPlacement, body_name: str, centre_height: float
    ):
        self.id = object_id
        self.type = object_type
        self.placement = placement
        self.body_name = body_name
        self.centre_height = centre_height  # m of the centre of mass above the object's base
        self.body = -1
        self.geoms: list[int] = []  # colliders
        self.mesh_geoms: list[int] = []  # its .obj model's, when it has one

    @property
    def fixed(self) -> bool:
        return self.type.fixed

    def bind(self, world: PhysicsWorld) -> None:
        self.world = world
        self.body = world.body_id(self.body_name)
        start = world.model.body_geomadr[self.body]
        geoms = range(start, start + world.model.body_geomnum[self.body])
        self.geoms = [g for g in geoms if world.model.geom_group[g] != MESH_GROUP]
        self.mesh_geoms = [g for g in geoms if world.model.geom_group[g] == MESH_GROUP]

    def pose(self) -> tuple[float, float, float, float]:
        """True pose: x, y of the centre of mass, z above its resting height (m), heading (rad)."""
        x, y, z, yaw = self.world.pose(self.body)
        return x, y, z - self.centre_height, yaw

    def pose_mm(self) -> tuple[float, float, float, float]:
        x, y, z, yaw = self.pose()
        return to_mm(x), to_mm(y), to_mm(z), math.degrees(yaw)

    def set_pose(self, x: float, y: float, z: float, yaw: float) -> None:
        if self.fixed:
            raise FixedObjectError(f"object {self.id} ({self.type.name}) is fixed and cannot be moved")
        self.world.set_free_pose(self.body, x, y, z + self.centre_height, yaw)


def add_object(spec: mujoco.MjSpec, object_id: int, object_type: ObjectType, placement: ObjectPlacement) -> SceneObject:
    name = f"object{object_id}"
    pose = placement.pose
    colliders = object_type.colliders
    volumes = [max(collider_volume(c), 1e-9) for c in colliders]
    centre = _centre_of_mass(object_type, volumes)  # m, object frame
    yaw = math.radians(pose.phi)
    cos, sin = math.cos(yaw), math.sin(yaw)
    body = spec.worldbody.add_body(
        name=name,
        pos=[mm(pose.x) + cos * centre[0] - sin * centre[1], mm(pose.y) + sin * centre[0] + cos * centre[1], centre[2]],
        quat=yaw_quat(yaw),
    )
    if not object_type.fixed:
        body.add_freejoint(name=f"{name}/free")
    friction = placement.friction if placement.friction is not None else DEFAULT_FRICTION
    for index, (collider, volume) in enumerate(zip(colliders, volumes)):
        sphere = collider.kind == "sphere"
        geom = add_collider(
            body,
            f"{name}/{index}",
            collider,
            rgba=rgba(object_type.color),
            mass=object_type.mass * volume / sum(volumes),
            # priority: the object's own friction decides its contacts (MuJoCo otherwise
            # takes the larger one, and the floor's grip would make crates too heavy to push)
            priority=1,
            friction=[friction, 0.005, ROLLING_FRICTION if sphere else 0.0001],
            condim=6 if sphere else 3,
        )
        geom.pos = [geom.pos[i] - centre[i] for i in range(3)]
    mesh = model_mesh(object_type.model)
    if mesh is not None:
        add_model(spec, body, name, mesh, scale=object_type.scale, shift=[-c for c in centre])
    if not object_type.fixed:
        _set_inertia(body, object_type)
    return SceneObject(object_id, object_type, placement, name, centre[2])


def _centre_of_mass(object_type: ObjectType, volumes: list[float]) -> list[float]:
    """The declared centre of mass, else the colliders' centre weighted by volume (m)."""
    if object_type.center_of_mass is not None:
        return [mm(v) for v in object_type.center_of_mass]
    total = sum(volumes)
    return [sum(mm(c.center[i]) * v for c, v in zip(object_type.colliders, volumes)) / total for i in range(3)]


def _set_inertia(body: mujoco.MjsBody, object_type: ObjectType) -> None:
    """The object's mass at the body's origin (its centre of mass), with the inertia of the
    colliders' bounding box."""
    low = [min(mm(c.center[i]) - _half_extent(c, i) for c in object_type.colliders) for i in range(3)]
    high = [max(mm(c.center[i]) + _half_extent(c, i) for c in object_type.colliders) for i in range(3)]
    sx, sy, sz = (h - lo for h, lo in zip(high, low))
    mass = object_type.mass
    body.explicitinertial = True
    body.mass = mass
    body.ipos = [0.0, 0.0, 0.0]
    body.inertia = [mass * (sy * sy + sz * sz) / 12, mass * (sx * sx + sz * sz) / 12, mass * (sx * sx + sy * sy) / 12]


def _half_extent(collider, axis: int) -> float:
    """Half the extent (m) of a collider along world axis 0, 1 or 2 of the object frame."""
    size = [mm(v) for v in collider.size]
    if collider.kind == "box":
        return size[axis] / 2
    if collider.kind == "sphere":
        return size[0]
    along = "xyz".index(collider.axis) == axis
    return size[1] / 2 if along else size[0]


def shape_of(model: mujoco.MjModel, geom: int) -> dict | None:
    """A geom as the viewer draws it: {shape, size, pos, quat} (body frame, metres), or None for
    shapes the viewer does not know."""
    geom_type = model.geom_type[geom]
    size = model.geom_size[geom]
    if geom_type == mujoco.mjtGeom.mjGEOM_BOX:
        shape, dims = "box", [2 * size[0], 2 * size[1], 2 * size[2]]
    elif geom_type == mujoco.mjtGeom.mjGEOM_SPHERE:
        shape, dims = "sphere", [size[0]]
    elif geom_type == mujoco.mjtGeom.mjGEOM_CYLINDER:
        shape, dims = "cylinder", [size[0], 2 * size[1]]
    elif geom_type == mujoco.mjtGeom.mjGEOM_CAPSULE:
        shape, dims = "capsule", [size[0], 2 * size[1] + 2 * size[0]]
    else:
        return None
    return {
        "shape": shape,
        "size": [float(v) for v in dims],
        "pos": [float(v) for v in model.geom_pos[geom]],
        "quat": [float(v) for v in model.geom_quat[geom]],
    }
