"""Camera images without OpenGL: a ray per pixel, intersected with the scene's shapes in numpy and
shaded like the OpenGL renderer.

Each geom is tested only against the rays of the pixels it can cover (the screen rectangle of its
bounding box, or for a fisheye the cone around it), so the cost follows what is in view, not the
number of geoms times the number of pixels. A surface is seen from outside only, as OpenGL culls
back faces. Geom types without a shape here (meshes, height fields) fall back to MuJoCo's ray
cast for every pixel. The image is drawn in bands of rows, other threads running between them. Colours come from each geom's rgba (or its material's); textured planes
(a floor texture) are sampled where the ray meets them; the lights are the ones in render.py."""

from __future__ import annotations

import time
from typing import NamedTuple, cast

import mujoco
import numpy as np

from eyesim.physics import render
from eyesim.physics.visual_mesh import COVERED_GROUP, MESH_GROUP

DEFAULT_GEOM_RGBA = (0.5, 0.5, 0.5, 1.0)  # MuJoCo's: a geom with this colour shows its material's
HIDDEN_GROUPS = 3  # geom groups from here on are hidden in MuJoCo's default view, so in OpenGL's too
# What this renderer draws: OpenGL's groups, but a body's colliders instead of its .obj model, which
# keeps every geom an analytic shape (physics/visual_mesh.py)
SHOWN_GROUPS = np.array(
    [(g < HIDDEN_GROUPS and g != MESH_GROUP) or g == COVERED_GROUP for g in range(6)], dtype=np.uint8
)
EPSILON = 1e-9
G = mujoco.mjtGeom
CORNERS = np.array([[x, y, z] for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)], dtype=np.float64)
SLICE_PIXELS = 1 << 17  # pixels drawn in one go (whole rows): each numpy step over them takes ~2 ms


class Rect(NamedTuple):
    """Rows r0..r1 and columns c0..c1 (ends excluded) of the image where a geom can show."""

    r0: int
    r1: int
    c0: int
    c1: int


class Cone(NamedTuple):
    """A fisheye's rays that may meet a geom: those within the cone around `axis` (unit, world)."""

    axis: np.ndarray
    cosine: float


class Band(NamedTuple):
    """Rows top..bottom (bottom excluded) of an image `width` pixels wide."""

    top: int
    bottom: int
    width: int


NOWHERE = Rect(0, 0, 0, 0)


