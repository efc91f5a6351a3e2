"""Loading scene files into the Scene description: reading, parsing and resolving references.

Everything a scene names (world, robot and object definitions, textures, models, programs) is
found by eyesim.scene.paths. A missing file is a warning naming where it was referenced and
the fallback taken; only a file that leaves nothing usable is an error.
"""

from __future__ import annotations

import dataclasses
import difflib
from pathlib import Path

from eyesim.paths import PROGRAM_SOURCE_SUFFIXES
from eyesim.scene import builtins, limits, paths
from eyesim.scene.description import (
    Collider,
    Diagnostic,
    Location,
    ObjectPlacement,
    ObjectType,
    Pose,
    RobotPlacement,
    RobotType,
    Scene,
    World,
)
from eyesim.scene.diagnostics import Diagnostics, SceneError, quoted
from eyesim.scene.drives import drive_of
from eyesim.scene.placement import settle_placements
from eyesim.scene.esobj import parse_esobj
from eyesim.scene.json_format import parse_json
from eyesim.scene.lexer import TextFileError, decode
from eyesim.scene.maz import MazeDocument, maze_world, parse_maz
from eyesim.scene.robi import parse_robi
from eyesim.scene.sim import Placement, SimDocument, parse_sim
from eyesim.scene.wld import parse_wld

# What each file extension holds; .json files say it themselves.
KIND_OF_SUFFIX = {".sim": "scene", ".wld": "world", ".maz": "maze", ".robi": "robot", ".esobj": "object"}
PARSERS = {"scene": parse_sim, "world": parse_wld, "maze": parse_maz, "robot": parse_robi, "object": parse_esobj}
DEFAULT_OBJECT_COLLIDER = Collider("box", (100.0, 100.0, 100.0), (0.0, 0.0, 50.0))


def kind_of(path: Path) -> str | None:
    return KIND_OF_SUFFIX.get(path.suffix.lower()) or ("json" if path.suffix.lower() == ".json" else None)


def read_document(
    path: str | Path, diagnostics: Diagnostics, expected: tuple[str, ...] | None = None, where: dict | None = None
):
    """(kind, document) of one file as written, without opening the files it names: a
    SimDocument, World, MazeDocument, RobotType or ObjectType; document None on errors.
    `where` receives the locations of the references in it ('floor_texture', 'model')."""
    path = Path(path)
    source = str(path)
    kind = kind_of(path)
    if kind is None:
        diagnostics.error(
            Location(source),
            f"unknown file type {quoted(path.suffix or path.name)}: expected .sim, .wld, .maz, .robi, .esObj or .json",
            "file-type",
        )
        return None, None
    if expected is not None and kind != "json" and kind not in expected:
        diagnostics.error(
            Location(source),
            f"expected a {' or '.join(expected)} file, found a {kind} file ({path.suffix})",
            "file-type",
        )
        return None, None
    try:
        data = limits.read_limited(path)
        if limits.file_too_big(data, source, diagnostics):
            return None, None
        text = decode(data)
    except TextFileError as e:
        diagnostics.error(Location(source), str(e), "not-text")
        return None, None
    except OSError as e:
        diagnostics.error(Location(source), f"cannot read the file: {e.strerror or e}", "unreadable")
        return None, None
    if kind == "json":
        return parse_json(text, source, diagnostics, expected or ("scene", "world", "maze", "robot", "object"), where)
    if limits.lines_too_long(text, source, diagnostics):
        return None, None
    return kind, PARSERS[kind](text, source, diagnostics, where)


