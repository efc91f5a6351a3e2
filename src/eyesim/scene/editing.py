"""The scene the viewer's editor works on, the edit operations on it, and saving it.

A `Draft` is a scene description in the shape of a .sim file (eyesim/scene/sim.py): a world,
the robot and object definition files, robots and objects placed at explicit poses, markers and
settings, every file as an absolute path. Each edit makes a new Draft; `Draft.scene()` turns it
into a Scene through the loader, exactly as a file would be (eyesim.scene.loader.build_scene),
so an edit the loader refuses is refused with its reasons and the scene stays as it was.
Saving writes the same description as .sim (+ .wld when the world was edited) or as JSON."""

from __future__ import annotations

import dataclasses
import os
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

from eyesim.scene import builtins
from eyesim.scene.description import Marker, Pose, Scene, Settings, Wall, World
from eyesim.scene.json_format import dumps, to_json
from eyesim.scene.description import ObjectPlacement, RobotPlacement
from eyesim.scene.loader import build_scene, load_object_type, load_robot_type
from eyesim.scene.placement import clear_place
from eyesim.scene.sim import Placement, Reference, SimDocument, write_sim
from eyesim.scene.wld import write_wld

DUPLICATE_OFFSET = 150.0  # mm a copy is placed beside its original
Placed = RobotPlacement | ObjectPlacement  # a robot or object where the scene puts it


class EditError(ValueError):
    """An edit that cannot be made, with the reason (the scene stays as it was)."""


@dataclass(frozen=True)
class RobotItem:
    type_name: str
    pose: Pose
    program: str | None = None  # absolute path (or as the scene wrote it when it was not found)


@dataclass(frozen=True)
class ObjectItem:
    type_name: str
    pose: Pose
    model: str | None = None  # an EyeSim 6 obstacle from a 3-D model file (absolute path)
    friction: float | None = None


@dataclass(frozen=True)
class Draft:
    """A scene being edited. `world_file` is the world file the scene names while its world is
    unchanged (its walls, balls and markers stay in it); once the world is edited it is None and
    the world's things are the draft's own."""

    file: Path  # where the scene is (or will be saved); references resolve from here
    world: World
    world_file: Path | None = None
    settings: Settings = Settings()
    robot_files: tuple[str, ...] = ()
    object_files: tuple[str, ...] = ()
    robots: tuple[RobotItem, ...] = ()
    objects: tuple[ObjectItem, ...] = ()  # after the world's own objects (while world_file is set)
    markers: tuple[Marker, ...] = ()  # after the world's own markers

    # -- to and from the scene description --------------------------------------------------
    @classmethod
    def of_scene(cls, scene: Scene) -> "Draft":
        """The draft of a loaded scene (a .sim, or a bare world file opened as a scene)."""
        file = Path(scene.source)
        world_source = Path(scene.world.source)
        world_file = world_source if world_source.is_file() and world_source.suffix.lower() != ".sim" else None
        world = scene.world
        robot_files = tuple(
            t.source
            for name, t in scene.robot_types.items()
            if not _is_builtin(builtins.robot_path(name), t.source) and Path(t.source).is_file()
        )
        object_files, models = [], {}
        for name, t in scene.object_types.items():
            if _is_builtin(builtins.object_path(name), t.source):
                continue
            if Path(t.source).suffix.lower() in (".esobj", ".json") and Path(t.source).is_file():
                object_files.append(t.source)
            else:  # an obstacle named by its model file
                models[name] = t.model or t.source
        robots = tuple(RobotItem(r.type_name, r.pose, r.program) for r in scene.robots)
        own_objects = scene.objects[len(world.objects) :]
        objects = tuple(ObjectItem(o.type_name, o.pose, models.get(o.type_name), o.friction) for o in own_objects)
        draft = cls(
            file,
            world,
            world_file,
            scene.settings,
            robot_files,
            tuple(object_files),
            robots,
            objects,
            scene.markers[len(world.markers) :],
        )
        if world_file is None:
            draft = draft.with_own_world()
        return draft

    def document(self) -> SimDocument:
        """The .sim document of this draft, every file by absolute path."""
        placements = [
            Placement(type_name=r.type_name, x=r.pose.x, y=r.pose.y, phi=r.pose.phi, program=r.program)
            for r in self.robots
        ]
        for o in self.objects:
            if o.model is not None:
                placements.append(
                    Placement(model=o.model, x=o.pose.x, y=o.pose.y, phi=o.pose.phi, friction=o.friction or 0.0)
                )
            else:
                placements.append(Placement(type_name=o.type_name, x=o.pose.x, y=o.pose.y, phi=o.pose.phi))
        return SimDocument(
            str(self.file),
            Reference(str(self.world_file)) if self.world_file else None,
            self.settings,
            tuple(Reference(p) for p in self.robot_files),
            tuple(Reference(p) for p in self.object_files),
            tuple(placements),
            self.markers,
        )

    def scene(self) -> Scene:
        """The Scene this draft describes, through the loader; SceneError when it refuses it."""
        return build_scene(self.document(), self.file, self.world)

    def with_own_world(self) -> "Draft":
        """The world made the draft's own (about to be edited): its balls and markers become
        the scene's, and it is saved with the scene instead of being named."""
        world = self.world
        if self.world_file is None and not (world.objects or world.markers or world.start_positions):
            return self
        balls = tuple(ObjectItem(o.type_name, o.pose, None, o.friction) for o in world.objects)
        own = dataclasses.replace(
            world, source=str(self.file), objects=(), markers=(), start_positions=(), start_pose=None
        )
        return dataclasses.replace(
            self, world=own, world_file=None, objects=balls + self.objects, markers=world.markers + self.markers
        )

    # -- what the browser shows --------------------------------------------------------------
    def items(self) -> dict:
        """The editable things, numbered as edits name them: objects and markers counting the
        world's own first (as the simulator numbers them)."""
        world_objects = [
            {"type": o.type_name, "x": o.pose.x, "y": o.pose.y, "phi": o.pose.phi, "world": True}
            for o in self.world.objects
        ]
        return {
            "robots": [
                {"type": r.type_name, "x": r.pose.x, "y": r.pose.y, "phi": r.pose.phi, "program": r.program}
                for r in self.robots
            ],
            "objects": world_objects
            + [
                {"type": o.type_name, "x": o.pose.x, "y": o.pose.y, "phi": o.pose.phi, "world": False}
                for o in self.objects
            ],
            "markers": [{"x": m.x, "y": m.y, "color": list(m.color)} for m in (*self.world.markers, *self.markers)],
            "walls": [
                {
                    "x1": w.x1,
                    "y1": w.y1,
                    "x2": w.x2,
                    "y2": w.y2,
                    "thickness": w.thickness,
                    "height": w.height,
                    "color": list(w.color),
                }
                for w in self.world.walls
            ],
            "floor": {"width": self.world.floor_width, "height": self.world.floor_height},
        }


