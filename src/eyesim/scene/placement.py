"""Robots and objects placed overlapping a wall or each other: real scene files do this (a 200 mm
LabBot 20 mm from a wall, a robot and a box on the same spot). Built as placed, the physics would
push them apart violently, flinging them over walls or lifting them, and a crowd on one spot
(300 robots) fills MuJoCo's contact memory and never gets going. So, on the floor plan:

- a placement overlapping a wall moves the shortest way out of it;
- one overlapping a body placed before it (fixed objects first, then robots, then objects, each
  in file order) moves to the nearest free place on a grid of its own size round where it was
  put, at most SEARCH_RINGS sizes away; when there is none the scene is refused (a limit);

each with a warning at its placement line (docs/file-formats.md: "Placements that overlap").
Walls and bodies are looked up through a grid of the floor, so a world of thousands of walls
and bodies costs only what is near each placement."""

from __future__ import annotations

import math
from collections import defaultdict
from dataclasses import replace

from eyesim.scene.description import (
    Collider,
    Location,
    ObjectPlacement,
    ObjectType,
    Pose,
    RobotPlacement,
    RobotType,
    Wall,
)
from eyesim.scene.diagnostics import Diagnostics, quoted
from eyesim.scene.drives import drive_of
from eyesim.scene.limits import LIMIT
from eyesim.scene.parts.body import hull_colliders

CLEARANCE = 1.0  # mm left between a moved footprint and the wall
DEFAULT_OBJECT_SIZE = 100.0  # mm: the box an object without colliders gets (physics/objects.py)
ROUNDS = 8  # of pushing out: a footprint pushed off one wall can touch the next (a corner)
SEARCH_RINGS = 5  # sizes round its spot a body may be moved off others: room for 120 more
CELL = 500.0  # mm of the floor grid that finds what is near a footprint
WIDE = 64  # cells: a longer wall (or a larger body) is looked at by every query instead


def _robot_extent(robot_type: RobotType) -> tuple[float, float, float, float]:
    """A robot's floor-plan bounding box: its hull as the physics builds it, and its drive wheels."""
    x0, y0, x1, y1 = _box_extent(hull_colliders(robot_type))
    wheels = robot_type.wheels
    if wheels is not None and drive_of(robot_type).wheels_outside_hull:
        radius, reach = wheels.diameter / 2, wheels.track / 2 + wheels.diameter / 2
        x0, x1 = min(x0, robot_type.axis_offset - radius), max(x1, robot_type.axis_offset + radius)
        y0, y1 = min(y0, -reach), max(y1, reach)
    return x0, y0, x1, y1


def footprint(body_type: RobotType | ObjectType) -> tuple[float, float]:
    """The floor-plan size (mm along x, along y) a robot or object of this type takes when placed:
    what must be free for it (the scene editor shows it)."""
    if isinstance(body_type, RobotType):
        x0, y0, x1, y1 = _robot_extent(body_type)
    else:
        x0, y0, x1, y1 = _box_extent(body_type.colliders)
    return x1 - x0, y1 - y0


def chassis_extent(robot_type: RobotType) -> tuple[float, float, float, float]:
    """The chassis' floor-plan box (x0, y0, x1, y1 mm, robot frame) as the physics builds its hull,
    without the wheels: the robot editor puts its PSD presets on its edges."""
    return _box_extent(hull_colliders(robot_type))


def _box_extent(colliders: tuple[Collider, ...]) -> tuple[float, float, float, float]:
    """The floor-plan bounding box (x0, y0, x1, y1, mm, object frame) of an object's colliders."""
    if not colliders:
        half = DEFAULT_OBJECT_SIZE / 2
        return -half, -half, half, half
    xs, ys = [], []
    for c in colliders:
        if c.kind == "box":
            hx, hy = c.size[0] / 2, c.size[1] / 2
        elif c.kind == "sphere":
            hx = hy = c.size[0]
        else:  # capsule, cylinder: radius across, half length along a horizontal axis
            r, h = c.size[0], c.size[1] / 2
            hx = max(r, h) if c.axis == "x" else r
            hy = max(r, h) if c.axis == "y" else r
        xs += [c.center[0] - hx, c.center[0] + hx]
        ys += [c.center[1] - hy, c.center[1] + hy]
    return min(xs), min(ys), max(xs), max(ys)