class _SceneLoader:
    """One load: its diagnostics and the types found so far (by case-folded name)."""

    def __init__(self, diagnostics: Diagnostics):
        self.diagnostics = diagnostics
        self.robot_types: dict[str, RobotType] = {}
        self.object_types: dict[str, ObjectType] = {}
        self.used_robots: dict[str, RobotType] = {}
        self.used_objects: dict[str, ObjectType] = {}
        self.loaded_files: dict[str, str] = {}  # definition file -> type name
        self.builtin_objects: dict[str, ObjectType | None] = {}
        self.refused_references: set[str] = set()  # file names past the limits (reported)
        self.scene_file: Path | None = None  # the scene being loaded: its folders are searched too
        self.edited_world: World | None = None  # a world edited in memory, in place of the scene's own

    # -- files ---------------------------------------------------------------------------------
    def world(self, path: Path) -> World | None:
        where: dict[str, Location] = {}
        kind, document = read_document(path, self.diagnostics, ("world", "maze"), where)
        if document is None:
            return None
        return self.finish_world(document, path, where)

    def finish_world(self, document, path: Path, where: dict[str, Location]) -> World:
        """A parsed world or maze with its texture resolved and its object types known."""
        world = maze_world(document, str(path), self.diagnostics) if isinstance(document, MazeDocument) else document
        # A .wld file stops at the line past a limit; a maze or JSON world is judged as a whole.
        where_world = Location(str(path))
        if (
            limits.too_many(len(world.walls), limits.MAX_WALLS, "walls", where_world, self.diagnostics, "a world")
            | limits.too_many(len(world.objects), limits.MAX_OBJECTS, "objects", where_world, self.diagnostics)
            | limits.too_many(len(world.markers), limits.MAX_MARKERS, "markers", where_world, self.diagnostics)
        ):
            return World(str(path))
        if world.floor_texture is not None:
            found = self.resolve(world.floor_texture, path, where.get("floor_texture", Location(str(path))))
            if found is None:
                self.missing(
                    where.get("floor_texture", Location(str(path))),
                    "floor texture",
                    world.floor_texture,
                    path,
                    "the floor is drawn in its plain colour",
                )
            world = dataclasses.replace(world, floor_texture=str(found) if found else None)
        for placement in world.objects:
            self.object_type(placement.type_name)
        return world

    def robot_file(self, path: Path) -> RobotType | None:
        where: dict[str, Location] = {}
        kind, robot = read_document(path, self.diagnostics, ("robot",), where)
        if robot is None:
            return None
        return self.with_model(robot, path, where)

    def object_file(self, path: Path) -> ObjectType | None:
        where: dict[str, Location] = {}
        kind, obj = read_document(path, self.diagnostics, ("object",), where)
        if obj is None:
            return None
        obj = self.with_model(obj, path, where)
        if not obj.colliders:
            self.diagnostics.warning(
                Location(str(path)), f"object {quoted(obj.name)} has no collider: it gets a 100 mm box", "no-collider"
            )
            obj = dataclasses.replace(obj, colliders=(DEFAULT_OBJECT_COLLIDER,))
        return obj

    def with_model(self, definition, path: Path, where: dict[str, Location]):
        if definition.model is None:
            return definition
        found = self.resolve(definition.model, path, where.get("model", Location(str(path))))
        if found is None:
            shape = "its collider shapes" if definition.colliders else "a plain box"
            self.missing(
                where.get("model", Location(str(path))), "3-D model", definition.model, path, f"drawn as {shape}"
            )
        return dataclasses.replace(definition, model=str(found) if found else None)

    def resolve(self, reference: str, referencing: Path, where: Location) -> Path | None:
        """The file a reference names (paths.resolve), or None; a name past the limits is an
        error here and not looked up (the file system would refuse it)."""
        problem = limits.path_too_long(reference)
        if problem is None:
            return paths.resolve(reference, referencing, self.scene_file)
        self.diagnostics.error(where, f"file name {quoted(reference)} {problem}", limits.LIMIT)
        self.refused_references.add(reference)
        return None

    def missing(self, where: Location, what: str, reference: str, referencing: Path, fallback: str) -> None:
        if reference in self.refused_references:
            return  # its error says enough
        hint = _near_file(reference, referencing)
        also = f"; did you mean {quoted(hint)}?" if hint else ""
        self.diagnostics.warning(
            where,
            f"{what} not found: {quoted(reference)} (looked as given, next to "
            f"{Path(referencing).name}, in the folders above and in the EyeSim home{also}); "
            f"{fallback}",
            "missing-file",
        )

    # -- types ---------------------------------------------------------------------------------
    def define_robot(self, reference: str, where: Location, scene_file: Path) -> RobotType:
        found = self.resolve(reference, scene_file, where)
        if found is not None and str(found) in self.loaded_files:
            return self.robot_types[self.loaded_files[str(found)].casefold()]
        robot = self.robot_file(found) if found is not None else None
        stem = Path(reference.replace("\\", "/")).stem
        if robot is None:
            stock = builtins.stock_robot(reference)
            stand_in = stock[1] if stock else builtins.FALLBACK_ROBOT
            shipped = self.builtin_robot(stand_in)
            assert shipped is not None, "the stock robots and the fallback robot ship with eyesim"
            robot = dataclasses.replace(shipped, name=stem)
            if found is None:
                self.missing(where, "robot file", reference, scene_file, self.stand_in_text(stock, robot, stem))
        else:
            self.loaded_files[str(found)] = robot.name
        key = robot.name.casefold()
        earlier = self.robot_types.get(key)
        if earlier is not None and earlier.source != robot.source:
            self.diagnostics.error(
                where,
                f"robot type {quoted(robot.name)} is defined twice: in {earlier.source} and in {robot.source}",
                "duplicate",
            )
        self.robot_types[key] = robot
        if builtins.robot_path(stem) is None:  # EyeSim VR 2018 named types after their files
            self.robot_types.setdefault(stem.casefold(), robot)
        return robot

    @staticmethod
    def stand_in_text(stock: tuple[str, str] | None, robot: RobotType, type_name: str) -> str:
        """What a missing robot file's warning says is used instead."""
        builtin = stock[1] if stock else builtins.FALLBACK_ROBOT
        what = drive_of(robot).noun
        if stock is None:
            return f"using the built-in {builtin} ({what}) as robot type {quoted(type_name)}"
        if stock[0].casefold() == builtin.casefold():
            return f"using the built-in {builtin} as robot type {quoted(type_name)}"
        return (
            f"{stock[0]} is one of EyeSim's own robots: using the built-in {builtin} ({what}, numbered as "
            f"{stock[0]}'s programs expect) as robot type {quoted(type_name)}"
        )

    def define_object(self, reference: str, where: Location, scene_file: Path) -> ObjectType:
        found = self.resolve(reference, scene_file, where)
        if found is not None and str(found) in self.loaded_files:
            return self.object_types[self.loaded_files[str(found)].casefold()]
        obj = self.object_file(found) if found is not None else None
        stem = Path(reference.replace("\\", "/")).stem
        if obj is None:
            if found is None:
                self.missing(
                    where, "object file", reference, scene_file, f"object type {quoted(stem)} becomes a 100 mm grey box"
                )
            obj = ObjectType(stem, reference, colliders=(DEFAULT_OBJECT_COLLIDER,))
        else:
            self.loaded_files[str(found)] = obj.name
        key = obj.name.casefold()
        earlier = self.object_types.get(key)
        if earlier is not None and earlier.source != obj.source:
            self.diagnostics.error(
                where,
                f"object type {quoted(obj.name)} is defined twice: in {earlier.source} and in {obj.source}",
                "duplicate",
            )
        self.object_types[key] = obj
        if builtins.object_path(stem) is None:
            self.object_types.setdefault(stem.casefold(), obj)
        return obj

    def builtin_robot(self, name: str) -> RobotType | None:
        path = builtins.robot_path(name)
        return load_robot_type(path) if path else None

    def builtin_object(self, name: str) -> ObjectType | None:
        key = name.casefold()
        if key not in self.builtin_objects:  # scenes place the same object many times
            path = builtins.object_path(name)
            self.builtin_objects[key] = load_object_type(path) if path else None
        return self.builtin_objects[key]

    def robot_type(self, name: str) -> RobotType | None:
        robot = self.robot_types.get(name.casefold()) or self.builtin_robot(name)
        if robot is not None:
            self.used_robots[robot.name] = robot
        return robot

    def object_type(self, name: str) -> ObjectType | None:
        obj = self.object_types.get(name.casefold()) or self.builtin_object(name)
        if obj is not None:
            self.used_objects[obj.name] = obj
        return obj

    def known_names(self) -> list[str]:
        names = {t.name for t in self.robot_types.values()} | {t.name for t in self.object_types.values()}
        return sorted(names | set(builtins.robot_names()) | set(builtins.object_names()))

    # -- the scene -----------------------------------------------------------------------------
    def scene(self, document: SimDocument, scene_file: Path) -> Scene:
        self.scene_file = scene_file
        world = self.scene_world(document, scene_file)
        for reference in document.robot_files:
            robot = self.define_robot(reference.path, reference.location or Location(str(scene_file)), scene_file)
            self.used_robots[robot.name] = robot
        for reference in document.object_files:
            obj = self.define_object(reference.path, reference.location or Location(str(scene_file)), scene_file)
            self.used_objects[obj.name] = obj
        robots, objects = [], list(world.objects)
        starts = _StartPicker(world, self.diagnostics)
        for placement in document.placements:
            where = placement.location or Location(str(scene_file))
            if placement.robi is not None:
                robot = self.define_robot(placement.robi, where, scene_file)
                self.used_robots[robot.name] = robot
                pose = starts.pose(placement, where)
                program = self.program(placement.program, where, scene_file)
                robots.append(RobotPlacement(robot.name, pose, program, where))
            elif placement.model is not None:
                obj = self.model_object(placement.model, where, scene_file)
                objects.append(ObjectPlacement(obj.name, starts.pose(placement, where), where, placement.friction))
            else:
                self.place_type(placement, where, scene_file, starts, robots, objects)
            if limits.too_many(len(robots), limits.MAX_ROBOTS, "robots", where, self.diagnostics) or limits.too_many(
                len(objects), limits.MAX_OBJECTS, "objects", where, self.diagnostics
            ):
                return self.refused(scene_file, world)
        markers = world.markers + document.markers
        if limits.too_many(len(markers), limits.MAX_MARKERS, "markers", Location(str(scene_file)), self.diagnostics):
            return self.refused(scene_file, world)
        robots, objects = settle_placements(
            robots, objects, self.used_robots, self.used_objects, world.walls, self.diagnostics, str(scene_file)
        )
        return Scene(
            str(scene_file),
            world,
            dict(self.used_robots),
            dict(self.used_objects),
            tuple(robots),
            tuple(objects),
            markers,
            document.settings,
            self.diagnostics.warnings,
        )

    @staticmethod
    def refused(scene_file: Path, world: World) -> Scene:
        """What a scene past a limit leaves: its world (the error is reported already)."""
        return Scene(str(scene_file), world)

    def scene_world(self, document: SimDocument, scene_file: Path) -> World:
        if self.edited_world is not None:
            return self.finish_world(self.edited_world, Path(self.edited_world.source), {})
        if document.world is None:
            if self.diagnostics.has_errors:
                return World(str(scene_file))  # a broken world line was reported already
            self.diagnostics.warning(
                Location(str(scene_file)), "the scene names no world or maze: it gets an empty floor", "no-world"
            )
            return World(str(scene_file))
        where = document.world.location or Location(str(scene_file))
        found = self.resolve(document.world.path, scene_file, where)
        if found is None:
            self.missing(where, "world file", document.world.path, scene_file, "using an empty world")
            return World(document.world.path)
        return self.world(found) or World(str(found))

    def place_type(self, placement: Placement, where: Location, scene_file: Path, starts, robots, objects) -> None:
        name = placement.type_name
        assert name is not None, "a placement is of a type_name, a robi or a model"
        robot = self.robot_type(name)
        if robot is not None:
            pose = starts.pose(placement, where)
            program = self.program(placement.program, where, scene_file)
            robots.append(RobotPlacement(robot.name, pose, program, where))
            return
        obj = self.object_type(name)
        if obj is None:
            hint = difflib.get_close_matches(name, self.known_names(), n=1, cutoff=0.5)
            also = f" (did you mean {quoted(hint[0])}?)" if hint else ""
            self.diagnostics.error(
                where,
                f"unknown robot or object type {quoted(name)}{also}: expected a built-in "
                f"type ({', '.join(builtins.robot_names() + builtins.object_names())}) or one "
                "defined earlier by a robi/robot or obj/object line",
                "unknown-type",
            )
            return
        if placement.start is not None or placement.program is not None:
            self.diagnostics.error(
                where,
                f"{quoted(name)} is an object: expected {name} <x> <y> <phi>, objects have no start letter or program",
                "syntax",
            )
            return
        objects.append(ObjectPlacement(obj.name, starts.pose(placement, where), where))

    def model_object(self, model: str, where: Location, scene_file: Path) -> ObjectType:
        """EyeSim 6 `object x y phi friction model`: the type named like the model file."""
        stem = Path(model.replace("\\", "/")).stem
        obj = self.object_type(stem)
        if obj is None:
            found = self.resolve(model, scene_file, where)
            if found is None:
                self.missing(where, "3-D model", model, scene_file, f"object {quoted(stem)} becomes a 100 mm grey box")
            obj = ObjectType(
                stem, model, model=str(found) if found else None, colliders=(DEFAULT_OBJECT_COLLIDER,), fixed=True
            )
            self.object_types[stem.casefold()] = obj
            self.used_objects[obj.name] = obj
        return obj

    def program(self, program: str | None, where: Location, scene_file: Path) -> str | None:
        if not program:
            return None
        found = self.resolve(program, scene_file, where)
        if found is None and not Path(program).suffix:  # `drive` for drive.c, compiled when it starts
            found = next(
                (
                    hit
                    for suffix in PROGRAM_SOURCE_SUFFIXES
                    if (hit := self.resolve(program + suffix, scene_file, where)) is not None
                ),
                None,
            )
        if found is None:
            self.missing(where, "program", program, scene_file, "the robot starts without it")
            return program
        return str(found)