def _is_builtin(builtin: Path | None, source: str) -> bool:
    return builtin is not None and Path(source).resolve() == builtin.resolve()


# -- edit operations --------------------------------------------------------------------------
def apply(draft: Draft, op: dict, locate) -> Draft:
    """The draft after the edit `op`, a JSON object from the browser that its definition in
    interface/viewer.schema.json (`SceneEdit`) has checked: its fields' types and ranges; what
    depends on the scene (is there a robot 3) is checked here. `locate(place)` turns a
    {"root", "path"} object into a confined absolute Path."""
    return OPERATIONS[op["op"]](draft, op, locate)


def _number(op: dict, key: str, default: float | None = None) -> float:
    """A field the schema checked when present; which ones a move needs depends on what moves."""
    value = op.get(key, default)
    if value is None:
        raise EditError(f"{op['op']}: field {key!r} is missing")
    return float(value)


def _pose(op: dict) -> Pose:
    phi = _number(op, "phi", 0.0)
    return Pose(_number(op, "x"), _number(op, "y"), (phi + 180.0) % 360.0 - 180.0)


def _index(op: dict, count: int, what: str) -> int:
    index = op["index"]
    if index >= count:
        raise EditError(f"{op['op']}: no {what} number {index} (there are {count})")
    return index


def _type_name(op: dict, locate, files: tuple[str, ...], load, builtin_path, builtin_names, suffix: str):
    """The type an add-robot/add-object names: a file under the roots (listed in `files` once) or a
    built-in; returns (type name, files)."""
    if isinstance(op.get("file"), dict):
        path = locate(op["file"])
        name = _definition(load, path).name
        return name, files if str(path) in files else files + (str(path),)
    if isinstance(op.get("type"), str) and builtin_path(op["type"]) is not None:
        return builtin_path(op["type"]).stem, files
    raise EditError(
        f"{op.get('op')}: unknown {op.get('op', '').removeprefix('add-')} type {op.get('type')!r}: "
        f"expected one of {', '.join(builtin_names())} or {suffix} file"
    )


