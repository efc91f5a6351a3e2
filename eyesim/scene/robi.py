"""The .robi robot format in its dialects (EyeSim 6, EyeSim VR 0.9, VR 1.x, ours) and its writer.

The dialects disagree on frames and on what some numbers mean; docs/file-formats.md, section
"Robot files", states the one rule we follow. In short: PSD positions are always in the robot
frame (x forward, y left, z up); the keywords EyeSim VR introduced for the body (mass centre,
colliders) are in VR model space (X right, Y up, Z forward) unless the file says
`dialect eyesim`; the VR wheel distance is half the track; VR 1.x files (id-first psd lines or
`fisheye`) give the camera as (right, forward, up).
"""

from __future__ import annotations

import dataclasses
import re
from pathlib import Path

from eyesim.robot.drives import DRIVES, drive_named, drive_of
from eyesim.scene.description import (ArmSpec, BuoyancySpec, CameraSpec, Collider, DragSpec, GripperSpec,
                                      JointSpec, LidarSpec, Location, PsdSpec, RobotType, SteeringSpec,
                                      ThrusterSpec, WheelSpec)
from eyesim.scene.diagnostics import Diagnostics, quoted
from eyesim.scene.keyword_reader import KeywordReader
from eyesim.scene.lexer import Line, Token, format_number, integer, number, quote_token, split_lines
from eyesim.scene.robot_type import finish_robot_type

DIALECTS = ("eyesim", "eyesim6", "vr", "vr1")
DRIVE_CHOICES = ", ".join(drive.keyword for drive in DRIVES[:-1]) + f" or {DRIVES[-1].keyword}"
PSD_IDS = {"PSD_FRONT": 1, "PSD_LEFT": 2, "PSD_RIGHT": 3, "PSD_BACK": 4}  # RoBIOS 7
VR_ONLY = ("mass", "collider", "axel", "lidar")
_SERVO = re.compile(r"SERVO(\d+)\(([^,()]+),([^,()]+)\)", re.IGNORECASE)
DEFAULT_HEIGHT = 80.0


def parse_robi(text: str, source: str, diagnostics: Diagnostics, where: dict | None = None) -> RobotType:
    """A RobotType from .robi text; the model path stays as written (resolved by the loader).
    `where`, when given, receives the location of the 'model' reference."""
    lines = [Line(line.number, _merge_parentheses(line.tokens))
             for line in split_lines(text, source, diagnostics)]
    reader = _RobotReader(source, diagnostics, detect_dialect(lines))
    for line in lines:
        reader.statement(line)
    if where is not None and "model" in reader.where:
        where["model"] = reader.where["model"]
    return reader.robot()


def _merge_parentheses(tokens: tuple[Token, ...]) -> tuple[Token, ...]:
    """'SERVO1(-90,' '+90)' -> 'SERVO1(-90,+90)': spaces inside parentheses do not split."""
    merged: list[Token] = []
    for token in tokens:
        if merged and not token.quoted and merged[-1].text.count("(") > merged[-1].text.count(")"):
            merged[-1] = Token(merged[-1].text + token.text, merged[-1].column)
        else:
            merged.append(token)
    return tuple(merged)


def detect_dialect(lines: list[Line]) -> str:
    """The file's dialect: as its `dialect` line says, else 'vr1' when it uses the id-first psd
    form or `fisheye`, 'vr' when it uses any keyword or form only EyeSim VR defines, else
    'eyesim6'."""
    found = set()
    for line in lines:
        word, args = line.keyword.lower(), line.args
        if word == "dialect" and args:
            if args[0].text.lower() in DIALECTS:
                return args[0].text.lower()
        elif word == "fisheye" or (word == "psd" and len(args) >= 2 and _is_integer(args[0])
                                   and not _is_integer(args[1])):
            found.add("vr1")
        elif word in VR_ONLY or (word == "model" and len(args) == 7) or (word == "axis" and len(args) == 2) \
                or (word == "wheel" and args and args[0].text.lower() in ("drive", "turn")):
            found.add("vr")
    return "vr1" if "vr1" in found else "vr" if "vr" in found else "eyesim6"