def _near_file(reference: str, referencing: Path) -> str | None:
    """A file next to the referencing one whose name is close to the missing one's (a typo), written
    as the reference would name it."""
    name = reference.replace("\\", "/").rsplit("/", 1)[-1]
    folder = Path(referencing).parent / Path(reference.replace("\\", "/")).parent
    try:
        names = [p.name for p in folder.iterdir() if p.is_file()]
    except OSError:
        return None
    same_kind = [n for n in names if Path(n).suffix.lower() == Path(name).suffix.lower()] or names
    hint = difflib.get_close_matches(name, same_kind, n=1, cutoff=0.6)
    if not hint or hint[0] == name:
        return None
    prefix = reference.replace("\\", "/")[: -len(name)] if "/" in reference.replace("\\", "/") else ""
    return prefix + hint[0]


class _StartPicker:
    """Poses for robots placed by a maze start letter or by nothing at all (EyeSim 6 `robi`)."""

    def __init__(self, world: World, diagnostics: Diagnostics):
        self.world = world
        self.diagnostics = diagnostics
        self.used: dict[str, int] = {}

    def pose(self, placement: Placement, where: Location) -> Pose:
        if placement.pose is not None:
            return placement.pose
        if placement.start is None:
            return self.default(where)
        letter = placement.start
        matches = [s for s in self.world.start_positions if s.letter.casefold() == letter.casefold()]
        if not matches:
            fallback = self.world.start_positions[0] if self.world.start_positions else None
            instead = (
                f"using start {quoted(fallback.letter)} instead"
                if fallback
                else "placing the robot at the default start"
            )
            self.diagnostics.warning(where, f"the world has no start letter {quoted(letter)}; {instead}", "no-start")
            pose = fallback.pose if fallback else self.default(where, quiet=True)
        else:
            # each robot naming a letter takes the next unused start with it
            index = self.used.get(letter.casefold(), 0)
            pose = matches[index % len(matches)].pose
            self.used[letter.casefold()] = index + 1
        if placement.phi is not None:  # the number after the letter overrides its heading
            pose = Pose(pose.x, pose.y, placement.phi)
        return pose

    def default(self, where: Location, quiet: bool = False) -> Pose:
        if self.world.start_pose is not None:
            return self.world.start_pose
        if self.world.start_positions:
            return self.world.start_positions[0].pose
        width, height = self.world.floor_width, self.world.floor_height
        pose = Pose(width / 2, height / 2, 0.0) if width and height else Pose(500.0, 500.0, 0.0)
        if not quiet:
            self.diagnostics.warning(
                where,
                f"no position given and the world has no start position: placing the robot at ({pose.x:g}, {pose.y:g})",
                "no-start",
            )
        return pose


