"""What a robot file says about the camera: `camera`, and `fov` or `fisheye` for its lens."""

from __future__ import annotations

import dataclasses
import re
from dataclasses import dataclass, field

from eyesim.parts.part import Part, PartReader, between, coordinate, flag, in_schema, numbers, record_of, ref, whole
from eyesim.scene.diagnostics import quoted
from eyesim.scene.lexer import Line, format_number, number

_SERVO = re.compile(r"SERVO(\d+)\(([^,()]+),([^,()]+)\)", re.IGNORECASE)


@dataclass(frozen=True)
class CameraSpec:
    """A camera at a robot-frame position (mm) with default pan/tilt (deg) and field of view.

    `pan_range`/`tilt_range` are the mechanical limits in degrees (min, max). When a servo
    drives pan or tilt (`pan_servo`/`tilt_servo`, RoBIOS servo numbers), SERVOSet 0..255 maps
    linearly onto that range. `fisheye` marks a fisheye lens whose field of view is `fov`.
    """

    x: float = field(metadata=in_schema(coordinate("x", "mm forward")))
    y: float = field(metadata=in_schema(coordinate("y", "mm left")))
    z: float = field(metadata=in_schema(coordinate("z", "mm up")))
    pan: float = field(default=0.0, metadata=in_schema(coordinate("Pan", "default pan, degrees")))
    tilt: float = field(default=0.0, metadata=in_schema(coordinate("Tilt", "default tilt, degrees")))
    fov: float = field(default=60.0, metadata=in_schema(between(0, 360, "Field of view", "field of view in degrees")))
    pan_servo: int | None = field(
        default=None, metadata=in_schema(whole(1, "Pan servo", "servo driving the pan (its range is pan_range)"))
    )
    tilt_servo: int | None = field(default=None, metadata=in_schema(whole(1, "Tilt servo", "servo driving the tilt")))
    pan_range: tuple[float, float] = field(
        default=(-90.0, 90.0), metadata=in_schema(numbers(2, "Pan range", "(min, max) in degrees"))
    )
    tilt_range: tuple[float, float] = field(
        default=(-90.0, 90.0), metadata=in_schema(numbers(2, "Tilt range", "(min, max) in degrees"))
    )
    fisheye: bool = field(default=False, metadata=in_schema(flag("Fisheye lens")))


@dataclass(frozen=True, kw_only=True)
class CameraFields:
    """What a robot type says about its camera."""

    camera: CameraSpec | None = field(default=None, metadata=in_schema(ref("camera")))


def read_camera(reader: PartReader, line: Line) -> None:
    if not reader.arity(line, (7,), "<x> <y> <z> <pan> <tilt> <a> <b>"):
        return
    position = reader.numbers(line, 1, ("x", "y", "z"))
    pan = _camera_axis(reader, line, 4, "pan")
    tilt = _camera_axis(reader, line, 5, "tilt")
    limits = reader.numbers(line, 6, ("maximum pan", "maximum tilt"))
    if not position or pan is None or tilt is None or not limits:
        return
    if reader.dialect == "vr1":  # (right, forward, up) as the VR 1.x files' own comment says
        position = [position[1], -position[0], position[2]]
    pan_range, tilt_range = (-90.0, 90.0), (-90.0, 90.0)
    a, b = limits
    if reader.dialect == "eyesim":
        for i, v in ((6, a), (7, b)):
            if not 0 <= v <= 180:
                reader.error(
                    line,
                    f"camera: expected a limit 0..180 degrees, found {quoted(line.tokens[i].text)}",
                    i,
                    "bad-value",
                )
                return
        pan_range, tilt_range = (-a + 0.0, a + 0.0), (-b + 0.0, b + 0.0)
    elif reader.dialect in ("vr", "vr1") and 0 < a <= 180 and 0 < b <= 180:
        pan_range, tilt_range = (-a + 0.0, a + 0.0), (-b + 0.0, b + 0.0)
    # else: EyeSim 6's maximum image size; programs choose the size with CAMInit
    reader.collected["camera"] = CameraSpec(
        position[0] + 0.0,
        position[1] + 0.0,
        position[2] + 0.0,
        pan=pan[0],
        tilt=tilt[0],
        pan_servo=pan[1],
        tilt_servo=tilt[1],
        pan_range=pan[2] or pan_range,
        tilt_range=tilt[2] or tilt_range,
    )
    reader.remember("camera", line)


def _camera_axis(reader: PartReader, line: Line, index: int, what: str):
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
    reader.error(
        line, f"camera: expected the {what} angle (a number) or SERVO<n>(<min>,<max>), found {quoted(text)}", index
    )
    return None


def _lens(key: str):
    """The reader of `fov` or `fisheye <field of view>`."""

    def read(reader: PartReader, line: Line) -> None:
        if reader.arity(line, (1,), "<field of view in degrees>"):
            values = reader.numbers(line, 1, ("field of view in degrees",))
            if values and _angle_of_view(reader, line, values[0]):
                reader.collected[key] = values[0]
                reader.remember(key, line)

    return read


def _angle_of_view(reader: PartReader, line: Line, value: float) -> bool:
    if 0 < value <= 360:
        return True
    reader.error(
        line,
        f"{line.keyword}: expected a field of view 0..360 degrees, found {quoted(line.tokens[1].text)}",
        1,
        "bad-value",
    )
    return False


def finish(reader: PartReader) -> None:
    camera, fov, fisheye = (reader.collected.get(key) for key in ("camera", "fov", "fisheye"))
    if camera is not None:
        if fov is not None:
            camera = dataclasses.replace(camera, fov=fov)
        if fisheye is not None:
            camera = dataclasses.replace(camera, fov=fisheye, fisheye=True)
        reader.fields["camera"] = camera
    elif fisheye is not None or fov is not None:
        key = "fisheye" if fisheye is not None else "fov"
        reader.diagnostics.warning(reader.where[key], f"{key} without a camera line; ignored", "ignored-line")


def servos(robot) -> list[tuple[int, str, str]]:
    users = []
    if robot.camera is not None:
        if robot.camera.pan_servo is not None:
            users.append((robot.camera.pan_servo, "camera pan", "camera"))
        if robot.camera.tilt_servo is not None:
            users.append((robot.camera.tilt_servo, "camera tilt", "camera"))
    return users


def write(robot) -> list[str]:
    c = robot.camera
    if c is None:
        return []
    f = format_number

    def axis(angle, servo, limits):
        if servo is not None:
            return f"SERVO{servo}({f(limits[0])},{f(limits[1])})"
        return f(angle)

    def half(limits):
        return f(min(180.0, max(abs(limits[0]), abs(limits[1]))))

    lines = [
        f"camera {f(c.x)} {f(c.y)} {f(c.z)} {axis(c.pan, c.pan_servo, c.pan_range)} "
        f"{axis(c.tilt, c.tilt_servo, c.tilt_range)} {half(c.pan_range)} {half(c.tilt_range)}"
    ]
    if c.fisheye:
        lines.append(f"fisheye {f(c.fov)}")
    elif c.fov != CameraSpec(0, 0, 0).fov:
        lines.append(f"fov {f(c.fov)}")
    return lines


PART = Part(
    "camera",
    components=("eyesim.parts.camera.component:create",),
    fields=CameraFields,
    keywords={"camera": read_camera, "fov": _lens("fov"), "fisheye": _lens("fisheye")},
    write=write,
    finish=finish,
    defs={"camera": record_of(CameraSpec, "Camera", "a camera (robot frame)")},
    json_locations=lambda robot, positions: {"camera": positions.value(["camera"])},
    servos=servos,
)
