"""The world seen from above, drawn with Pillow: floor, walls, markers, objects, robots, their paths
and sensor rays at a time of a recording. `eyesim render` makes its video frames with it.

A plain 2D drawing rather than MuJoCo's OpenGL renderer: it needs no GL context (headless
machines, CI), it shows what a student looks for when grading a run (where the robot went, what
its sensors saw) without perspective hiding anything, and it costs a few milliseconds a frame."""

from __future__ import annotations

import io
import math

from PIL import Image, ImageDraw

FLOOR = (246, 242, 232)
BACKGROUND = (221, 227, 234)
PATH = (30, 99, 200)
RAY_COLORS = {"psd": (229, 57, 53), "lidar": (46, 158, 68)}
TEXT = (20, 24, 30)
MARGIN = 12  # pixels around the floor


def yaw(quat) -> float:
    w, x, y, z = quat
    return math.atan2(2 * (w * z + x * y), 1 - 2 * (y * y + z * z))


class TopView:
    """Draws frames of one scene (the viewer's `scene` message) `size` pixels on its longer side
    (rounded to even numbers, as video encoders want)."""

    def __init__(self, scene: dict, size: int = 720, floor_image: bytes | None = None):
        self.scene = scene
        width, height = scene["floor"]["width"], scene["floor"]["height"]
        self.scale = (size - 2 * MARGIN) / max(width, height)
        self.size = (
            2 * round((width * self.scale + 2 * MARGIN) / 2),
            2 * round((height * self.scale + 2 * MARGIN) / 2),
        )
        self.height_m = height
        self.background = self._background(floor_image)

    def pixel(self, x: float, y: float) -> tuple[float, float]:
        return MARGIN + x * self.scale, MARGIN + (self.height_m - y) * self.scale

    def _background(self, floor_image: bytes | None) -> Image.Image:
        image = Image.new("RGB", self.size, BACKGROUND)
        draw = ImageDraw.Draw(image)
        floor = self.scene["floor"]
        corners = [self.pixel(0, floor["height"]), self.pixel(floor["width"], 0)]
        if floor_image:
            texture = Image.open(io.BytesIO(floor_image)).convert("RGB")
            box = [round(v) for v in (*corners[0], *corners[1])]
            image.paste(texture.resize((box[2] - box[0], box[3] - box[1])), (box[0], box[1]))
        else:
            draw.rectangle(corners, fill=FLOOR)
        for wall in self.scene["walls"]:
            width = max(1, round(wall["thickness"] * self.scale))
            draw.line(
                [self.pixel(wall["x1"], wall["y1"]), self.pixel(wall["x2"], wall["y2"])],
                fill=tuple(wall["color"]),
                width=width,
            )
        for marker in self.scene["markers"]:
            x, y = self.pixel(marker["x"], marker["y"])
            r = max(2, 0.0125 * self.scale)
            draw.ellipse([x - r, y - r, x + r, y + r], fill=tuple(marker["color"][:3]))
        return image

    def draw(
        self, snapshot: dict | None, paths: dict[int, list[tuple[float, float]]] | None = None, label: str = ""
    ) -> Image.Image:
        """A frame: the snapshot's poses (and `rays`; the arena alone without a snapshot: a recording
        with no pose samples), each robot's path so far, `label` in a corner."""
        image = self.background.copy()
        draw = ImageDraw.Draw(image)
        for points in (paths or {}).values():
            if len(points) > 1:
                draw.line([self.pixel(x, y) for x, y in points], fill=PATH, width=2)
        if snapshot is not None:
            self._draw_poses(draw, snapshot)
        if label:
            draw.text((MARGIN + 4, MARGIN + 2), label, fill=TEXT)
        return image

    def _draw_poses(self, draw: ImageDraw.ImageDraw, snapshot: dict) -> None:
        for ray in snapshot.get("rays", []):
            origin = self.pixel(*ray["origin"][:2])
            ends = ray["ends"]
            for i in range(0, len(ends) - 2, 3):
                draw.line([origin, self.pixel(ends[i], ends[i + 1])], fill=RAY_COLORS.get(ray["kind"], TEXT), width=1)
        objects = {o["id"]: o for o in self.scene["objects"]}
        for pose in snapshot["objects"]:
            if pose["id"] in objects:
                self._object(draw, objects[pose["id"]], pose)
        robots = {r["id"]: r for r in self.scene["robots"]}
        for pose in snapshot["robots"]:
            if pose["id"] in robots:
                self._robot(draw, robots[pose["id"]], pose)

    def _footprint(self, x: float, y: float, heading: float, length: float, width: float) -> list:
        c, s = math.cos(heading), math.sin(heading)
        corners = [
            (length / 2, width / 2),
            (-length / 2, width / 2),
            (-length / 2, -width / 2),
            (length / 2, -width / 2),
        ]
        return [self.pixel(x + c * u - s * v, y + s * u + c * v) for u, v in corners]

    def _robot(self, draw: ImageDraw.ImageDraw, robot: dict, pose: dict) -> None:
        x, y = pose["pos"][:2]
        heading = yaw(pose["quat"])
        length, width = robot["size"][:2]
        draw.polygon(self._footprint(x, y, heading, length, width), fill=tuple(robot["color"]), outline=TEXT)
        tip = self.pixel(x + math.cos(heading) * length / 2, y + math.sin(heading) * length / 2)
        draw.line([self.pixel(x, y), tip], fill=(255, 255, 255), width=2)
        centre = self.pixel(x, y)
        draw.text((centre[0] + 4, centre[1] - length * self.scale / 2 - 12), str(robot["id"]), fill=TEXT)

    def _object(self, draw: ImageDraw.ImageDraw, thing: dict, pose: dict) -> None:
        x, y = pose["pos"][:2]
        heading = yaw(pose["quat"])
        color = tuple(thing["color"])
        for part in thing["parts"] or [
            {"shape": thing["shape"], "size": thing["size"], "pos": [0, 0, 0], "quat": [1, 0, 0, 0]}
        ]:
            c, s = math.cos(heading), math.sin(heading)
            px, py = part["pos"][:2]
            cx, cy = x + c * px - s * py, y + s * px + c * py
            if part["shape"] == "box":
                draw.polygon(
                    self._footprint(cx, cy, heading + yaw(part["quat"]), part["size"][0], part["size"][1]),
                    fill=color,
                    outline=TEXT,
                )
            else:
                r = part["size"][0] * self.scale
                u, v = self.pixel(cx, cy)
                draw.ellipse([u - r, v - r, u + r, v + r], fill=color, outline=TEXT)