def _is_integer(token: Token) -> bool:
    return not token.quoted and integer(token.text) is not None


def _name(name: str) -> str:
    """A name token for writing: quoted when it would read as a number."""
    token = quote_token(name)
    return f'"{name}"' if token == name and number(name) is not None else token


def vr_to_robot(x: float, y: float, z: float) -> tuple[float, float, float]:
    """VR model space (X right, Y up, Z forward) to the robot frame (x forward, y left, z up)."""
    return (z + 0.0, -x + 0.0, y + 0.0)


VR_AXIS = {"x": "y", "y": "z", "z": "x"}


class _RobotReader(KeywordReader):
    def __init__(self, source: str, diagnostics: Diagnostics, dialect: str):
        super().__init__(source, diagnostics)
        self.dialect = dialect
        self.fields: dict = {}
        self.where: dict[str, Location] = {}
        self.psds: list[tuple[int | None, PsdSpec, Location]] = []
        self.colliders: list[Collider] = []
        self.thrusters: list[ThrusterSpec] = []
        self.joints: list[JointSpec] = []
        self.arm: tuple[float, float, float, float] | None = None
        self.gripper: GripperSpec | None = None
        self.camera: CameraSpec | None = None
        self.fisheye: float | None = None
        self.fov: float | None = None
        self.diameter: float | None = None
        self.errors_before = sum(d.kind == "error" for d in diagnostics.items)
        self.size: tuple[float, float, float] | None = None
        self.steering: dict = {}

    # -- helpers -------------------------------------------------------------------------------
    def positive(self, line: Line, value: float, index: int, name: str) -> bool:
        if value <= 0:
            self.error(line, f"{line.keyword}: expected {name} > 0, found {quoted(line.tokens[index].text)}",
                       index, "bad-value")
            return False
        return True

    def whole(self, line: Line, index: int, name: str, minimum: int | None = None) -> int | None:
        text = line.tokens[index].text
        value = integer(text)
        if value is None or (minimum is not None and value < minimum):
            need = f"a whole number >= {minimum}" if minimum is not None else "a whole number"
            self.error(line, f"{line.keyword}: expected {name} ({need}), found {quoted(text)}", index)
            return None
        return value

    def body_point(self, x: float, y: float, z: float) -> tuple[float, float, float]:
        """A mass centre or collider position in the robot frame."""
        return (x + 0.0, y + 0.0, z + 0.0) if self.dialect == "eyesim" else vr_to_robot(x, y, z)

    def remember(self, key: str, line: Line) -> None:
        self.where.setdefault(key, self.at(line))

    # -- statements ----------------------------------------------------------------------------
    def statement(self, line: Line) -> None:
        self.dispatch(line, line.keyword.lower())

    def kw_dialect(self, line: Line) -> None:
        if self.arity(line, (1,), "eyesim|eyesim6|vr|vr1") and line.args[0].text.lower() not in DIALECTS:
            self.error(line, f"dialect: expected one of {', '.join(DIALECTS)}, found {quoted(line.args[0].text)}", 1)

    def kw_name(self, line: Line) -> None:
        if not line.args:
            self.error(line, "name: expected a robot name, found nothing")
            return
        if len(line.args) == 1:
            self.fields["name"] = line.args[0].text
        else:  # EyeSim 6: the rest of the line
            self.fields["name"] = " ".join(t.text for t in line.args)

    def kw_drive(self, line: Line) -> None:
        if not line.args:
            self.error(line, f"drive: expected a drive type ({DRIVE_CHOICES}), found nothing")
            return
        drive = drive_named(line.args[0].text)
        if drive is None:
            self.error(line, f"drive: expected {DRIVE_CHOICES}, found {quoted(line.args[0].text)}", 1)
            return
        self.fields["drive"] = drive.name
        self.fields["drive_motors"] = tuple(t.text for t in line.args[1:])
        self.remember("drive", line)

    def _single(self, line: Line, field: str, name: str) -> None:
        if self.arity(line, (1,), f"<{name}>"):
            values = self.numbers(line, 1, (name,))
            if values and self.positive(line, values[0], 1, name):
                self.fields[field] = values[0]

    def kw_diameter(self, line: Line) -> None:
        if self.arity(line, (1,), "<mm>"):
            values = self.numbers(line, 1, ("diameter in mm",))
            if values and self.positive(line, values[0], 1, "diameter"):
                self.diameter = values[0]

    def kw_speed(self, line: Line) -> None:
        self._single(line, "max_speed", "speed in mm/s")

    def kw_turn(self, line: Line) -> None:
        self._single(line, "max_turn", "turn rate in deg/s")

    def kw_size(self, line: Line) -> None:
        if self.arity(line, (3,), "<length> <width> <height>"):
            values = self.numbers(line, 1, ("length in mm", "width in mm", "height in mm"))
            if values and all(self.positive(line, v, 1 + i, n) for i, (v, n) in
                              enumerate(zip(values, ("length", "width", "height")))):
                self.size = (values[0], values[1], values[2])

    def kw_color(self, line: Line) -> None:
        if self.arity(line, (3,), "<r> <g> <b>"):
            rgb = [self.whole(line, 1 + i, c + " (0..255)", 0) for i, c in enumerate(("red", "green", "blue"))]
            if None not in rgb:
                if any(c > 255 for c in rgb):
                    self.error(line, "color: expected components 0..255, found "
                               + " ".join(str(c) for c in rgb), 1, "bad-value")
                else:
                    self.fields["color"] = tuple(rgb)

    def kw_model(self, line: Line) -> None:
        if not self.arity(line, (1, 7), "<file> [<x> <y> <z> <rx> <ry> <rz>]"):
            return
        self.fields["model"] = line.args[0].text
        self.where["model"] = self.at(line, 1)
        if len(line.args) == 7:
            values = self.numbers(line, 2, ("x offset", "y offset", "z offset", "x rotation", "y rotation",
                                            "z rotation"))
            if values:
                self.fields["model_offset"] = tuple(v + 0.0 for v in values[:3])
                self.fields["model_rotation"] = tuple(v + 0.0 for v in values[3:])

    def kw_mass(self, line: Line) -> None:
        if not self.arity(line, (1, 4), "<kg> [<cx> <cy> <cz>]"):
            return
        values = self.numbers(line, 1, ("mass in kg", "centre x", "centre y", "centre z")[:len(line.args)])
        if values and self.positive(line, values[0], 1, "mass"):
            self.fields["mass"] = values[0]
            self.remember("mass", line)
            if len(values) == 4:
                self.fields["center_of_mass"] = self.body_point(*values[1:])

    def kw_collider(self, line: Line) -> None:
        shapes = {"box": ("<sx> <sy> <sz> <cx> <cy> <cz>", 6), "sphere": ("<r> <cx> <cy> <cz>", 4),
                  "capsule": ("<r> <h> <cx> <cy> <cz> [x|y|z]", 5), "cylinder": ("<r> <h> <cx> <cy> <cz> [x|y|z]", 5)}
        kind = line.args[0].text.lower() if line.args else ""
        if kind not in shapes:
            found = quoted(line.args[0].text) if line.args else "nothing"
            self.error(line, f"collider: expected box, sphere, capsule or cylinder, found {found}", 1)
            return
        form, count = shapes[kind]
        counts = (count + 1, count + 2) if kind in ("capsule", "cylinder") else (count + 1,)
        if not self.arity(line, counts, f"{kind} {form}"):
            return
        names = {"box": ("size x", "size y", "size z"), "sphere": ("radius",),
                 "capsule": ("radius", "height"), "cylinder": ("radius", "height")}[kind]
        values = self.numbers(line, 2, names + ("centre x", "centre y", "centre z"))
        if not values:
            return
        size, centre = values[:len(names)], values[len(names):]
        if not all(self.positive(line, v, 2 + i, n) for i, (v, n) in enumerate(zip(size, names))):
            return
        axis = "y" if self.dialect != "eyesim" else "z"
        if len(line.args) == count + 2:
            axis = line.args[-1].text.lower()
            if axis not in ("x", "y", "z"):
                self.error(line, f"collider: expected axis x, y or z, found {quoted(line.args[-1].text)}",
                           len(line.args))
                return
        if self.dialect != "eyesim":
            axis = VR_AXIS[axis]
            if kind == "box":
                size = [size[2], size[0], size[1]]
        self.colliders.append(Collider(kind, tuple(v + 0.0 for v in size), self.body_point(*centre),
                                       axis if kind in ("capsule", "cylinder") else "z"))

    def kw_axis(self, line: Line) -> None:
        if not self.arity(line, (1, 2), "[<vertical>] <forward>"):
            return
        names = ("forward offset",) if len(line.args) == 1 else ("vertical offset", "forward offset")
        values = self.numbers(line, 1, names)
        if values:
            self.fields["axis_offset"] = values[-1]
            if len(values) == 2 and values[0] > 0:
                self.fields["axle_height"] = values[0]

    def kw_axel(self, line: Line) -> None:
        if not self.arity(line, (3,), "drive|turn <vertical> <forward>"):
            return
        which = line.args[0].text.lower()
        if which not in ("drive", "turn"):
            self.error(line, f"axel: expected drive or turn, found {quoted(line.args[0].text)}", 1)
            return
        values = self.numbers(line, 2, ("vertical offset", "forward offset"))
        if not values:
            return
        height = values[0] if values[0] > 0 else None
        if which == "drive":
            self.fields["axis_offset"] = values[1]
            if height is not None:
                self.fields["axle_height"] = height
        else:
            self.steering["offset"] = values[1]
            self.steering["height"] = height

    def kw_wheel(self, line: Line) -> None:
        which = None
        if line.args and line.args[0].text.lower() in ("drive", "turn"):
            which = line.args[0].text.lower()
        first = 2 if which else 1
        if not self.arity(line, (first + 3,), ("drive|turn " if which else "") +
                          "<diameter> <max deg/s> <ticks/rev> <distance>"):
            return
        values = self.numbers(line, first, ("diameter in mm", "maximum speed in deg/s", "ticks per revolution",
                                            "wheel distance in mm"))
        if not values:
            return
        ticks = self.whole(line, first + 2, "ticks per revolution", 1)
        if ticks is None or not all(self.positive(line, values[i], first + i, n) for i, n in
                                    ((0, "diameter"), (1, "maximum speed"), (3, "wheel distance"))):
            return
        # EyeSim VR gives the distance of each wheel from the robot's middle, EyeSim 6 the track.
        track = values[3] * 2 if self.dialect in ("vr", "vr1") else values[3]
        spec = WheelSpec(values[0], values[1], ticks, track)
        if which == "turn":
            self.steering["wheels"] = spec
        else:
            self.fields["wheels"] = spec
            self.remember("wheels", line)

    def kw_psd(self, line: Line) -> None:
        args = line.args
        if len(args) not in (5, 6, 8):
            self.arity(line, (5, 6, 8), "<NAME> [<id>] <x> <y> <z> <angle>, or <id> <NAME> <x> <y> <z> <rx> <ry> <rz>")
            return
        if len(args) == 5:
            ident, name_index, first = None, 1, 2
        elif _is_integer(args[0]) and not _is_integer(args[1]):
            ident, name_index, first = integer(args[0].text), 2, 3
        else:
            ident = self.whole(line, 2, "PSD id")
            if ident is None:
                return
            name_index, first = 1, 3
        names = ("x", "y", "z") + (("angle",) if len(args) < 8 else ("pitch", "heading", "roll"))
        values = self.numbers(line, first, names)
        if not values:
            return
        heading, pitch = (values[3], 0.0) if len(args) < 8 else (values[4], values[3])
        spec = PsdSpec(ident if ident is not None and ident > 0 else 0, line.tokens[name_index].text,
                       values[0], values[1], values[2], heading + 0.0, pitch + 0.0)
        self.psds.append((ident, spec, self.at(line)))

    def kw_camera(self, line: Line) -> None:
        if not self.arity(line, (7,), "<x> <y> <z> <pan> <tilt> <a> <b>"):
            return
        position = self.numbers(line, 1, ("x", "y", "z"))
        pan = self._camera_axis(line, 4, "pan")
        tilt = self._camera_axis(line, 5, "tilt")
        limits = self.numbers(line, 6, ("maximum pan", "maximum tilt"))
        if not position or pan is None or tilt is None or not limits:
            return
        if self.dialect == "vr1":  # (right, forward, up) as the VR 1.x files' own comment says
            position = [position[1], -position[0], position[2]]
        pan_range, tilt_range = (-90.0, 90.0), (-90.0, 90.0)
        a, b = limits
        if self.dialect == "eyesim":
            for i, v in ((6, a), (7, b)):
                if not 0 <= v <= 180:
                    self.error(line, f"camera: expected a limit 0..180 degrees, found {quoted(line.tokens[i].text)}",
                               i, "bad-value")
                    return
            pan_range, tilt_range = (-a + 0.0, a + 0.0), (-b + 0.0, b + 0.0)
        elif self.dialect in ("vr", "vr1") and 0 < a <= 180 and 0 < b <= 180:
            pan_range, tilt_range = (-a + 0.0, a + 0.0), (-b + 0.0, b + 0.0)
        # else: EyeSim 6's maximum image size; programs choose the size with CAMInit
        self.camera = CameraSpec(
            position[0] + 0.0, position[1] + 0.0, position[2] + 0.0,
            pan=pan[0], tilt=tilt[0], pan_servo=pan[1], tilt_servo=tilt[1],
            pan_range=pan[2] or pan_range, tilt_range=tilt[2] or tilt_range)
        self.remember("camera", line)

    def _camera_axis(self, line: Line, index: int, what: str):
        """(default angle, servo, range) from a number or from SERVO<n>(<min>,<max>)."""
        text = line.tokens[index].text
        value = number(text)
        if value is not None:
            return (value, None, None)
        match = _SERVO.fullmatch(text)
        if match:
            low, high = number(match.group(2).strip()), number(match.group(3).strip())
            if low is not None and high is not None and low <= high:
                return (0.0, int(match.group(1)), (low, high))
        self.error(line, f"camera: expected the {what} angle (a number) or SERVO<n>(<min>,<max>), "
                         f"found {quoted(text)}", index)
        return None

    def kw_fisheye(self, line: Line) -> None:
        if self.arity(line, (1,), "<field of view in degrees>"):
            values = self.numbers(line, 1, ("field of view in degrees",))
            if values and self._angle_of_view(line, values[0]):
                self.fisheye = values[0]
                self.remember("fisheye", line)

    def kw_fov(self, line: Line) -> None:
        if self.arity(line, (1,), "<field of view in degrees>"):
            values = self.numbers(line, 1, ("field of view in degrees",))
            if values and self._angle_of_view(line, values[0]):
                self.fov = values[0]
                self.remember("fov", line)

    def _angle_of_view(self, line: Line, value: float) -> bool:
        if 0 < value <= 360:
            return True
        self.error(line, f"{line.keyword}: expected a field of view 0..360 degrees, "
                         f"found {quoted(line.tokens[1].text)}", 1, "bad-value")
        return False

    def kw_lidar(self, line: Line) -> None:
        if not self.arity(line, (2, 3), "<points> <tilt>"):
            return
        points = self.whole(line, 1, "number of points", 1)
        tilt = self.numbers(line, 2, ("tilt in degrees",))
        if points is None or not tilt:
            return
        if not -90 < tilt[0] < 90:
            self.error(line, f"lidar: expected a tilt between -90 and 90 degrees, found {quoted(line.tokens[2].text)}",
                       2, "bad-value")
            return
        if len(line.args) == 3:
            self.diagnostics.warning(self.at(line, 3), f"lidar: third argument {quoted(line.args[2].text)} "
                                     "(EyeSim VR 2018) has no known meaning; ignored", "ignored-argument")
        self.fields["lidar"] = LidarSpec(points, tilt[0])

    def kw_thruster(self, line: Line) -> None:
        if not self.arity(line, (9,), "<NAME> <motor> <x> <y> <z> <dx> <dy> <dz> <max thrust N>"):
            return
        motor = self.whole(line, 2, "motor number", 1)
        values = self.numbers(line, 3, ("x", "y", "z", "direction x", "direction y", "direction z",
                                        "maximum thrust in N"))
        if motor is None or not values or not self.positive(line, values[6], 9, "maximum thrust"):
            return
        self.thrusters.append(ThrusterSpec(line.args[0].text, motor, *(v + 0.0 for v in values)))
        self.remember(f"thruster:{len(self.thrusters) - 1}", line)

    def kw_buoyancy(self, line: Line) -> None:
        if not self.arity(line, (1, 4), "<volume in litres> [<x> <y> <z>]"):
            return
        values = self.numbers(line, 1, ("volume in litres", "centre x", "centre y", "centre z")[:len(line.args)])
        if values:
            if values[0] < 0:
                self.error(line, f"buoyancy: expected a volume >= 0, found {quoted(line.tokens[1].text)}", 1,
                           "bad-value")
                return
            self.fields["buoyancy"] = BuoyancySpec(*(v + 0.0 for v in values))

    def kw_drag(self, line: Line) -> None:
        if not self.arity(line, (3, 4), "<x> <y> <z> [<rotation>]"):
            return
        names = ("drag along x", "drag along y", "drag along z", "rotational drag")
        values = self.numbers(line, 1, names[:len(line.args)])
        if values:
            if any(v < 0 for v in values):
                self.error(line, "drag: expected coefficients >= 0", 1, "bad-value")
                return
            self.fields["drag"] = DragSpec(*(v + 0.0 for v in values))

    def kw_arm(self, line: Line) -> None:
        if self.arity(line, (3, 4), "<x> <y> <z> [<heading>]"):
            values = self.numbers(line, 1, ("x", "y", "z", "heading")[:len(line.args)])
            if values:
                self.arm = tuple(v + 0.0 for v in values) + ((0.0,) if len(values) == 3 else ())

    def kw_joint(self, line: Line) -> None:
        if not self.arity(line, (9,), "<NAME> <servo> revolute|prismatic <d> <theta> <a> <alpha> <min> <max>"):
            return
        servo = self.whole(line, 2, "servo number", 1)
        kind = line.args[2].text.lower()
        if kind not in ("revolute", "prismatic"):
            self.error(line, f"joint: expected revolute or prismatic, found {quoted(line.args[2].text)}", 3)
            return
        values = self.numbers(line, 4, ("d in mm", "theta in degrees", "a in mm", "alpha in degrees", "minimum",
                                        "maximum"))
        if servo is None or not values:
            return
        self.joints.append(JointSpec(line.args[0].text, servo, kind, *(v + 0.0 for v in values)))
        self.remember(f"joint:{len(self.joints) - 1}", line)

    def kw_gripper(self, line: Line) -> None:
        if not self.arity(line, (3,), "<servo> <opening mm> <force N>"):
            return
        servo = self.whole(line, 1, "servo number", 1)
        values = self.numbers(line, 2, ("opening in mm", "force in N"))
        if servo is None or not values:
            return
        if self.positive(line, values[0], 2, "opening") and self.positive(line, values[1], 3, "force"):
            self.gripper = GripperSpec(servo, values[0], values[1])
            self.remember("gripper", line)

    # -- result --------------------------------------------------------------------------------
    def robot(self) -> RobotType:
        fields = dict(self.fields)
        file_location = Location(self.source)
        if "name" not in fields:
            fields["name"] = Path(self.source).stem
            self.diagnostics.warning(Location(self.source, 1, 1), f"no 'name' line: the robot type is called "
                                     f"{quoted(fields['name'])} after its file", "no-name")
        fields["psds"] = self._numbered_psds()
        fields["colliders"] = tuple(self.colliders)
        fields["thrusters"] = tuple(self.thrusters)
        if self.camera is not None:
            camera = self.camera
            if self.fov is not None:
                camera = _replace(camera, fov=self.fov)
            if self.fisheye is not None:
                camera = _replace(camera, fov=self.fisheye, fisheye=True)
            fields["camera"] = camera
        elif self.fisheye is not None or self.fov is not None:
            key = "fisheye" if self.fisheye is not None else "fov"
            self.diagnostics.warning(self.where[key], f"{key} without a camera line; ignored", "ignored-line")
        if self.steering:
            fields["steering"] = SteeringSpec(self.steering.get("offset", 0.0), self.steering.get("height"),
                                              self.steering.get("wheels"))
        if self.joints or self.arm is not None or self.gripper is not None:
            x, y, z, heading = self.arm if self.arm is not None else (0.0, 0.0, None, 0.0)
            fields["arm"] = ArmSpec(x, y, z, heading, tuple(self.joints), self.gripper)
        fields["length"], fields["width"], fields["height"] = self._dimensions()
        if "arm" in fields and fields["arm"].z is None:
            fields["arm"] = _replace(fields["arm"], z=fields["height"])
        robot = RobotType(source=self.source, **fields)
        where = dict(self.where)
        for i, (_, _, location) in enumerate(self.psds):
            where[f"psd:{i}"] = location
        if sum(d.kind == "error" for d in self.diagnostics.items) > self.errors_before:
            return robot  # the file is rejected: completing it would only add noise
        return finish_robot_type(robot, self.diagnostics, where, file_location)

    def _numbered_psds(self) -> tuple[PsdSpec, ...]:
        """RoBIOS ids: as written when positive; EyeSim 6's negative hdt ids and missing ids
        become PSD_FRONT=1 .. PSD_BACK=4 by name, other sensors number on after the highest."""
        taken = {ident for ident, _, _ in self.psds if ident is not None and ident > 0}
        ids: list[int | None] = []
        for ident, spec, _ in self.psds:
            if ident is not None and ident > 0:
                ids.append(ident)
            elif PSD_IDS.get(spec.name.upper()) and PSD_IDS[spec.name.upper()] not in taken:
                ids.append(PSD_IDS[spec.name.upper()])
                taken.add(ids[-1])
            else:
                ids.append(None)
        next_id = max(taken, default=0) + 1
        result = []
        for value, (_, spec, _) in zip(ids, self.psds):
            if value is None:
                value, next_id = next_id, next_id + 1
            result.append(_replace(spec, id=value))
        return tuple(result)

    def _dimensions(self) -> tuple[float, float, float]:
        """Chassis size: `size`, else the colliders' extent, else `diameter`, else the default."""
        if self.size is not None:
            return self.size
        if self.colliders:
            low, high = [float("inf")] * 3, [float("-inf")] * 3
            for collider in self.colliders:
                half = _half_extent(collider)
                for i in range(3):
                    low[i] = min(low[i], collider.center[i] - half[i])
                    high[i] = max(high[i], collider.center[i] + half[i])
            return (round(high[0] - low[0], 6), round(high[1] - low[1], 6), round(max(high[2], 1.0), 6))
        default = RobotType("", "")
        if self.diameter is not None:
            return (self.diameter, self.diameter, DEFAULT_HEIGHT)
        return (default.length, default.width, default.height)