class RayCastRenderer:
    """Draws an image in bands of whole rows of at most `slice_pixels` pixels, and lets other
    threads run between them: a numpy step holds the interpreter's lock for as long as it works,
    and over a whole 5-megapixel image one step took up to 66 ms, during which the simulation
    thread could serve no program. Every pixel is computed on its own, so the image is the same
    in any bands."""

    name = "raycast"

    def __init__(self, slice_pixels: int = SLICE_PIXELS):
        self.slice_pixels = slice_pixels

    def render(self, world, view: render.View, data=None) -> np.ndarray:
        """The view's image, (height, width, 3) uint8, top row first; `data`: the physics state to
        draw (a copy of the world's), else the world's own."""
        model, data = world.model, world.data if data is None else data
        axes = render.camera_ray_axes(view.width, view.height, view.fov, view.fisheye)
        forward = np.asarray(view.forward, dtype=np.float64)
        basis = np.stack([view.right, np.asarray(view.up, dtype=np.float64), forward])
        origin = np.asarray(view.position, dtype=np.float64)
        geoms = _visible_geoms(model, view.own_body)
        analytic = bool(np.isin(model.geom_type[geoms], SHAPES).all())
        reaches = [_reach(model, data, geom, origin, view, basis) for geom in geoms] if analytic else []
        geom_colours = _geom_colours(model)
        image = np.empty((view.width * view.height, 3), dtype=np.uint8)
        rows = max(1, self.slice_pixels // view.width)
        for top in range(0, view.height, rows):
            bottom = min(view.height, top + rows)
            pixels = slice(top * view.width, bottom * view.width)
            # The band's rays in the world, one array per axis (camera frame: x right, y up, z
            # forward); an array each, though sum() is typed as 0 for no terms.
            columns = [
                cast(np.ndarray, sum(axes[k][pixels] * float(basis[k, axis]) for k in range(3))) for axis in range(3)
            ]
            if analytic:
                band = Band(top, bottom, view.width)
                geom_ids, distances, normals = _cast(model, data, geoms, reaches, origin, columns, band)
            else:
                geom_ids, distances, normals = _mujoco_cast(
                    model, data, origin, np.stack(columns, axis=1), view.own_body
                )
            hit = np.flatnonzero((geom_ids >= 0) & axes[3][pixels])
            hit_geoms = geom_ids[hit]
            colours = render.shade(geom_colours[hit_geoms], normals[hit], forward)
            if model.ntex:  # as in OpenGL, the texture modulates the lit colour
                points = np.stack([origin[axis] + columns[axis][hit] * distances[hit] for axis in range(3)], axis=1)
                _apply_textures(model, data, hit_geoms, points, colours)
            drawn = image[pixels]
            drawn[:] = render.BACKGROUND
            drawn[hit] = np.rint(colours * 255.0)
            self.between_slices()
        return image.reshape(view.height, view.width, 3)

    def between_slices(self) -> None:
        """Give the interpreter's lock to a thread that waits for it (the simulation's)."""
        time.sleep(0)


def _cast(model, data, geoms, reaches, origin, columns, band: Band):
    """Nearest geom, distance and world normal of every ray of the band (geom -1 where it hits
    nothing). Distances first, geom by geom over the pixels each can cover; normals only where it
    won."""
    n = len(columns[0])
    nearest = np.full(n, -1, dtype=np.int32)
    distance = np.full(n, np.inf, dtype=np.float32)
    for geom, reach in zip(geoms, reaches):
        pixels = _pixels_in(reach, columns, band)
        if pixels is not None and not len(pixels):
            continue
        o, d = _local_rays(data, geom, origin, columns, pixels)
        t = SHAPE_DISTANCE[int(model.geom_type[geom])](o, d, model.geom_size[geom])
        if pixels is None:  # every pixel
            nearer = np.flatnonzero(t < distance)
            nearest[nearer] = geom
            distance[nearer] = t[nearer]
        else:
            nearer = t < distance[pixels]
            nearest[pixels[nearer]] = geom
            distance[pixels[nearer]] = t[nearer]
    normals = np.zeros((n, 3))
    for geom in np.unique(nearest[nearest >= 0]):
        pixels = np.flatnonzero(nearest == geom)
        o, d = _local_rays(data, geom, origin, columns, pixels)
        point = [o[axis] + d[axis] * distance[pixels] for axis in range(3)]
        normal = np.stack(SHAPE_NORMAL[int(model.geom_type[geom])](point, model.geom_size[geom]), axis=1)
        normals[pixels] = render.times(normal, data.geom_xmat[geom].reshape(3, 3).T)  # geom frame -> world
    return nearest, distance, normals


def _visible_geoms(model, own_body: int) -> np.ndarray:
    """Geoms a camera shows: not transparent, in a shown group, not the camera's own chassis."""
    visible = (
        (model.geom_rgba[:, 3] > 0)
        & np.isin(model.geom_group, np.flatnonzero(SHOWN_GROUPS))
        & (model.geom_bodyid != own_body)
    )
    return np.flatnonzero(visible)


def _half_extent(model, geom: int) -> np.ndarray:
    """Half sizes of the geom's box in its own frame."""
    size, kind = model.geom_size[geom], model.geom_type[geom]
    if kind == G.mjGEOM_SPHERE:
        return np.full(3, size[0])
    if kind == G.mjGEOM_CAPSULE:
        return np.array([size[0], size[0], size[1] + size[0]])
    if kind == G.mjGEOM_CYLINDER:
        return np.array([size[0], size[0], size[1]])
    return size.copy()  # box, ellipsoid


def _reach(model, data, geom: int, origin: np.ndarray, view: render.View, basis: np.ndarray) -> Rect | Cone | None:
    """Where on the image the geom can show: a screen rectangle (NOWHERE: not at all), for a
    fisheye the cone from the camera around it, or None for anywhere. `basis`: the camera's
    right, up and forward vectors as rows."""
    width, height = view.width, view.height
    if model.geom_type[geom] == G.mjGEOM_PLANE:
        return None
    rotation = data.geom_xmat[geom].reshape(3, 3)
    centre = data.geom_xpos[geom]
    half = _half_extent(model, geom)
    if view.fisheye:  # the cone from the camera around the geom's bounding sphere
        offset = centre - origin
        distance, radius = np.linalg.norm(offset), np.linalg.norm(half)
        if distance <= radius:
            return None
        return Cone(offset / distance, np.sqrt(1.0 - (radius / distance) ** 2))
    corners = centre + render.times(CORNERS * half, rotation.T)
    local = render.times(corners - origin, basis.T)
    if (local[:, 2] <= render.NEAR).all():
        return NOWHERE  # behind the camera
    if (local[:, 2] <= render.NEAR).any():
        return None  # reaches behind the camera: any pixel may see it
    focal = (width / 2) / np.tan(np.radians(view.fov) / 2)
    xs = (width - 1) / 2 + focal * local[:, 0] / local[:, 2]
    ys = (height - 1) / 2 - focal * local[:, 1] / local[:, 2]
    c0, c1 = max(0, int(np.floor(xs.min())) - 1), min(width, int(np.ceil(xs.max())) + 2)
    r0, r1 = max(0, int(np.floor(ys.min())) - 1), min(height, int(np.ceil(ys.max())) + 2)
    return Rect(r0, r1, c0, c1)


def _pixels_in(reach: Rect | Cone | None, columns: list[np.ndarray], band: Band):
    """Indices, within the band, of the pixels whose rays may meet a geom that reaches so far;
    None for every pixel. `columns`: the band's rays."""
    if reach is None:
        return None
    if isinstance(reach, Cone):
        axis = reach.axis
        return np.flatnonzero(columns[0] * axis[0] + columns[1] * axis[1] + columns[2] * axis[2] >= reach.cosine - 1e-9)
    r0, r1 = max(reach.r0, band.top), min(reach.r1, band.bottom)
    if reach.c0 >= reach.c1 or r0 >= r1:
        return np.zeros(0, dtype=np.intp)
    return (
        np.arange(r0 - band.top, r1 - band.top)[:, None] * band.width + np.arange(reach.c0, reach.c1)[None, :]
    ).ravel()


def _local_rays(data, geom: int, origin: np.ndarray, columns: list[np.ndarray], pixels):
    """The rays' origin (3 floats) and directions (3 arrays, one per axis) in the geom's frame,
    for the given pixels (None: all)."""
    rotation = data.geom_xmat[geom].reshape(3, 3)
    o = np.array((origin - data.geom_xpos[geom]) @ rotation, dtype=np.float32)
    world = columns if pixels is None else [c[pixels] for c in columns]
    if np.array_equal(rotation, np.eye(3)):
        return o, world
    r = rotation.tolist()  # Python floats keep the arrays' single precision
    d = [world[0] * r[0][axis] + world[1] * r[1][axis] + world[2] * r[2][axis] for axis in range(3)]
    return o, d


# Ray-shape distances, in the shape's frame, with the directions as one array per axis: how far
# along each ray it enters the shape, inf where it misses or starts inside (seen from outside only).


def _plane_distance(o, d, size):
    """MuJoCo's plane: z = 0 seen from above, within +-size[0] x +-size[1] unless those are 0."""
    if o[2] <= 0:
        return np.full(len(d[2]), np.inf)
    with np.errstate(divide="ignore", invalid="ignore"):
        t = -o[2] / d[2]
    ok = d[2] < 0
    if size[0] > 0:
        ok &= (np.abs(o[0] + d[0] * t) <= size[0]) & (np.abs(o[1] + d[1] * t) <= size[1])
    return np.where(ok, t, np.inf)


def _sphere_distance(o, d, radius, centre_z=0.0):
    oz = o[2] - centre_z
    c = o[0] * o[0] + o[1] * o[1] + oz * oz - radius * radius
    if c <= 0:
        return np.full(len(d[0]), np.inf)
    a = d[0] * d[0] + d[1] * d[1] + d[2] * d[2]
    b = o[0] * d[0] + o[1] * d[1] + oz * d[2]
    disc = b * b - a * c
    with np.errstate(invalid="ignore"):
        t = (-b - np.sqrt(disc)) / a
    return np.where((disc >= 0) & (t > EPSILON), t, np.inf)


def _ellipsoid_distance(o, d, size):
    return _sphere_distance(o / size, [d[axis] / size[axis] for axis in range(3)], 1.0)  # the same t


def _box_distance(o, d, half):
    enter = np.full(len(d[0]), -np.inf)
    leave = np.full(len(d[0]), np.inf)
    with np.errstate(divide="ignore", invalid="ignore"):
        for axis in range(3):
            if abs(o[axis]) > half[axis]:  # outside this slab: rays parallel to it miss
                parallel = d[axis] == 0
                enter[parallel] = np.inf
            inverse = 1.0 / d[axis]
            low, high = (-half[axis] - o[axis]) * inverse, (half[axis] - o[axis]) * inverse
            np.maximum(enter, np.fmin(low, high), out=enter)
            np.minimum(leave, np.fmax(low, high), out=leave)
    return np.where((enter <= leave) & (enter > EPSILON), enter, np.inf)


def _cylinder_side_distance(o, d, radius, half_length):
    """Where rays enter the side of a cylinder around the z axis, between +-half_length."""
    c = o[0] * o[0] + o[1] * o[1] - radius * radius
    if c <= 0:
        return np.full(len(d[0]), np.inf)
    a = d[0] * d[0] + d[1] * d[1]
    b = o[0] * d[0] + o[1] * d[1]
    disc = b * b - a * c
    with np.errstate(divide="ignore", invalid="ignore"):
        t = (-b - np.sqrt(disc)) / a
    return np.where((a > EPSILON) & (disc >= 0) & (t > EPSILON) & (np.abs(o[2] + t * d[2]) <= half_length), t, np.inf)


def _cylinder_distance(o, d, size):
    radius, half_length = size[0], size[1]
    side = _cylinder_side_distance(o, d, radius, half_length)
    if abs(o[2]) <= half_length:
        return side  # beside the cylinder: no cap faces the camera
    cap_z = np.copysign(half_length, o[2])  # the cap on the camera's side
    with np.errstate(divide="ignore", invalid="ignore"):
        cap = (cap_z - o[2]) / d[2]
    x, y = o[0] + d[0] * cap, o[1] + d[1] * cap
    cap = np.where((cap > EPSILON) & (x * x + y * y <= radius * radius), cap, np.inf)
    return np.minimum(side, cap)


def _capsule_distance(o, d, size):
    radius, half_length = size[0], size[1]
    return np.minimum(
        _cylinder_side_distance(o, d, radius, half_length),
        np.minimum(_sphere_distance(o, d, radius, half_length), _sphere_distance(o, d, radius, -half_length)),
    )


# Outward normals of the shapes at points on them (one array per axis, in the shape's frame).


def _plane_normal(p, size):
    return np.zeros_like(p[0]), np.zeros_like(p[0]), np.ones_like(p[0])


def _sphere_normal(p, size):
    return p[0] / size[0], p[1] / size[0], p[2] / size[0]


def _ellipsoid_normal(p, size):
    n = [p[axis] / size[axis] ** 2 for axis in range(3)]
    length = np.maximum(np.sqrt(n[0] ** 2 + n[1] ** 2 + n[2] ** 2), EPSILON)
    return n[0] / length, n[1] / length, n[2] / length


def _box_normal(p, size):
    """The face the point lies on: the axis where it is nearest the box's half size."""
    outside = np.stack([np.abs(p[axis]) / size[axis] for axis in range(3)])
    face = outside.argmax(axis=0)
    return tuple(np.where(face == axis, np.sign(p[axis]), 0.0) for axis in range(3))


def _cylinder_normal(p, size):
    radius, half_length = size[0], size[1]
    on_cap = np.abs(np.abs(p[2]) - half_length) < 1e-7 * max(1.0, half_length) + 1e-9
    on_cap &= p[0] ** 2 + p[1] ** 2 < radius * radius * (1 - 1e-6)
    return (
        np.where(on_cap, 0.0, p[0] / radius),
        np.where(on_cap, 0.0, p[1] / radius),
        np.where(on_cap, np.sign(p[2]), 0.0),
    )


def _capsule_normal(p, size):
    radius, half_length = size[0], size[1]
    axis_z = np.clip(p[2], -half_length, half_length)  # the nearest point of the capsule's axis
    return p[0] / radius, p[1] / radius, (p[2] - axis_z) / radius


# keyed by the geom type's number, as model.geom_type holds it
SHAPE_DISTANCE = {
    int(G.mjGEOM_PLANE): _plane_distance,
    int(G.mjGEOM_SPHERE): lambda o, d, s: _sphere_distance(o, d, s[0]),
    int(G.mjGEOM_ELLIPSOID): _ellipsoid_distance,
    int(G.mjGEOM_BOX): _box_distance,
    int(G.mjGEOM_CYLINDER): _cylinder_distance,
    int(G.mjGEOM_CAPSULE): _capsule_distance,
}
SHAPE_NORMAL = {
    int(G.mjGEOM_PLANE): _plane_normal,
    int(G.mjGEOM_SPHERE): _sphere_normal,
    int(G.mjGEOM_ELLIPSOID): _ellipsoid_normal,
    int(G.mjGEOM_BOX): _box_normal,
    int(G.mjGEOM_CYLINDER): _cylinder_normal,
    int(G.mjGEOM_CAPSULE): _capsule_normal,
}
SHAPES = tuple(SHAPE_DISTANCE)


def _mujoco_cast(model, data, origin, directions, own_body):
    """MuJoCo's own ray cast of every pixel (for geoms without a shape here)."""
    n = len(directions)
    geoms = np.empty(n, dtype=np.int32)
    distances = np.empty(n)
    normals = np.empty((n, 3))
    mujoco.mj_multiRay(
        model,
        data,
        origin,
        np.ascontiguousarray(directions).reshape(-1),
        SHOWN_GROUPS,
        1,
        own_body,
        geoms,
        distances,
        normals.reshape(-1),
        n,
        render.FAR,
    )
    return geoms, distances, normals


def _geom_colours(model) -> np.ndarray:
    """RGB 0..1 of every geom: its own rgba, or its material's when the geom keeps MuJoCo's default."""
    colours = model.geom_rgba[:, :3].astype(np.float64)
    material = model.geom_matid
    uses_material = (material >= 0) & np.all(model.geom_rgba == DEFAULT_GEOM_RGBA, axis=1)
    colours[uses_material] = model.mat_rgba[material[uses_material], :3]
    return colours


def _apply_textures(model, data, geoms: np.ndarray, points: np.ndarray, colours: np.ndarray) -> None:
    """Multiply the lit colours of hits on textured planes (a floor texture) by the texture there.

    MuJoCo stretches a plane's 2D texture `texrepeat` times over the whole plane, the image's
    first row along the plane's +y edge."""
    role = mujoco.mjtTextureRole.mjTEXROLE_RGB
    for geom in np.unique(geoms):
        material = model.geom_matid[geom]
        if model.geom_type[geom] != G.mjGEOM_PLANE or material < 0:
            continue
        texture = model.mat_texid[material, role]
        if texture < 0 or model.tex_type[texture] != mujoco.mjtTexture.mjTEXTURE_2D:
            continue
        width, height, channels = model.tex_width[texture], model.tex_height[texture], model.tex_nchannel[texture]
        start = model.tex_adr[texture]
        pixels = model.tex_data[start : start + width * height * channels].reshape(height, width, channels)
        mine = np.flatnonzero(geoms == geom)
        local = render.times(points[mine] - data.geom_xpos[geom], data.geom_xmat[geom].reshape(3, 3))
        size_x, size_y = model.geom_size[geom, :2]
        repeat_x, repeat_y = model.mat_texrepeat[material]
        u = ((local[:, 0] + size_x) / (2 * size_x) * repeat_x) % 1.0
        v = ((size_y - local[:, 1]) / (2 * size_y) * repeat_y) % 1.0
        columns = np.minimum((u * width).astype(np.intp), width - 1)
        rows = np.minimum((v * height).astype(np.intp), height - 1)
        colours[mine] *= pixels[rows, columns, :3] / 255.0