# -- public entry points ---------------------------------------------------------------------
def load_scene(path: str | Path) -> Scene:
    """The Scene of a .sim file, or of a bare world (.wld, .maz) with no robots; .json files of
    kind scene, world or maze too. Raises SceneError listing every problem."""
    paths.clear_cache()
    path = Path(path)
    diagnostics = Diagnostics()
    loader = _SceneLoader(diagnostics)
    where: dict[str, Location] = {}
    kind, document = read_document(path, diagnostics, ("scene", "world", "maze"), where)
    scene = None
    if isinstance(document, SimDocument):
        scene = loader.scene(document, path)
    elif document is not None:
        world = loader.finish_world(document, path, where)
        scene = Scene(str(path), world, {}, dict(loader.used_objects), (), world.objects, world.markers)
    diagnostics.raise_if_errors()
    assert scene is not None, "read_document reported why it read nothing"
    return dataclasses.replace(scene, warnings=diagnostics.warnings)


def build_scene(document: SimDocument, scene_file: str | Path, world: World | None = None) -> Scene:
    """The Scene of a scene document held in memory (the browser's scene editor), resolved
    against `scene_file` as if it were that file. `world`, when given, is used in place of the
    document's world reference (a world edited in memory, walls in world coordinates).
    Raises SceneError like load_scene."""
    paths.clear_cache()
    diagnostics = Diagnostics()
    loader = _SceneLoader(diagnostics)
    loader.edited_world = world
    scene = loader.scene(document, Path(scene_file))
    diagnostics.raise_if_errors()
    return dataclasses.replace(scene, warnings=diagnostics.warnings)