def add_robot(draft: Draft, op: dict, locate) -> Draft:
    name, robot_files = _type_name(
        op, locate, draft.robot_files, load_robot_type, builtins.robot_path, builtins.robot_names, "a .robi"
    )
    program = str(locate(op["program"])) if isinstance(op.get("program"), dict) else None
    return dataclasses.replace(
        draft, robot_files=robot_files, robots=draft.robots + (RobotItem(name, _pose(op), program),)
    )


def add_object(draft: Draft, op: dict, locate) -> Draft:
    name, object_files = _type_name(
        op, locate, draft.object_files, load_object_type, builtins.object_path, builtins.object_names, "an .esObj"
    )
    return dataclasses.replace(draft, object_files=object_files, objects=draft.objects + (ObjectItem(name, _pose(op)),))


def add_marker(draft: Draft, op: dict, locate) -> Draft:
    color = op.get("color", [255, 0, 0])
    marker = Marker(_number(op, "x"), _number(op, "y"), tuple(color) if len(color) == 4 else (*color, 255))
    return dataclasses.replace(draft, markers=draft.markers + (marker,))


def add_wall(draft: Draft, op: dict, locate) -> Draft:
    wall = Wall(_number(op, "x1"), _number(op, "y1"), _number(op, "x2"), _number(op, "y2"))
    if (wall.x1, wall.y1) == (wall.x2, wall.y2):
        raise EditError("add-wall: the wall has no length (both ends at the same point)")
    draft = draft.with_own_world()
    return dataclasses.replace(draft, world=dataclasses.replace(draft.world, walls=draft.world.walls + (wall,)))


def move(draft: Draft, op: dict, locate) -> Draft:
    """x, y (mm) and phi (deg) of a robot, object or marker; x1 y1 x2 y2 of a wall."""
    kind = op["kind"]
    if kind == "robot":
        index = _index(op, len(draft.robots), "robot")
        robots = list(draft.robots)
        robots[index] = dataclasses.replace(robots[index], pose=_pose(op))
        return dataclasses.replace(draft, robots=tuple(robots))
    draft = _owning(draft, kind, op)
    if kind == "object":
        index = _index(op, len(draft.objects), "object")
        objects = list(draft.objects)
        objects[index] = dataclasses.replace(objects[index], pose=_pose(op))
        return dataclasses.replace(draft, objects=tuple(objects))
    if kind == "marker":
        index = _index(op, len(draft.markers), "marker")
        markers = list(draft.markers)
        markers[index] = dataclasses.replace(markers[index], x=_number(op, "x"), y=_number(op, "y"))
        return dataclasses.replace(draft, markers=tuple(markers))
    index = _index(op, len(draft.world.walls), "wall")
    walls = list(draft.world.walls)
    walls[index] = dataclasses.replace(
        walls[index], x1=_number(op, "x1"), y1=_number(op, "y1"), x2=_number(op, "x2"), y2=_number(op, "y2")
    )
    return dataclasses.replace(draft, world=dataclasses.replace(draft.world, walls=tuple(walls)))


def delete(draft: Draft, op: dict, locate) -> Draft:
    kind = op["kind"]
    if kind == "robot":
        index = _index(op, len(draft.robots), "robot")
        return dataclasses.replace(draft, robots=draft.robots[:index] + draft.robots[index + 1 :])
    draft = _owning(draft, kind, op)
    if kind == "object":
        index = _index(op, len(draft.objects), "object")
        return dataclasses.replace(draft, objects=draft.objects[:index] + draft.objects[index + 1 :])
    if kind == "marker":
        index = _index(op, len(draft.markers), "marker")
        return dataclasses.replace(draft, markers=draft.markers[:index] + draft.markers[index + 1 :])
    index = _index(op, len(draft.world.walls), "wall")
    walls = draft.world.walls[:index] + draft.world.walls[index + 1 :]
    return dataclasses.replace(draft, world=dataclasses.replace(draft.world, walls=walls))