def _corners(pose: Pose, extent: tuple[float, float, float, float]) -> list[tuple[float, float]]:
    x0, y0, x1, y1 = extent
    c, s = math.cos(math.radians(pose.phi)), math.sin(math.radians(pose.phi))
    return [(pose.x + x * c - y * s, pose.y + x * s + y * c) for x, y in ((x0, y0), (x1, y0), (x1, y1), (x0, y1))]


def _push_out(pose: Pose, extent, wall: Wall) -> tuple[float, float]:
    """The shortest shift (mm) along the wall's normal that clears the footprint of this wall, or
    (0, 0) when it does not overlap. The footprint leaves on the side its centre is on."""
    dx, dy = wall.x2 - wall.x1, wall.y2 - wall.y1
    length = math.hypot(dx, dy)
    if length == 0:
        return 0.0, 0.0
    ux, uy = dx / length, dy / length
    nx, ny = -uy, ux
    half = wall.thickness / 2
    corners = _corners(pose, extent)
    along = [(x - wall.x1) * ux + (y - wall.y1) * uy for x, y in corners]
    # Walls are built lengthened by half their thickness at both ends (physics/world.py).
    if max(along) < -half or min(along) > length + half:
        return 0.0, 0.0
    across = [(x - wall.x1) * nx + (y - wall.y1) * ny for x, y in corners]
    if min(across) >= half or max(across) <= -half:
        return 0.0, 0.0  # wholly on one side
    centre = (pose.x - wall.x1) * nx + (pose.y - wall.y1) * ny
    if centre >= 0:
        shift = half + CLEARANCE - min(across)
    else:
        shift = -(half + CLEARANCE + max(across))
    return shift * nx, shift * ny


def _box(corners) -> tuple[float, float, float, float]:
    xs, ys = [x for x, _ in corners], [y for _, y in corners]
    return min(xs), min(ys), max(xs), max(ys)


def _wall_box(wall: Wall) -> tuple[float, float, float, float]:
    reach = wall.thickness / 2  # built lengthened by this at both ends, and this thick either side
    return (
        min(wall.x1, wall.x2) - reach,
        min(wall.y1, wall.y2) - reach,
        max(wall.x1, wall.x2) + reach,
        max(wall.y1, wall.y2) + reach,
    )


class _Grid:
    """Things by the grid cells their floor-plan box covers; `near(box)` gives those that may
    overlap a box (each once, in the order they were added, so results never depend on hashing)."""

    def __init__(self):
        self.cells: dict[tuple[int, int], list[int]] = defaultdict(list)
        self.wide: list[int] = []
        self.things: list = []

    @staticmethod
    def _span(box):
        x0, y0, x1, y1 = box
        return math.floor(x0 / CELL), math.floor(y0 / CELL), math.floor(x1 / CELL), math.floor(y1 / CELL)

    def add(self, box, thing) -> None:
        index = len(self.things)
        self.things.append(thing)
        i0, j0, i1, j1 = self._span(box)
        if (i1 - i0 + 1) * (j1 - j0 + 1) > WIDE:
            self.wide.append(index)
            return
        for i in range(i0, i1 + 1):
            for j in range(j0, j1 + 1):
                self.cells[(i, j)].append(index)

    def near(self, box) -> list:
        i0, j0, i1, j1 = self._span(box)
        if (i1 - i0 + 1) * (j1 - j0 + 1) > WIDE:
            return list(self.things)
        found = set(self.wide)
        for i in range(i0, i1 + 1):
            for j in range(j0, j1 + 1):
                found.update(self.cells.get((i, j), ()))
        return [self.things[k] for k in sorted(found)]


def _walls_grid(walls) -> _Grid:
    grid = _Grid()
    for wall in walls:
        grid.add(_wall_box(wall), wall)
    return grid


def _settle(pose: Pose, extent, walls: _Grid) -> tuple[Pose, Wall | None]:
    """The pose moved clear of all walls (as far as a few rounds manage), and the first wall it
    overlapped (None: it was clear)."""
    first = None
    for _ in range(ROUNDS):
        moved = False
        for wall in walls.near(_box(_corners(pose, extent))):
            sx, sy = _push_out(pose, extent, wall)
            if sx or sy:
                first = first or wall
                pose = replace(pose, x=pose.x + sx, y=pose.y + sy)
                moved = True
        if not moved:
            break
    return pose, first