def load_world(path: str | Path) -> World:
    """The World of a .wld, .maz or world/maze .json file (texture resolved)."""
    paths.clear_cache()
    diagnostics = Diagnostics()
    world = _SceneLoader(diagnostics).world(Path(path))
    diagnostics.raise_if_errors()
    assert world is not None, "read_document reported why it read nothing"
    return world


_BUILTIN_CACHE: dict = {}


def load_robot_type(name_or_path: str | Path) -> RobotType:
    """A robot type by built-in name ('S4', 'LabBot', any letter case) or from a .robi/.json file."""
    return _load_definition(name_or_path, builtins.robot_path, "robot")


def load_object_type(name_or_path: str | Path) -> ObjectType:
    """An object type by built-in name ('Can', 'Soccer', 'Crate', 'Golf', ...) or from a file."""
    return _load_definition(name_or_path, builtins.object_path, "object")


def _load_definition(name_or_path, builtin_path, kind: str):
    path = Path(name_or_path)
    if not path.suffix and builtin_path(str(name_or_path)) is not None:
        path = builtin_path(str(name_or_path))
    elif not path.suffix:
        names = builtins.robot_names() if kind == "robot" else builtins.object_names()
        raise SceneError(
            [
                _diagnostic(
                    str(name_or_path),
                    f"unknown built-in {kind} type {quoted(str(name_or_path))}: "
                    f"expected one of {', '.join(names)} or a file path",
                    "unknown-type",
                )
            ]
        )
    builtin = path.parent.resolve() in (builtins.ROBOTS_DIR, builtins.OBJECTS_DIR)
    key = (str(path.resolve()), path.stat().st_mtime) if builtin else None
    if key in _BUILTIN_CACHE:
        return _BUILTIN_CACHE[key]
    if not builtin:
        paths.clear_cache()
    diagnostics = Diagnostics()
    result = read_definition(path, kind, diagnostics)
    diagnostics.raise_if_errors()
    if builtin:
        _BUILTIN_CACHE[key] = result  # built-ins are immutable data: load them once
    return result


def read_definition(path: str | Path, kind: str, diagnostics: Diagnostics):
    """A robot or object type from a file, its model resolved; problems go to `diagnostics`
    (the result is None when the file has errors)."""
    loader = _SceneLoader(diagnostics)
    result = loader.robot_file(Path(path)) if kind == "robot" else loader.object_file(Path(path))
    return None if diagnostics.has_errors else result


def _diagnostic(file: str, message: str, code: str) -> Diagnostic:
    return Diagnostic("error", Location(file), message, code)