def duplicate(draft: Draft, op: dict, locate) -> Draft:
    """A copy beside the original (robots, objects and markers), appended to its list."""
    kind = op["kind"]
    if kind == "robot":
        original = draft.robots[_index(op, len(draft.robots), "robot")]
        pose = Pose(original.pose.x + DUPLICATE_OFFSET, original.pose.y, original.pose.phi)
        return dataclasses.replace(draft, robots=draft.robots + (dataclasses.replace(original, pose=pose),))
    draft = _owning(draft, kind, op)
    if kind == "object":
        obj = draft.objects[_index(op, len(draft.objects), "object")]
        pose = Pose(obj.pose.x + DUPLICATE_OFFSET, obj.pose.y, obj.pose.phi)
        return dataclasses.replace(draft, objects=draft.objects + (dataclasses.replace(obj, pose=pose),))
    if kind == "marker":
        marker = draft.markers[_index(op, len(draft.markers), "marker")]
        copy = dataclasses.replace(marker, x=marker.x + DUPLICATE_OFFSET)
        return dataclasses.replace(draft, markers=draft.markers + (copy,))
    wall = draft.world.walls[_index(op, len(draft.world.walls), "wall")]
    moved = dataclasses.replace(wall, y1=wall.y1 + DUPLICATE_OFFSET, y2=wall.y2 + DUPLICATE_OFFSET)
    return dataclasses.replace(draft, world=dataclasses.replace(draft.world, walls=draft.world.walls + (moved,)))


def set_floor(draft: Draft, op: dict, locate) -> Draft:
    draft = draft.with_own_world()
    world = dataclasses.replace(draft.world, floor_width=_number(op, "width"), floor_height=_number(op, "height"))
    return dataclasses.replace(draft, world=world)


def set_properties(draft: Draft, op: dict, locate) -> Draft:
    """What the inspector sets: a wall's ends, thickness, height and colour, a marker's place and
    colour; a field not given stays as it was."""
    draft = _owning(draft, op["kind"], op)
    given = {key: op[key] for key in ("x", "y", "x1", "y1", "x2", "y2", "thickness", "height") if key in op}
    if "color" in op:
        given["color"] = tuple(op["color"])
    if op["kind"] == "marker":
        index = _index(op, len(draft.markers), "marker")
        if {"x1", "y1", "x2", "y2", "thickness", "height"} & given.keys():
            raise EditError("set-properties: a marker has x, y and a colour only")
        markers = list(draft.markers)
        old = markers[index]
        color = given.pop("color", old.color[:3]) + old.color[3:]  # the marker keeps its alpha
        markers[index] = dataclasses.replace(old, **given, color=color)
        return dataclasses.replace(draft, markers=tuple(markers))
    index = _index(op, len(draft.world.walls), "wall")
    if {"x", "y"} & given.keys():
        raise EditError("set-properties: a wall has x1, y1, x2, y2, thickness, height and a colour")
    walls = list(draft.world.walls)
    walls[index] = dataclasses.replace(walls[index], **given)
    wall = walls[index]
    if (wall.x1, wall.y1) == (wall.x2, wall.y2):
        raise EditError("set-properties: the wall has no length (both ends at the same point)")
    return dataclasses.replace(draft, world=dataclasses.replace(draft.world, walls=tuple(walls)))


def set_program(draft: Draft, op: dict, locate) -> Draft:
    """The program a robot runs: a file under the roots, or none (`program: null`)."""
    index = _index(op, len(draft.robots), "robot")
    program = op.get("program")
    path = locate(program) if program is not None else None
    if program is not None and path is not None and not path.is_file():
        raise EditError(f"set-program: no program file {program.get('path')!r}")
    robots = list(draft.robots)
    robots[index] = dataclasses.replace(robots[index], program=str(path) if path else None)
    return dataclasses.replace(draft, robots=tuple(robots))


def _owning(draft: Draft, kind: str, op: dict) -> Draft:
    """Edits of walls and of the world's own balls and markers make the world the draft's own;
    item numbers then stay the same (the world's things come first)."""
    if kind == "wall" or (kind == "object" and draft.world.objects) or (kind == "marker" and draft.world.markers):
        return draft.with_own_world()
    return draft


def _definition(load, path: Path):
    from eyesim.scene import SceneError

    try:
        return load(path)
    except SceneError as error:
        raise EditError("; ".join(str(d) for d in error.errors) or str(error)) from None
    except OSError as error:
        raise EditError(f"cannot read {path.name}: {error.strerror}") from None


OPERATIONS = {
    "add-robot": add_robot,
    "add-object": add_object,
    "add-marker": add_marker,
    "add-wall": add_wall,
    "move": move,
    "delete": delete,
    "duplicate": duplicate,
    "set-floor": set_floor,
    "set-program": set_program,
    "set-properties": set_properties,
}


# -- making way ------------------------------------------------------------------------------
def placed_body(draft: Draft, op: dict) -> tuple[str, int] | None:
    """The robot or object an edit put down (kind, index as items() numbers it), or None."""
    name = op["op"]
    objects = len(draft.world.objects) + len(draft.objects)
    if name == "add-robot" or (name == "duplicate" and op["kind"] == "robot"):
        return "robot", len(draft.robots) - 1
    if name == "add-object" or (name == "duplicate" and op["kind"] == "object"):
        return "object", objects - 1
    if name == "move" and op["kind"] in ("robot", "object"):
        return op["kind"], op["index"]
    return None