def _half_extent(collider: Collider) -> tuple[float, float, float]:
    if collider.kind == "box":
        return tuple(v / 2 for v in collider.size)
    r = collider.size[0]
    if collider.kind == "sphere":
        return (r, r, r)
    along = max(collider.size[1] / 2, r)  # a capsule's height includes its caps
    return tuple(along if axis == collider.axis else r for axis in "xyz")


def _replace(obj, **changes):
    return dataclasses.replace(obj, **changes)


# -- writing -----------------------------------------------------------------------------------
def write_robi(robot: RobotType) -> str:
    """RobotType as .robi text in our dialect (every position in the robot frame, full track)."""
    f = format_number
    out = ["# EyeSim robot definition (written by eyesim convert)", "dialect eyesim",
           " ".join(["drive", drive_of(robot).keyword, *robot.drive_motors]),
           f"name {quote_token(robot.name)}",
           f"size {f(robot.length)} {f(robot.width)} {f(robot.height)}",
           "color " + " ".join(str(c) for c in robot.color)]
    mass = f"mass {f(robot.mass)}"
    if robot.center_of_mass is not None:
        mass += " " + " ".join(f(v) for v in robot.center_of_mass)
    out += [mass, f"speed {f(robot.max_speed)}", f"turn {f(robot.max_turn)}"]
    if robot.axle_height is not None:
        out.append(f"axis {f(robot.axle_height)} {f(robot.axis_offset)}")
    else:
        out.append(f"axis {f(robot.axis_offset)}")
    if robot.model is not None:
        line = f"model {quote_token(robot.model)}"
        if robot.model_offset != (0, 0, 0) or robot.model_rotation != (0, 0, 0):
            line += " " + " ".join(f(v) for v in (*robot.model_offset, *robot.model_rotation))
        out.append(line)
    for c in robot.colliders:
        numbers = " ".join(f(v) for v in (*c.size, *c.center))
        axis = f" {c.axis}" if c.kind in ("capsule", "cylinder") else ""
        out.append(f"collider {c.kind} {numbers}{axis}")
    def wheel_line(keyword: str, w) -> str:
        return f"{keyword} {f(w.diameter)} {f(w.max_speed)} {w.ticks_per_rev} {f(w.track)}"

    if robot.wheels is not None:
        out.append(wheel_line(drive_of(robot).wheel_keyword, robot.wheels))
    if robot.steering is not None:
        s = robot.steering
        out.append(f"axel turn {f(s.height) if s.height is not None else 0} {f(s.offset)}")
        if s.wheels is not None:
            out.append(wheel_line("wheel turn", s.wheels))
    for p in robot.psds:
        if p.pitch:
            out.append(f"psd {p.id} {_name(p.name)} {f(p.x)} {f(p.y)} {f(p.z)} {f(p.pitch)} {f(p.heading)} 0")
        else:
            out.append(f"psd {_name(p.name)} {p.id} {f(p.x)} {f(p.y)} {f(p.z)} {f(p.heading)}")
    if robot.camera is not None:
        out += _camera_lines(robot.camera)
    if robot.lidar is not None:
        out.append(f"lidar {robot.lidar.points} {f(robot.lidar.tilt)}")
    for t in robot.thrusters:
        out.append(f"thruster {quote_token(t.name)} {t.motor} " +
                   " ".join(f(v) for v in (t.x, t.y, t.z, t.dx, t.dy, t.dz, t.max_thrust)))
    if robot.buoyancy is not None:
        b = robot.buoyancy
        out.append(f"buoyancy {f(b.volume)} {f(b.x)} {f(b.y)} {f(b.z)}")
    if robot.drag is not None:
        d = robot.drag
        out.append(f"drag {f(d.x)} {f(d.y)} {f(d.z)} {f(d.rotation)}")
    if robot.arm is not None:
        a = robot.arm
        out.append(f"arm {f(a.x)} {f(a.y)} {f(a.z)} {f(a.heading)}")
        for j in a.joints:
            out.append(f"joint {quote_token(j.name)} {j.servo} {j.kind} " +
                       " ".join(f(v) for v in (j.d, j.theta, j.a, j.alpha, j.min, j.max)))
        if a.gripper is not None:
            out.append(f"gripper {a.gripper.servo} {f(a.gripper.opening)} {f(a.gripper.force)}")
    return "\n".join(out) + "\n"


def _camera_lines(c: CameraSpec) -> list[str]:
    f = format_number

    def axis(angle, servo, limits):
        if servo is not None:
            return f"SERVO{servo}({f(limits[0])},{f(limits[1])})"
        return f(angle)

    def half(limits):
        return f(min(180.0, max(abs(limits[0]), abs(limits[1]))))

    lines = [f"camera {f(c.x)} {f(c.y)} {f(c.z)} {axis(c.pan, c.pan_servo, c.pan_range)} "
             f"{axis(c.tilt, c.tilt_servo, c.tilt_range)} {half(c.pan_range)} {half(c.tilt_range)}"]
    if c.fisheye:
        lines.append(f"fisheye {f(c.fov)}")
    elif c.fov != CameraSpec(0, 0, 0).fov:
        lines.append(f"fov {f(c.fov)}")
    return lines