def _separation(a, b) -> tuple[float, float] | None:
    """None when two footprints (corner lists of rectangles) do not overlap (touching is not
    overlapping), else the shortest shift of `a` that takes it off `b` (separating axes)."""
    best: tuple[float, float, float] | None = None
    for corners in (a, b):
        for k in range(4):
            (x1, y1), (x2, y2) = corners[k], corners[(k + 1) % 4]
            length = math.hypot(x2 - x1, y2 - y1)
            nx, ny = (y1 - y2) / length, (x2 - x1) / length  # a side's normal
            pa = [x * nx + y * ny for x, y in a]
            pb = [x * nx + y * ny for x, y in b]
            forward, backward = max(pb) - min(pa), max(pa) - min(pb)  # a's shift along +n / -n to clear b
            if forward <= 0 or backward <= 0:
                return None  # apart along this axis
            shift = (forward, nx, ny) if forward < backward else (backward, -nx, -ny)
            if best is None or shift[0] < best[0]:
                best = shift
    assert best is not None, "each of the eight axes either separates them or sets best"
    depth, nx, ny = best
    return (depth + CLEARANCE) * nx, (depth + CLEARANCE) * ny


class _Body:
    """A placed footprint: what it is (for messages) and its corners on the floor plan."""

    def __init__(self, kind: str, placement, corners):
        self.kind, self.placement, self.corners, self.box = kind, placement, corners, _box(corners)

    def describe(self) -> str:
        line = (
            f" (line {self.placement.location.line})"
            if self.placement.location and self.placement.location.line
            else ""
        )
        return f"{self.kind} {quoted(self.placement.type_name)}{line}"


def _first_overlap(corners, bodies: _Grid) -> _Body | None:
    x0, y0, x1, y1 = box = _box(corners)
    for body in bodies.near(box):
        bx0, by0, bx1, by1 = body.box
        if bx0 < x1 and x0 < bx1 and by0 < y1 and y0 < by1 and _separation(corners, body.corners) is not None:
            return body
    return None


def _clear_of_walls(pose: Pose, extent, walls: _Grid) -> bool:
    return not any(_push_out(pose, extent, wall) != (0.0, 0.0) for wall in walls.near(_box(_corners(pose, extent))))


def _ring_offsets() -> list[tuple[int, int]]:
    """Grid steps round a spot, nearest first (ties in a fixed order)."""
    steps = [
        (i, j)
        for i in range(-SEARCH_RINGS, SEARCH_RINGS + 1)
        for j in range(-SEARCH_RINGS, SEARCH_RINGS + 1)
        if (i, j) != (0, 0)
    ]
    return sorted(steps, key=lambda s: (s[0] * s[0] + s[1] * s[1], s[1], s[0]))


_OFFSETS = _ring_offsets()


def _free_place(pose: Pose, extent, other: _Body, walls: _Grid, bodies: _Grid) -> Pose | None:
    """A pose near `pose` that overlaps no wall and no placed body: pushed the shortest way off
    `other` when that is clear, else the nearest place on a grid of the footprint's size round
    `pose`, at most SEARCH_RINGS steps away; None when there is none. Moved poses are whole mm
    (CLEARANCE keeps them clear)."""

    def free(candidate: Pose) -> bool:
        corners = _corners(candidate, extent)
        return _first_overlap(corners, bodies) is None and _clear_of_walls(candidate, extent, walls)

    shift = _separation(_corners(pose, extent), other.corners)
    assert shift is not None, "`other` is a body that `pose` overlaps"
    sx, sy = shift
    pushed = replace(pose, x=float(round(pose.x + sx)), y=float(round(pose.y + sy)))
    if free(pushed):
        return pushed
    x0, y0, x1, y1 = _box(_corners(Pose(0.0, 0.0, pose.phi), extent))
    step_x, step_y = x1 - x0 + CLEARANCE, y1 - y0 + CLEARANCE
    for i, j in _OFFSETS:
        candidate = replace(pose, x=float(round(pose.x + i * step_x)), y=float(round(pose.y + j * step_y)))
        if free(candidate):
            return candidate
    return None