def _placements(draft: Draft) -> tuple[list[RobotPlacement], list[ObjectPlacement]]:
    robots = [RobotPlacement(r.type_name, r.pose) for r in draft.robots]
    objects = list(draft.world.objects) + [ObjectPlacement(o.type_name, o.pose) for o in draft.objects]
    return robots, objects


def make_way(draft: Draft, scene: Scene, kind: str, index: int) -> tuple[Draft, str]:
    """The draft with the body just put down (kind, index) moved clear of the walls and the other
    bodies, which stay where they are (the loader alone would move whichever comes later in the
    file); and what was done, for the page ("" when it was clear). EditError when there is no free
    place near it."""
    robots, objects = _placements(draft)
    mine = (robots if kind == "robot" else objects).pop(index)
    pose, overlapped = clear_place(mine, robots + objects, scene.robot_types, scene.object_types, scene.world.walls)
    what = f"{kind.capitalize()} {index + 1} ({mine.type_name})"
    if pose is None:
        raise EditError(
            f"{what} at ({mine.pose.x:.0f}, {mine.pose.y:.0f}) overlaps {overlapped} and there is no "
            "free place near it: put it somewhere with more room"
        )
    if not overlapped:
        return draft, ""
    moved = move(draft, {"op": "move", "kind": kind, "index": index, "x": pose.x, "y": pose.y, "phi": pose.phi}, None)
    return moved, f"{what} overlapped {overlapped}: moved to ({pose.x:.0f}, {pose.y:.0f}), clear of it"


def settled(draft: Draft, scene: Scene) -> Draft:
    """The draft with its robots and objects where the loader put them (out of a wall drawn
    across them, say), so that the saved file loads as it is shown, without `overlap` warnings."""
    robots, objects = _placements(draft)
    kinds: tuple[tuple[str, Sequence[Placed], Sequence[Placed]], ...] = (
        ("robot", robots, scene.robots),
        ("object", objects, scene.objects),
    )
    for kind, placed, built in kinds:
        for index, (before, after) in enumerate(zip(placed, built)):
            if (before.pose.x, before.pose.y) != (after.pose.x, after.pose.y):
                draft = move(
                    draft,
                    {
                        "op": "move",
                        "kind": kind,
                        "index": index,
                        "x": after.pose.x,
                        "y": after.pose.y,
                        "phi": after.pose.phi,
                    },
                    None,
                )
    return draft


# -- saving -----------------------------------------------------------------------------------
def saved_files(draft: Draft, target: Path, as_json: bool) -> dict[Path, str]:
    """The files (path -> text) that save the draft at `target`: the scene, and its world when
    the draft has its own (`<name>.wld`, or `<name>.world.json` for JSON). References are written
    relative to the target's folder."""
    folder = target.parent
    files: dict[Path, str] = {}
    world_file = draft.world_file
    if world_file is None and (draft.world.walls or draft.world.floor_width or draft.world.floor_texture):
        stem = target.name[: -len(".json")] if target.name.lower().endswith(".json") else target.stem
        stem = Path(stem).stem
        world_file = folder / (f"{stem}.world.json" if as_json else f"{stem}.wld")
        world = dataclasses.replace(draft.world, floor_texture=_relative_or_none(draft.world.floor_texture, folder))
        files[world_file] = dumps(to_json("world", world)) if as_json else write_wld(world)
    document = dataclasses.replace(
        draft.document(),
        source=str(target),
        world=Reference(_relative(str(world_file), folder)) if world_file else None,
        robot_files=tuple(Reference(_relative(p, folder)) for p in draft.robot_files),
        object_files=tuple(Reference(_relative(p, folder)) for p in draft.object_files),
        placements=tuple(
            dataclasses.replace(
                p, program=_relative_or_none(p.program, folder), model=_relative_or_none(p.model, folder)
            )
            for p in draft.document().placements
        ),
    )
    files[target] = dumps(to_json("scene", document)) if as_json else write_sim(document)
    return files


def _relative_or_none(path: str | None, folder: Path) -> str | None:
    return None if path is None else _relative(path, folder)


def _relative(path: str, folder: Path) -> str:
    """A reference as written in a saved file: relative to its folder (with / on every system)
    when the file exists, else as it was."""
    if not Path(path).is_absolute():
        return path
    try:
        return Path(os.path.relpath(path, folder)).as_posix()
    except ValueError:  # another drive (Windows)
        return path