def settle_placements(
    robots: list[RobotPlacement],
    objects: list[ObjectPlacement],
    robot_types: dict[str, RobotType],
    object_types: dict[str, ObjectType],
    walls: tuple[Wall, ...],
    diagnostics: Diagnostics,
    scene_file: str,
):
    """Robots and objects moved out of walls and out of each other, with a warning for each
    move; an error (code 'limit') for a body that finds no free place nearby."""
    wall_grid, bodies = _walls_grid(walls), _Grid()

    def where(placement) -> Location:
        return placement.location or Location(scene_file)

    refused = False

    def place(placement, kind: str, extent, movable: bool = True):
        nonlocal refused
        if refused:  # the scene is refused already: spare the searches
            return None
        pose, wall = _settle(placement.pose, extent, wall_grid) if movable else (placement.pose, None)
        if wall is not None:
            diagnostics.warning(
                where(placement),
                f"{kind} {quoted(placement.type_name)} at ({placement.pose.x:g}, "
                f"{placement.pose.y:g}) overlaps the wall from ({wall.x1:g}, {wall.y1:g}) to "
                f"({wall.x2:g}, {wall.y2:g}): moved to ({pose.x:.0f}, {pose.y:.0f}), clear of the "
                "walls",
                "overlap",
            )
        other = _first_overlap(_corners(pose, extent), bodies) if movable else None
        if other is not None:
            free = _free_place(pose, extent, other, wall_grid, bodies)
            if free is None:
                diagnostics.error(
                    where(placement),
                    f"{kind} {quoted(placement.type_name)} at ({pose.x:g}, "
                    f"{pose.y:g}) overlaps {other.describe()} and there is no free place within "
                    f"{SEARCH_RINGS} of its sizes: at most {len(_OFFSETS) + 1} bodies fit round one "
                    "spot, the limit for overlapping placements; spread them out",
                    LIMIT,
                )
                refused = True
                return None
            diagnostics.warning(
                where(placement),
                f"{kind} {quoted(placement.type_name)} at ({pose.x:g}, {pose.y:g}) "
                f"overlaps {other.describe()}: moved to ({free.x:.0f}, {free.y:.0f}), clear of it",
                "overlap",
            )
            pose = free
        bodies.add(_box(_corners(pose, extent)), _Body(kind, placement, _corners(pose, extent)))
        return placement if pose == placement.pose else replace(placement, pose=pose)

    def object_extent(placement):
        return _box_extent(object_types[placement.type_name].colliders)

    # Fixed objects never move: the others make room for them.
    placed_objects = {
        i: place(p, "object", object_extent(p), movable=False)
        for i, p in enumerate(objects)
        if object_types[p.type_name].fixed
    }
    settled_robots = [place(p, "robot", _robot_extent(robot_types[p.type_name])) for p in robots]
    for i, p in enumerate(objects):
        if i not in placed_objects:
            placed_objects[i] = place(p, "object", object_extent(p))
    settled_objects = [placed_objects[i] for i in range(len(objects))]
    # None marks a body refused (its error is reported); the scene is not built then.
    return [r for r in settled_robots if r is not None], [o for o in settled_objects if o is not None]


def clear_place(
    placement: RobotPlacement | ObjectPlacement,
    others,
    robot_types: dict[str, RobotType],
    object_types: dict[str, ObjectType],
    walls: tuple[Wall, ...],
) -> tuple[Pose | None, str]:
    """Where `placement` goes when it alone makes way (the scene editor's drop, an added robot):
    moved out of the walls, then to the nearest free place off the `others` (robot and object
    placements that stay where they are), as `settle_placements` moves a later placement. Returns
    the pose (whole mm when moved; None when there is no free place nearby) and what it
    overlapped ("" when it was clear)."""

    def extent(p):
        if isinstance(p, RobotPlacement):
            return _robot_extent(robot_types[p.type_name])
        return _box_extent(object_types[p.type_name].colliders)

    wall_grid, bodies = _walls_grid(walls), _Grid()
    for other in others:
        corners = _corners(other.pose, extent(other))
        bodies.add(_box(corners), _Body("robot" if isinstance(other, RobotPlacement) else "object", other, corners))
    own = extent(placement)
    pose, wall = _settle(placement.pose, own, wall_grid)
    overlapped = "" if wall is None else f"the wall from ({wall.x1:g}, {wall.y1:g}) to ({wall.x2:g}, {wall.y2:g})"
    if overlapped:
        pose = replace(pose, x=float(round(pose.x)), y=float(round(pose.y)))
    other = _first_overlap(_corners(pose, own), bodies)
    if other is not None:
        return _free_place(pose, own, other, wall_grid, bodies), other.describe()
    return pose, overlapped
